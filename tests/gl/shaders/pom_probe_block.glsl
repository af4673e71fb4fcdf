// pom_probe.glsl's uniforms: tests/gl/terrain_detail_test.cpp fills them.
#include "../../../renderer/shaders/pass_block.glsl"
PASS_BLOCK(PomProbeBlock)
    ivec4 u_params;  // layer, max linear steps, refinement steps, probe width
    vec2 u_probe; vec2 u_probe_unused;  // depth (texture units), probe height (px)
PASS_BLOCK_END
