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

#ifdef TERRAIN_STREAM
// The streamed terrain's page table (terrain/tile_stream.h): a header (levels, tile, map width,
// height; per level at 4 + 8 l: first entry, tiles x, z, level width, height), then per cache
// tile of every level its page in the pools (layers of u_height / u_normals) or -1.
layout(std430, binding = BINDING_TERRAIN_PAGES) readonly buffer TerrainPages { int u_pages[]; };
const int kStreamHeader = 4 + 8 * 32;

// Level-l sample coordinate of level-0 texel coordinate t: each level keeps every other sample
// and always the last one, so samples 0 .. size_l - 2 lie at i * 2^l and the last at size0 - 1.
float streamLevelCoord(float t, int l, int size0, int size_l) {
    float step = float(1 << l), last = float(size_l - 2);
    float s = t / step;
    if (s <= last) return s;
    float p = last * step;
    return last + (t - p) / max(float(size0 - 1) - p, 1e-6);
}

// (uv, page) of level-0 texel coordinates t in the finest resident level at or above `level`.
// A point on a tile border (within rounding) lies in the tiles on both sides: the first resident
// of them (in a fixed order) serves it, so nodes that share a vertex agree whatever is resident.
// Residency is hierarchical, so a missing tile's point is served by the next level up.
vec3 streamCoord(vec2 t, int level) {
    int levels = u_pages[0];
    float tile = float(u_pages[1]);
    ivec2 size0 = ivec2(u_pages[2], u_pages[3]);
    t = clamp(t, vec2(0.0), vec2(size0 - 1));
    const float eps = 0.05;  // level samples: beyond float rounding of texel coordinates up to 65k
    for (int l = level; l < levels; ++l) {
        int h = 4 + 8 * l;
        ivec2 count = ivec2(u_pages[h + 1], u_pages[h + 2]);
        ivec2 size_l = ivec2(u_pages[h + 3], u_pages[h + 4]);
        vec2 s = vec2(streamLevelCoord(t.x, l, size0.x, size_l.x), streamLevelCoord(t.y, l, size0.y, size_l.y));
        s = clamp(s, vec2(0.0), vec2(size_l - 1));
        ivec2 lo = clamp(ivec2(floor((s - eps) / tile)), ivec2(0), count - 1);
        ivec2 hi = clamp(ivec2(floor((s + eps) / tile)), ivec2(0), count - 1);
        for (int tz = lo.y; tz <= hi.y; ++tz)
            for (int tx = lo.x; tx <= hi.x; ++tx) {
                int page = u_pages[kStreamHeader + u_pages[h] + tz * count.x + tx];
                if (page >= 0) {
                    vec2 local = clamp(s - vec2(tx, tz) * tile, vec2(0.0), vec2(tile));
                    return vec3((local + 0.5) / (tile + 1.0), float(page));
                }
            }
    }
    return vec3(0.5 / (tile + 1.0), 0.5 / (tile + 1.0), 0.0);  // never: the top level is always resident
}
#endif
