// The SSAO passes' uniforms: postfx/ssao.cpp fills them, ssao.glsl reads them.
#include "../../renderer/shaders/pass_block.glsl"
PASS_BLOCK(SsaoBlock)
    vec4 u_params;   // radius_m, intensity, bias, full-size pixels per texel (1 or 2)
    ivec4 u_counts;  // directions, steps, unused, unused
PASS_BLOCK_END

