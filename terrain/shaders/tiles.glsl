// Heightmap-sized data stored as a texture array of tiles that share their border texels
// (terrain/terrain.h, TerrainTiles), so maps larger than the GL texture limit work.
// The includer declares the uniforms u_tiles and u_tile_layer at its own locations.

// Texture coordinates (uv, layer) of continuous texel coordinates t (texel centres at
// integers, 0..size-1). Bilinear filtering inside one layer is exact: every tile holds the
// texels on both sides of any point it is chosen for.
vec3 tileCoord(vec2 t, ivec4 tiles, vec4 layer) {
    t = clamp(t, vec2(0.0), layer.zw - 1.0);
    ivec2 tile = min(ivec2(t / float(tiles.z)), tiles.xy - 1);
    vec2 local = t - vec2(tile) * float(tiles.z);
    return vec3((local + 0.5) / layer.xy, float(tile.y * tiles.x + tile.x));
}

// The texel at integer coordinates t (clamped to the map) of layer 0..: exact, no filtering.
vec4 tileFetch(sampler2DArray tex, ivec2 t, ivec4 tiles, vec4 layer) {
    t = clamp(t, ivec2(0), ivec2(layer.zw) - 1);
    ivec2 tile = min(t / tiles.z, tiles.xy - 1);
    return texelFetch(tex, ivec3(t - tile * tiles.z, tile.y * tiles.x + tile.x), 0);
}
