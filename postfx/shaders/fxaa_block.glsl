// postfx.fxaa's uniforms: postfx/fxaa.cpp fills them, fxaa.glsl reads them.
#include "../../renderer/shaders/pass_block.glsl"
PASS_BLOCK(FxaaBlock)
    float u_edge_threshold; float u_edge_threshold_min; float u_subpixel; float u_unused;
PASS_BLOCK_END
