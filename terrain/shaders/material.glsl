// Terrain material weights, shared by the terrain shader (terrain.glsl) and grass placement
// (terrain/grass/shaders/grass_cull.glsl) so grass grows exactly where the ground is drawn as grass.
// Mirrored on the CPU by terrain/material_weights.h (tests compare both).
// bands = (sand_top, grass_top, snow_start, band_blend), in heightmap units.

// 001's height bands: L = sum of clamp((h - start_i) / blend, 0, 1) over the three band
// starts; layer floor(L) (sand, grass, rock, snow) blends into the next by fract(L).
float materialBands(float h, vec4 bands) {
    return clamp((h - bands.x) / bands.w, 0.0, 1.0) + clamp((h - bands.y) / bands.w, 0.0, 1.0) +
           clamp((h - bands.z) / bands.w, 0.0, 1.0);
}

// Height jitter that breaks the band edges: noise in [0, 1] (the rock texture's green) around 0.45.
float bandJitter(float noise, float band_jitter) {
    return (noise - 0.45) * 2.0 * band_jitter;
}

// Rock on steep slopes: 1 where normal.y is 0.06 below rock_slope, 0 where 0.06 above.
float rockWeight(float normal_y, float rock_slope) {
    return 1.0 - smoothstep(rock_slope - 0.06, rock_slope + 0.06, normal_y);
}

// Dirt on moderate slopes of the sand and grass bands (up to 70%), not where rock already is.
float dirtWeight(float normal_y, float rock_slope, float rock, float bands) {
    float lower_two = min(floor(bands), 3.0) <= 1.5 ? 1.0 : 0.0;
    return 0.7 * (1.0 - smoothstep(rock_slope + 0.04, rock_slope + 0.12, normal_y)) * (1.0 - rock) * lower_two;
}

// Share of the grass layer in the final blend: its band weight, less rock and dirt.
float grassWeight(float bands, float rock, float dirt) {
    float band = min(bands, 1.0) - clamp(bands - 1.0, 0.0, 1.0);
    return band * (1.0 - rock) * (1.0 - dirt);
}
