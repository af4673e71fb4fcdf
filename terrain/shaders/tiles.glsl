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

// The full-resolution surface (heightmap samples) at continuous texel coordinates t: texels
// joined by triangles split along the (x+1, z)-(x, z+1) diagonal, as the terrain's grid mesh is
// (terrain.cpp), so it is the height the terrain draws at full resolution.
float tileSurfaceSample(sampler2DArray height, vec2 t, ivec4 tiles, vec4 layer) {
    t = clamp(t, vec2(0.0), layer.zw - 1.0);
    ivec2 i = min(ivec2(t), ivec2(layer.zw) - 2);
    vec2 f = t - vec2(i);
    float h00 = tileFetch(height, i, tiles, layer).r;
    float h10 = tileFetch(height, i + ivec2(1, 0), tiles, layer).r;
    float h01 = tileFetch(height, i + ivec2(0, 1), tiles, layer).r;
    float h11 = tileFetch(height, i + ivec2(1, 1), tiles, layer).r;
    return f.x + f.y <= 1.0 ? h00 + (h10 - h00) * f.x + (h01 - h00) * f.y
                            : h11 + (h01 - h11) * (1.0 - f.x) + (h10 - h11) * (1.0 - f.y);
}
