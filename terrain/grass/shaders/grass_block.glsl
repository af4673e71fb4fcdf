// grass.gbuffer's, grass.velocity's and the grass shadow draws' uniforms: terrain/grass/grass.cpp
// fills them (once per indirect draw), grass.glsl reads them.
#include "../../../renderer/shaders/pass_block.glsl"
PASS_BLOCK(GrassBlock)
    mat4 u_prev_clip;      // GRASS_VELOCITY: previous clip from this camera's relative space
    mat4 u_shadow_matrix;  // SHADOW_PASS: camera-relative world -> the shadow view's clip (sun cascade, spot tile, cube face)
    vec4 u_look;           // root darkening, roughness, normal blend, wetness (0 dry .. 1)
    vec4 u_jitter;         // GRASS_VELOCITY: xy this frame's jitter (NDC)
    int u_segments; uint u_first; float u_grass_unused0; float u_grass_unused1;  // segments of this draw's blades; index of its first blade in u_blades
PASS_BLOCK_END
