// grass.cull's uniforms: terrain/grass/grass.cpp fills them, grass_cull.glsl reads them.
#include "../../../renderer/shaders/pass_block.glsl"
PASS_BLOCK(GrassCullBlock)
    ivec4 u_box;          // box min cell x, z; cells per side; blades per cell
    ivec2 u_camera_cell; ivec2 u_box_mod;  // world cell holding the camera; box min cell modulo cells per side (0..cells-1)
    vec4 u_cell;          // camera position in its cell (cells, x z), cell size (m), candidates
    vec4 u_radius;        // radius_m, thin start (m), far_keep, lod distance (m)
    vec4 u_blade;         // length (m), length variation, width (m), max rest bend (rad)
    vec4 u_map;           // camera-relative x, z of texel (0, 0); texel size x, z (m)
    vec2 u_height_map; vec2 u_tex_offset;  // height = scale * sample + (offset - camera y); camera x, z relative to the terrain origin (texture space)
    ivec4 u_tiles;        // the height texture's tiles (terrain/shaders/tiles.glsl)
    vec4 u_tile_layer;
    vec4 u_bands;         // sand_top, grass_top, snow_start, band_blend
    vec4 u_material;      // band_jitter, rock_slope, jitter noise uv per m, unused
    vec4 u_planes[5];     // frustum side and near planes (camera-relative, inward)
    vec4 u_wind_a;        // dir x, z; gust origin x, z
    vec4 u_wind_b;        // inv gust scale, sway phase, strength, gust
    vec4 u_wind_c;        // sway; previous frame's gust origin x, z and sway phase (< 0: none)
    vec4 u_color;         // tip colour (linear), colour variation
    vec4 u_dry;           // dry colour (linear), dry fraction
    uvec4 u_capacity;     // near, far list capacity; far list start; count blades (0/1)
    ivec4 u_splat_layers[2];  // TERRAIN_SPLAT: layer per splat channel (-1: none)
PASS_BLOCK_END
