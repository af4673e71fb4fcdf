// lights.shade's uniforms: renderer/lighting/local_lights.cpp fills them (once per chunk), light_shade.glsl reads them.
#include "../../shaders/pass_block.glsl"
PASS_BLOCK(LightShadeBlock)
    uvec2 u_light_chunk; uvec2 u_light_unused;  // this draw's chunk of every range: first entry, entry count
PASS_BLOCK_END
