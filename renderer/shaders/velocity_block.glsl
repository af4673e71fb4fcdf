// temporal.velocity's uniforms: renderer/velocity.cpp fills them, velocity.glsl reads them.
#include "pass_block.glsl"
PASS_BLOCK(VelocityBlock)
    mat4 u_reproject;  // this frame's unjittered clip -> the previous frame's clip
    vec4 u_jitter;     // xy this frame's jitter (NDC)
PASS_BLOCK_END
