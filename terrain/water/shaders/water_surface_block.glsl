// water.surface's and water.velocity's uniforms: terrain/water/water.cpp fills them,
// water_surface.glsl reads them (the frame's sea settings travel in water_bindings.glsl's block).
#include "../../../renderer/shaders/pass_block.glsl"
PASS_BLOCK(WaterSurfaceBlock)
    mat4 u_prev_clip;                           // WATER_VELOCITY: previous clip from this camera's relative space
    vec4 u_jitter;                              // WATER_VELOCITY: xy this frame's jitter (NDC)
    uvec2 u_light_chunk; uvec2 u_water_unused;  // with lights: this draw's chunk of each light range: first entry, entry count
PASS_BLOCK_END
