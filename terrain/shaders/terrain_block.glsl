// The terrain programs' uniforms (terrain.glsl and terrain_tess.glsl, every variant, the shadow
// ones too): terrain/terrain.cpp fills them once per draw, the shaders read what their variant
// uses. Guarded: terrain_tess.glsl reaches it through terrain.glsl.
#ifndef TERRAIN_BLOCK_GLSL
#define TERRAIN_BLOCK_GLSL
#include "../../renderer/shaders/pass_block.glsl"
// The material layers the block holds: terrain/user_materials.h kMaxMaterialLayers (terrain.cpp
// checks that they agree), in every variant, so that one C++ struct fits them all.
#define TERRAIN_BLOCK_LAYERS 8
PASS_BLOCK(TerrainBlock)
    mat4 u_shadow_matrix;   // SHADOW_PASS: camera-relative world -> clip (a cascade, spot tile or cube face)
    ivec4 u_tiles;          // tiles in x, z; texels between tiles
    vec4 u_tile_layer;      // texels per layer x, z; heightmap size x, z
    vec2 u_map_min; vec2 u_texel_m;     // camera-relative x, z of texel (0, 0) (m); metres between samples in x, z
    vec2 u_height_map; vec2 u_map_max;  // height = offset + scale * sample: (scale, offset - camera y); camera-relative x, z of the last texel (m)
    ivec4 u_bias_cells;     // leaf cells in x, z; texels per cell; bias on (1) / off (0)
    int u_quads; int u_first_instance; float u_max_error_px; float u_wetness;
                            // quads per instance side (half a node); this draw's first entry in u_instances;
                            // the LOD's screen error bound (error view); rain ([weather]): 0 dry .. 1 soaked
    vec4 u_bands;           // sand_top, grass_top, snow_start, band_blend
    vec4 u_material;        // band_jitter, rock_slope, 1 / texture_scale_m, detail_distance_m
    vec2 u_tex_offset; vec2 u_far_fade;  // camera x, z modulo the texture period (m); m where textures start to give way to layer means, and are gone
    vec4 u_grass_far;       // grass blades' mean albedo (linear), strength (0: no grass)
    vec2 u_grass_fade; vec2 u_terrain_unused;  // distance (m) where the far grass colour starts, and is full
    vec4 u_pom;             // TERRAIN_POM: depth_m, distance where the relief is gone (m), shadow strength, unused
    ivec4 u_pom_steps;      // TERRAIN_POM: max linear steps, refinement steps, shadow steps, unused
    vec4 u_tess;            // TERRAIN_TESS: target edge length (px), pixels per unit of (length / distance) of the main camera,
                            // the tessellated range (m), largest factor
    vec4 u_tess_relief;     // TERRAIN_TESS: relief depth (m) below the drawn surface, 1 / texture period (m), camera x, z modulo the period (m)
    vec4 u_tess_fade;       // TERRAIN_TESS: distance (m) where the displacement starts to fade, and is gone; the layer whose relief displaces
    ivec4 u_splat_layers[2];  // TERRAIN_SPLAT: the layer each splat channel weighs (-1: none)
    vec4 u_layer_mean[TERRAIN_BLOCK_LAYERS];       // each layer's mean linear albedo, roughness (far tier)
    vec4 u_layer_scale[TERRAIN_BLOCK_LAYERS / 4];  // texture coordinates per m of each layer, four a row (terrain.glsl layerScale)
PASS_BLOCK_END
#endif
