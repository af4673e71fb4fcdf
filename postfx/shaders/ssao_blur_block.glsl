// postfx.ssao.blur's uniforms: postfx/ssao.cpp fills them, ssao_blur.glsl reads them.
#include "../../renderer/shaders/pass_block.glsl"
PASS_BLOCK(SsaoBlurBlock)
    vec4 u_blur;  // depth tolerance, radius (0 or 1), full pixels per AO texel, unused
PASS_BLOCK_END
