// The motion blur passes' uniforms: postfx/motion_blur.cpp fills them, motion_blur_*.glsl read them.
#include "../../renderer/shaders/pass_block.glsl"
PASS_BLOCK(MotionBlurBlock)
    vec4 u_vel_pass;  // exposure / frame time, k: tile size (px), near plane (m), unused
    vec4 u_gather;    // taps, depth extent (relative), k (px), unused
    ivec4 u_tiles;    // mode (0: max per tile, 1: max of the 3x3 tiles around), k (px), unused, unused
PASS_BLOCK_END
