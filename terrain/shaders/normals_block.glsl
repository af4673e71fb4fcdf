// terrain normals' uniforms (once at load): terrain/terrain.cpp fills them, normals.glsl reads them.
#include "../../renderer/shaders/pass_block.glsl"
PASS_BLOCK(NormalsBlock)
    vec2 u_texel_m; float u_scale_m; float u_normals_unused;  // metres between samples in x and z; metres per heightmap unit
    ivec4 u_tiles;      // tiles in x, z; texels between tiles
    vec4 u_tile_layer;  // texels per layer x, z; heightmap size x, z
PASS_BLOCK_END
