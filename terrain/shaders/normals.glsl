// Terrain normal map from the height tiles, once at load: central differences in metres
// (one-sided at the map's edges), so lighting does not change when the LOD does. One
// invocation per texel of each tile layer; neighbours may come from other tiles.
#ifdef COMPUTE_SHADER
#include "../../renderer/shaders/bindings.glsl"
layout(local_size_x = 16, local_size_y = 16) in;
layout(binding = BINDING_TEX_0) uniform sampler2DArray u_height;  // R32F heightmap tiles
layout(binding = BINDING_IMAGE_OUTPUT, rgba8_snorm) uniform writeonly image2DArray u_normals;
#include "normals_block.glsl"

// Height (m) of map texel p (integer), clamped to the map.
float h(ivec2 p) {
    ivec2 size = ivec2(u_tile_layer.zw);
    p = clamp(p, ivec2(0), size - 1);
    ivec2 tile = min(p / u_tiles.z, u_tiles.xy - 1);
    return texelFetch(u_height, ivec3(p - tile * u_tiles.z, tile.y * u_tiles.x + tile.x), 0).r * u_scale_m;
}

void main() {
    ivec3 id = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(id.xy, ivec2(u_tile_layer.xy)))) return;
    ivec2 tile = ivec2(id.z % u_tiles.x, id.z / u_tiles.x);
    ivec2 size = ivec2(u_tile_layer.zw);
    ivec2 p = min(tile * u_tiles.z + id.xy, size - 1);  // padding repeats the edge, like the heights
    ivec2 lo = max(p - 1, ivec2(0)), hi = min(p + 1, size - 1);
    float dhdx = (h(ivec2(hi.x, p.y)) - h(ivec2(lo.x, p.y))) / (float(hi.x - lo.x) * u_texel_m.x);
    float dhdz = (h(ivec2(p.x, hi.y)) - h(ivec2(p.x, lo.y))) / (float(hi.y - lo.y) * u_texel_m.y);
    imageStore(u_normals, id, vec4(normalize(vec3(-dhdx, 1.0, -dhdz)), 0.0));
}
#endif
