// postfx.scotopic's uniforms: postfx/scotopic.cpp fills them, scotopic.glsl reads them.
#include "../../renderer/shaders/pass_block.glsl"
PASS_BLOCK(ScotopicBlock)
    float u_cd_per_value; float u_blur_px; float u_blue_shift; float u_unused;  // cd/m^2 per image unit; blur radius (px) at w = 1
PASS_BLOCK_END
