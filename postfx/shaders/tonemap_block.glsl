// postfx.tonemap's uniforms: postfx/tonemap.cpp fills them, tonemap.glsl reads them.
#include "../../renderer/shaders/pass_block.glsl"
PASS_BLOCK(TonemapBlock)
    float u_exposure; float u_white; float u_unused0; float u_unused1;  // manual linear scale, 2^ev (1 without exposure); Reinhard: value mapped to 1
PASS_BLOCK_END
