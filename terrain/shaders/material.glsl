// Terrain material weights, shared by the terrain shader (terrain.glsl) and grass placement
// (terrain/grass/shaders/grass_cull.glsl) so grass grows exactly where the ground is drawn as grass:
// the height/slope rules (mirrored on the CPU by terrain/material_weights.h; tests compare both), or
// with TERRAIN_SPLAT a splat map's weights.
// bands = (sand_top, grass_top, snow_start, band_blend), in heightmap units.

// Bilinear filtering of an array texture's finest level, repeating (power-of-two sizes), through
// texelFetch: what textureLod(t, vec3(uv, layer), 0.0) returns, without the sampler's state. The
// stages without derivatives (tessellation evaluation, compute) fetch the material arrays this
// way: with anisotropic filtering on the arrays ([terrain] material_anisotropy > 1) llvmpipe runs
// its anisotropic footprint loop even for an explicit level, and without derivatives the
// footprint covers the texture: one tessellated frame at 48x27 took minutes of CPU at 16x, 2 s
// at 1x (docs/terrain-detail.md). The CPU mirrors (tess_displacement.h reliefAt) filter the same way.
vec4 texelBilinearRepeat(sampler2DArray t, vec2 uv, int layer) {
    ivec2 size = textureSize(t, 0).xy;
    vec2 p = uv * vec2(size) - 0.5;
    vec2 i = floor(p), f = p - i;
    ivec2 a = ivec2(i) & (size - 1), b = (a + 1) & (size - 1);
    vec4 top = mix(texelFetch(t, ivec3(a.x, a.y, layer), 0), texelFetch(t, ivec3(b.x, a.y, layer), 0), f.x);
    vec4 bottom = mix(texelFetch(t, ivec3(a.x, b.y, layer), 0), texelFetch(t, ivec3(b.x, b.y, layer), 0), f.x);
    return mix(top, bottom, f.y);
}

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

// The generated layers' indices in the material arrays (terrain/materials.h MaterialLayer).
const int SAND = 0, GRASS = 1, ROCK = 2, SNOW = 3, DIRT = 4;

#ifdef TERRAIN_SPLAT
// Splat maps (terrain/user_materials.h): TERRAIN_SPLAT RGBA images of layer weights, one texel per
// height sample of a map of size.x x size.y samples; layers[c / 4][c % 4] is the layer channel c
// weighs (-1: none). The weights at heightmap texel t, normalised over the channels that name a
// layer; where none weighs anything the first channel's layer takes it all. One level, no mips:
// the same in every stage.
void splatWeightsAt(sampler2DArray splat, ivec4 layers[2], vec2 size, vec2 t, out vec4 a, out vec4 b) {
    vec2 uv = (t + 0.5) / size;  // texel centres: sample i at (i + 0.5) / size
    a = textureLod(splat, vec3(uv, 0.0), 0.0) * vec4(greaterThanEqual(layers[0], ivec4(0)));
#if TERRAIN_SPLAT > 1
    b = textureLod(splat, vec3(uv, 1.0), 0.0) * vec4(greaterThanEqual(layers[1], ivec4(0)));
#else
    b = vec4(0.0);
#endif
    float sum = dot(a, vec4(1.0)) + dot(b, vec4(1.0));
    if (sum < 1e-4) {
        a = vec4(1.0, 0.0, 0.0, 0.0);
        sum = 1.0;
    }
    a /= sum;
    b /= sum;
}

// The share of layer in splat weights a, b (splatWeightsAt).
float splatShare(vec4 a, vec4 b, ivec4 layers[2], int layer) {
    return dot(a, vec4(equal(layers[0], ivec4(layer)))) + dot(b, vec4(equal(layers[1], ivec4(layer))));
}
#endif
