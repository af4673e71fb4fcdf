// CDLOD terrain: a half-node grid mesh drawn once per selected quadrant (instanced), heights
// from the height texture, each vertex morphing toward the next coarser grid; per-pixel
// normals from the normal map, height/slope material splatting with detail normals, in three
// distance tiers. Writes the G-buffer (renderer/scene_targets.h); lighting.* light it. The
// debug views (LOD, morph, normals, screen error) write their colour as unlit emissive radiance.
#include "../../renderer/shaders/common.glsl"
#include "../../renderer/shaders/gbuffer.glsl"
#include "tiles.glsl"
#include "material.glsl"
#include "terrain_block.glsl"

struct Instance {
    vec4 a;  // camera-relative x, z of the quadrant's min corner (m), grid step in x (m), LOD level
    vec4 b;  // morph constants (end / (end - start), 1 / (end - start)), grid step in z (m), unused
};
layout(std430, binding = BINDING_TERRAIN_NODES) readonly buffer Instances { Instance u_instances[]; };
layout(binding = BINDING_TEX_0) uniform sampler2DArray u_height;   // heightmap samples (R32F tiles)
layout(binding = BINDING_TEX_1) uniform sampler2DArray u_normals;  // world normals (RGBA8 snorm tiles)

#ifdef TERRAIN_STREAM
// Streamed (terrain/tile_stream.h): the finest resident level's surface (bilinear) stands in for
// the full-resolution one; heights and normals come through the page table (tiles.glsl).
float surfaceSample(vec2 t) {
    return textureLod(u_height, streamCoord(t, 0), 0.0).r;
}
#else
// The full-resolution terrain surface at texel coordinates t (tiles.glsl).
float surfaceSample(vec2 t) {
    return tileSurfaceSample(u_height, t, u_tiles, u_tile_layer);
}
#endif

#ifdef VERTEX_SHADER
#ifdef TERRAIN_TESS
// The tessellation stages (terrain_tess.glsl) take this stage's outputs and give the fragment
// stage its v_* inputs.
#define v_rel tc_rel
#define v_texel tc_texel
#define v_sample tc_sample
#define v_grid tc_grid
#define v_lod tc_lod
#define v_morph tc_morph
#endif
// SHADOW_PASS (u_shadow_matrix: a sun shadow cascade, renderer/shadows/cascades.h, a spot tile or a
// cube face): camera-relative world -> clip x, y and depth. The vertices morph for the main camera
// (distances from the camera-relative origin), so the caster is the very surface the view shows.
out vec3 v_rel;        // camera-relative position (m)
out vec2 v_texel;      // heightmap texel coordinates (the fragment stage derives it from v_rel but for TERRAIN_TESS)
out float v_sample;    // heightmap value (for material bands; likewise)
out vec2 v_grid;       // grid coordinates within the instance (wireframe view)
flat out vec2 v_lod;   // level, unused
out float v_morph;

vec2 texelAt(vec2 rel_xz) {
    return (rel_xz - u_map_min) / u_texel_m;
}

int g_level = 0;  // the instance's LOD level (streamed: the pyramid level its heights come from)
float heightSample(vec2 texel) {
#ifdef TERRAIN_STREAM
    return textureLod(u_height, streamCoord(texel, g_level), 0.0).r;
#else
    return textureLod(u_height, tileCoord(texel, u_tiles, u_tile_layer), 0.0).r;
#endif
}

layout(binding = BINDING_TEX_4) uniform sampler2D u_bias;  // distance bias (m) at leaf-cell corners

// The error metric's distance bias at texel coordinates t: bilinear between the corners of the
// leaf cell holding t (the last cell may be narrower), with exact fetches so it matches
// DistanceBias::at and neighbouring nodes agree on shared vertices.
float distanceBias(vec2 t) {
    if (u_bias_cells.w == 0) return 0.0;
    vec2 size = u_tile_layer.zw - 1.0;
    t = clamp(t, vec2(0.0), size);
    float n = float(u_bias_cells.z);
    ivec2 i = min(ivec2(t / n), u_bias_cells.xy - 1);
    vec2 t0 = vec2(i) * n;
    vec2 f = clamp((t - t0) / (min(t0 + n, size) - t0), 0.0, 1.0);
    float g00 = texelFetch(u_bias, i, 0).r, g10 = texelFetch(u_bias, i + ivec2(1, 0), 0).r;
    float g01 = texelFetch(u_bias, i + ivec2(0, 1), 0).r, g11 = texelFetch(u_bias, i + ivec2(1, 1), 0).r;
    float top = g00 + (g10 - g00) * f.x;
    return top + (g01 + (g11 - g01) * f.x - top) * f.y;
}

void main() {
    Instance inst = u_instances[u_first_instance + gl_InstanceID];
    g_level = int(inst.a.w);
    int side = u_quads + 1;
    vec2 grid = vec2(gl_VertexID % side, gl_VertexID / side);
    vec2 step_m = vec2(inst.a.z, inst.b.z);
    vec2 xz = inst.a.xy + grid * step_m;
    float h = u_height_map.y + u_height_map.x * heightSample(texelAt(xz));
    // Strugar's morph: distance to the unmorphed vertex, odd vertices slide onto the
    // coarser grid (toward their even neighbour) as morph goes 0 -> 1.
    float dist = length(vec3(xz.x, h, xz.y)) + distanceBias(texelAt(xz));
    float morph = 1.0 - clamp(inst.b.x - dist * inst.b.y, 0.0, 1.0);
    // A vertex at or past the map's far edge keeps its place on that axis (as cdlod.cpp).
    vec2 odd = fract(grid * 0.5) * 2.0 * vec2(lessThan(xz, u_map_max));
    grid -= odd * morph;
    // Nodes may reach past the map's edge: their vertices stop at it (as cdlod.cpp's replica).
    xz = clamp(inst.a.xy + grid * step_m, u_map_min, u_map_max);
    vec2 texel = texelAt(xz);
    float s = heightSample(texel);
    h = u_height_map.y + u_height_map.x * s;
    v_rel = vec3(xz.x, h, xz.y);
    v_texel = texel;
    v_sample = s;
    v_grid = grid;
    v_lod = vec2(inst.a.w, 0.0);
    v_morph = morph;
#if defined(TERRAIN_TESS)
    gl_Position = vec4(v_rel, 1.0);  // projected after displacement (terrain_tess.glsl)
#elif defined(SHADOW_PASS)
    gl_Position = u_shadow_matrix * vec4(v_rel, 1.0);
#else
    gl_Position = u_view_proj * vec4(v_rel, 1.0);
#endif
}
#endif

#if defined(FRAGMENT_SHADER) && defined(SHADOW_PASS)
void main() {}  // depth only
#endif

#if defined(FRAGMENT_SHADER) && !defined(SHADOW_PASS)
// Program variants (terrain.cpp terrainProgram()), so no pixel pays for what its draw does not
// show (llvmpipe runs both sides of a branch): TERRAIN_VIEW 1 LOD, 2 morph, 3 normals, 4 screen
// error (debug views, unlit); otherwise MATERIAL_TIER 0, 1 or 2 (below); TERRAIN_WIREFRAME
// darkens the grid's edges.
layout(binding = BINDING_TEX_2) uniform sampler2DArray u_albedo;  // sRGB albedo, A = roughness
layout(binding = BINDING_TEX_3) uniform sampler2DArray u_detail;  // tangent-space normals

// Texture coordinates per m of layer l (terrain_block.glsl packs them four a row).
float layerScale(int l) { return u_layer_scale[l >> 2][l & 3]; }
#ifdef TERRAIN_SPLAT
// Splat maps (terrain/user_materials.h): TERRAIN_SPLAT RGBA images of layer weights, one texel per
// height sample; u_splat_layers says which layer each channel weighs (-1: none).
layout(binding = BINDING_TEX_5) uniform sampler2DArray u_splat;
#endif

in vec3 v_rel;
#ifdef TERRAIN_TESS
in vec2 v_texel;
in float v_sample;
#else
// Both are affine in v_rel, so derived per pixel they equal the interpolated ones up to rounding;
// left out of the vertex outputs, every triangle has three attributes fewer to set up, which on
// llvmpipe (the triangle setup runs on the application's thread) cut terrain.gbuffer to about
// 0.7 of its time on the grazing 4096^2 view (docs/performance.md).
#define v_texel ((v_rel.xz - u_map_min) / u_texel_m)
#define v_sample ((v_rel.y - u_height_map.y) / u_height_map.x)
#endif
in vec2 v_grid;
flat in vec2 v_lod;

// Where the normal at texel coordinates t is: the full map's tiles, or (streamed) the page of the
// finest resident level at or above the instance's.
vec3 normalCoord(vec2 t) {
#ifdef TERRAIN_STREAM
    return streamCoord(t, int(v_lod.x + 0.5));
#else
    return tileCoord(t, u_tiles, u_tile_layer);
#endif
}
in float v_morph;
layout(location = 0) out vec4 o_color;   // emissive radiance (0 when lit); error view: alpha = px
layout(location = 1) out vec4 o_albedo;  // G-buffer albedo, roughness
layout(location = 2) out vec4 o_normal;  // G-buffer normal, F0, lit flag

vec3 lodColor(float level) {
    const vec3 colors[8] = vec3[](vec3(1, 0.2, 0.2), vec3(1, 0.6, 0.1), vec3(0.9, 0.9, 0.1), vec3(0.3, 0.9, 0.2),
                                  vec3(0.1, 0.8, 0.9), vec3(0.2, 0.4, 1), vec3(0.7, 0.3, 1), vec3(1, 0.4, 0.8));
    return colors[int(level) % 8];
}

// Darkens the grid mesh's edges (terrain wireframe): 0 away from an edge, up to 0.8 on it.
float wireframe() {
#ifdef TERRAIN_WIREFRAME
    vec2 g = abs(fract(v_grid - 0.5) - 0.5) / max(fwidth(v_grid), vec2(1e-6));
    return (1.0 - min(min(g.x, g.y), 1.0)) * 0.8;
#else
    return 0.0;
#endif
}

#ifdef TERRAIN_SPLAT
// The splat weights at heightmap texel t (material.glsl).
void splatWeights(vec2 t, out vec4 a, out vec4 b) {
    splatWeightsAt(u_splat, u_splat_layers, u_tile_layer.zw, t, a, b);
}
int splatLayer(int c) { return max(u_splat_layers[c / 4][c % 4], 0); }
#endif

#if TERRAIN_VIEW == 5
// The layer with the largest weight at the drawn point (ties: the first), from the splat maps or
// the height/slope rules as the shaded image blends them.
int materialId(vec3 n) {
#ifdef TERRAIN_SPLAT
    vec4 a, b;
    splatWeights(v_texel, a, b);
    int best = 0;
    float best_w = -1.0;
    for (int c = 0; c < 4 * TERRAIN_SPLAT; ++c) {
        float w = c < 4 ? a[c] : b[c - 4];
        if (w > best_w) best = c, best_w = w;
    }
    return splatLayer(best);
#else
    vec2 world_xz = v_rel.xz + u_tex_offset;
    float noise = texture(u_albedo, vec3(world_xz * (u_material.z * 0.031), float(ROCK))).g;
    float bands = materialBands(v_sample + bandJitter(noise, u_material.x), u_bands);
    const int order[4] = int[](SAND, GRASS, ROCK, SNOW);
    int lower = int(min(floor(bands), 3.0));
    float t = bands - float(lower);
    float rock = rockWeight(n.y, u_material.y);
    float dirt = dirtWeight(n.y, u_material.y, rock, bands);
    float rest = (1.0 - dirt) * (1.0 - rock);
    int ids[4] = int[](order[lower], order[min(lower + 1, 3)], DIRT, ROCK);
    float ws[4] = float[]((1.0 - t) * rest, t * rest, dirt * (1.0 - rock), rock);
    int best = 0;
    for (int i = 1; i < 4; ++i)
        if (ws[i] > ws[best]) best = i;
    return ids[best];
#endif
}
#endif

#ifdef TERRAIN_VIEW
void main() {
    vec3 n = safeNormalize(texture(u_normals, normalCoord(v_texel)).xyz);
    float wire = wireframe();  // here, in uniform control flow (it takes derivatives)
    // Debug views are unlit: their colour goes to the HDR target, the G-buffer says "unlit".
    o_albedo = vec4(0.0);
    o_normal = vec4(encodeNormal(n), 0.0, 0.0);
#if TERRAIN_VIEW == 4
    // Vertical screen error: the drawn point and the full-resolution surface below or
    // above it, both projected; alpha holds the error in pixels (vista bench terrain reads it).
    float truth = u_height_map.y + u_height_map.x * surfaceSample(v_texel);
    vec4 a = u_view_proj * vec4(v_rel, 1.0), b = u_view_proj * vec4(v_rel.x, truth, v_rel.z, 1.0);
    float px = length((a.xy / a.w - b.xy / b.w) * 0.5 * u_viewport.xy);
    float e = px / max(u_max_error_px, 1e-6);
    vec3 c = e <= 1.0 ? mix(vec3(0.1, 0.25, 0.8), vec3(1.0, 0.9, 0.1), e) : mix(vec3(1.0, 0.4, 0.0), vec3(1.0, 0.0, 0.6), min(e - 1.0, 1.0));
    o_color = vec4(c * (0.5 + 0.5 * max(dot(n, u_sun_dir.xyz), 0.0)), px);
#elif TERRAIN_VIEW == 5
    // Material layers (alpha = the layer index, for tests and tools reading the HDR target).
    const vec3 colors[8] = vec3[](vec3(0.9, 0.8, 0.4), vec3(0.1, 0.7, 0.1), vec3(0.45), vec3(1.0), vec3(0.45, 0.25, 0.1),
                                  vec3(1.0, 0.1, 0.8), vec3(0.1, 0.8, 1.0), vec3(1.0, 0.45, 0.0));  // sand grass rock snow dirt, added
    int id = materialId(n);
    o_color = vec4(colors[id % 8] * (0.35 + 0.65 * max(dot(n, u_sun_dir.xyz), 0.0)), float(id));
#else
#if TERRAIN_VIEW == 1
    vec3 c = lodColor(v_lod.x);
#elif TERRAIN_VIEW == 2
    vec3 c = vec3(v_morph, 1.0 - v_morph, 0.2);
#else
    vec3 c = n * 0.5 + 0.5;
#endif
    o_color = vec4(c * (0.35 + 0.65 * max(dot(n, u_sun_dir.xyz), 0.0)), 1.0);
#endif
    o_color.rgb *= 1.0 - wire;
}
#else
// Material tiers, one instanced draw each (terrain.cpp picks a tier per quadrant from its
// distance; every tier computes the same image where its neighbours meet it, so no seam):
//   0 near (closer than detail_distance_m): every layer with its detail normal, triplanar rock;
//     the detail normals fade out and the triplanar rock gives way to tier 1's planar rock
//     towards detail_distance_m;
//   1 mid: albedo only, rock planar along the normal's main axis; textures give way to each
//     layer's mean albedo between u_far_fade.x and .y (where mip-mapping has nearly got there);
//   2 far (beyond u_far_fade.y): the layer means, no material texture at all.
// Each tier also draws every farther tier's quadrants as that tier would (up to rounding), so
// [terrain] material_tiers = false (the near tier everywhere) shows any seam by comparison.
#ifndef MATERIAL_TIER
#define MATERIAL_TIER 0
#endif

// Albedo (linear) + roughness of one layer, and its detail normal in the near tier.
vec4 layerAlbedo(int layer, vec2 uv, float textured) {
#if MATERIAL_TIER == 2
    return u_layer_mean[layer];
#else  // the near tier too, so that it draws any quadrant as its tier would ([terrain] material_tiers off)
    return mix(u_layer_mean[layer], texture(u_albedo, vec3(uv, float(layer))), textured);
#endif
}
vec3 layerDetail(int layer, vec2 uv) {
    return texture(u_detail, vec3(uv, float(layer))).xyz * 2.0 - 1.0;
}

#ifdef TERRAIN_POM

// What the relief at a point depends on, set once per pixel before the march: the planar
// position's gradients (m), the two band layers, their blend t, dirt and rock weights (splat
// maps: the channel weights), the terrain normal.
vec2 g_uv_dx, g_uv_dy;
ivec2 g_layers;
vec3 g_weights;
vec4 g_splat_a, g_splat_b;
vec3 g_normal;

// Layer's relief at world position m (metres), its texture coordinates and gradients at its scale.
float layerRelief(int layer, vec2 m) {
    float k = layerScale(layer);
    return textureGrad(u_detail, vec3(m * k, float(layer)), g_uv_dx * k, g_uv_dy * k).a;  // the detail array's alpha (materials.h)
}

// p projected along the terrain normal's main axis (metres): rock's planar projection, and every
// splat layer's.
vec2 mainAxisMetres(vec3 p, vec3 n) {
    vec3 q = p + vec3(u_tex_offset.x, 0.0, u_tex_offset.y);
    vec3 an = abs(n);
    return an.x >= an.y && an.x >= an.z ? q.zy : an.y >= an.z ? q.xz : q.xy;
}

// The blended relief height at camera-relative point p, weighted as main() blends the albedo; rock
// in its main-axis projection (the triplanar blend's largest share).
float pomHeight(vec3 p) {
#ifdef TERRAIN_SPLAT
    vec2 m = mainAxisMetres(p, g_normal);
    float h = 0.0;
    for (int c = 0; c < 4 * TERRAIN_SPLAT; ++c) h += (c < 4 ? g_splat_a[c] : g_splat_b[c - 4]) * layerRelief(splatLayer(c), m);
    return h;
#else
    vec2 world = p.xz + u_tex_offset;
    float h = mix(layerRelief(g_layers.x, world), layerRelief(g_layers.y, world), g_weights.x);
    if (g_weights.y > 0.0) h = mix(h, layerRelief(DIRT, world), g_weights.y);
    // The planar gradients stand in for the main axis's: close enough for a mip choice.
    if (g_weights.z > 0.0) h = mix(h, layerRelief(ROCK, mainAxisMetres(p, g_normal)), g_weights.z);
    return h;
#endif
}
#endif

#ifdef TERRAIN_POM
#include "pom.glsl"
#endif

void main() {
    vec3 n = safeNormalize(texture(u_normals, normalCoord(v_texel)).xyz);
    float dist = length(v_rel);
    float wire = wireframe();  // here, in uniform control flow (it takes derivatives)
    vec2 world_xz = v_rel.xz + u_tex_offset;
    // Detail (near tier) and texture (mid tier) weights by distance.
    float detail_fade = 1.0 - smoothstep(u_material.w * 0.5, u_material.w, dist);
    float textured = 1.0 - smoothstep(u_far_fade.x, u_far_fade.y, dist);
#ifdef TERRAIN_SPLAT
    // Splat maps place the layers (user_materials.h): each layer projected along the normal's
    // main axis at its own scale, so cliffs do not stretch; rock, snow and grass shares for the
    // far grass colour and wetness below come from the weights too.
    vec4 splat_a, splat_b;
    splatWeights(v_texel, splat_a, splat_b);
    float rock = splatShare(splat_a, splat_b, u_splat_layers, ROCK);
    float snow = splatShare(splat_a, splat_b, u_splat_layers, SNOW);
    float grass = splatShare(splat_a, splat_b, u_splat_layers, GRASS);  // grass_cull.glsl places blades by it
#else
    // Height bands (001): L = sum of clamp((h - start_i) / blend, 0, 1); layer floor(L)
    // blends into the next by fract(L). The height is jittered to break the bands (the coarse
    // rock noise: every tier fetches it, so band edges match across tiers).
    float noise = texture(u_albedo, vec3(world_xz * (u_material.z * 0.031), float(ROCK))).g;
    float h = v_sample + bandJitter(noise, u_material.x);
    float bands = materialBands(h, u_bands);
    const int order[4] = int[](SAND, GRASS, ROCK, SNOW);
    int lower = int(min(floor(bands), 3.0));
    float t = bands - float(lower);
    int upper = order[min(lower + 1, 3)];
    // Slopes: dirt on moderate ones, rock on steep ones; rock is triplanar near the camera so
    // cliffs do not stretch. Snow holds on flatter ground only.
    float rock = rockWeight(n.y, u_material.y);
    float dirt = dirtWeight(n.y, u_material.y, rock, bands);
    float snow = clamp(bands - 2.0, 0.0, 1.0) * (1.0 - rock);
    float grass = grassWeight(bands, rock, dirt);
#endif
    vec3 rel = v_rel;  // the point whose material shows: the drawn one, or where the relief's view ray lands
#ifdef TERRAIN_POM
    // Parallax occlusion mapping over the blend of the layers' reliefs, with the same weights
    // (they change over metres, the relief over centimetres). Fetches take the drawn point's
    // gradients: the march's offsets jump at the relief's silhouettes and would pick coarse mips.
    float pom_fade = 1.0 - smoothstep(u_pom.y * 0.5, u_pom.y, dist);
    float pom_shadow = 1.0;
    g_uv_dx = dFdx(world_xz);  // here, in uniform control flow
    g_uv_dy = dFdy(world_xz);
    if (pom_fade > 0.0) {
#ifdef TERRAIN_SPLAT
        g_splat_a = splat_a;
        g_splat_b = splat_b;
#else
        g_layers = ivec2(order[lower], upper);
        g_weights = vec3(t, dirt, rock);
#endif
        g_normal = n;
        vec3 to_eye = -v_rel / max(dist, 1e-6);
        float depth_m = u_pom.x * pom_fade;  // flattens with distance, so no pixel jumps where it ends
        vec3 span = pomSpan(to_eye, n, depth_m);
        float hit = pomMarch(v_rel, span, pomSteps(dot(to_eye, n), u_pom_steps.x), u_pom_steps.y);
        rel = v_rel - span * hit;
        if (u_pom.z > 0.0 && dot(u_sun_dir.xyz, n) > 0.0)
            pom_shadow = mix(1.0, pomShadow(rel, 1.0 - hit, pomSpan(u_sun_dir.xyz, n, depth_m), u_pom_steps.z), u_pom.z);
    }
    world_xz = rel.xz + u_tex_offset;
#endif
#ifdef TERRAIN_SPLAT
    vec4 albedo = vec4(0.0);
#if MATERIAL_TIER == 0
    vec3 detail = vec3(0.0);
#endif
    vec3 pw = rel + vec3(u_tex_offset.x, 0.0, u_tex_offset.y);
    vec3 an = abs(n);
    vec2 main_m = an.x >= an.y && an.x >= an.z ? pw.zy : an.y >= an.z ? pw.xz : pw.xy;
    // Every channel fetched, weight 0 or not: no branch (llvmpipe would run both sides anyway), and
    // the fetches stay in uniform control flow for their derivatives.
    for (int c = 0; c < 4 * TERRAIN_SPLAT; ++c) {
        float w = c < 4 ? splat_a[c] : splat_b[c - 4];
        int layer = splatLayer(c);
        vec2 uv = main_m * layerScale(layer);
        albedo += w * layerAlbedo(layer, uv, textured);
#if MATERIAL_TIER == 0
        detail += w * layerDetail(layer, uv);
#endif
    }
    float far_grass = grass * u_grass_far.w * smoothstep(u_grass_fade.x, u_grass_fade.y, dist);
#else
    vec2 uv_lower = world_xz * layerScale(order[lower]), uv_upper = world_xz * layerScale(upper);
    vec4 albedo = mix(layerAlbedo(order[lower], uv_lower, textured), layerAlbedo(upper, uv_upper, textured), t);
#if MATERIAL_TIER == 0
    vec3 detail = mix(layerDetail(order[lower], uv_lower), layerDetail(upper, uv_upper), t);
#endif
    // Beyond the grass blades' reach the grass layer takes their colour, so the meadow
    // keeps its tone where the blades fade out (u_grass_far.w = 0 without grass).
    float far_grass = grass * u_grass_far.w * smoothstep(u_grass_fade.x, u_grass_fade.y, dist);
    if (dirt > 0.0) {
        vec2 uv_dirt = world_xz * layerScale(DIRT);
        albedo = mix(albedo, layerAlbedo(DIRT, uv_dirt, textured), dirt);
#if MATERIAL_TIER == 0
        detail = mix(detail, layerDetail(DIRT, uv_dirt), dirt);
#endif
    }
    if (rock > 0.0) {
        vec3 p = (rel + vec3(u_tex_offset.x, 0.0, u_tex_offset.y)) * layerScale(ROCK);
        // Planar rock along the normal's main axis (tiers 0 and 1; tier 2: the mean).
        vec3 an = abs(n);
        vec2 main_uv = an.x >= an.y && an.x >= an.z ? p.zy : an.y >= an.z ? p.xz : p.xy;
        vec4 rock_albedo = layerAlbedo(ROCK, main_uv, textured);
#if MATERIAL_TIER == 0
        vec3 w = pow(an, vec3(4.0));
        w /= w.x + w.y + w.z;
        vec4 tri = texture(u_albedo, vec3(p.zy, ROCK)) * w.x + texture(u_albedo, vec3(p.xz, ROCK)) * w.y +
                   texture(u_albedo, vec3(p.xy, ROCK)) * w.z;
        rock_albedo = mix(rock_albedo, tri, detail_fade);
        detail = mix(detail, layerDetail(ROCK, p.zy) * w.x + layerDetail(ROCK, p.xz) * w.y + layerDetail(ROCK, p.xy) * w.z, rock);
#endif
        albedo = mix(albedo, rock_albedo, rock);
    }
#endif
#ifdef TERRAIN_POM
    // The relief's self-shadow darkens the albedo: the G-buffer has no sun-visibility channel
    // (docs/terrain-detail.md), and the pits it falls in would see less sky too.
    albedo.rgb *= pom_shadow;
#endif
    vec3 shading_n = n;
#if MATERIAL_TIER == 0
    // Detail normals through the in-shader tangent frame (001: texture coordinates follow
    // x/z), fading out with distance.
    vec3 tangent = safeNormalize(cross(n, vec3(0.0, 0.0, 1.0)));
    vec3 bitangent = safeNormalize(vec3(0.0, -n.z, n.y));
    vec3 nd = safeNormalize(tangent * detail.x + bitangent * detail.y + n * max(detail.z, 0.05));
    shading_n = safeNormalize(mix(n, nd, detail_fade));
#endif

    albedo.rgb = mix(albedo.rgb, u_grass_far.rgb, far_grass);
    if (u_wetness > 0.0) {
        // Wet ground: water in the pores darkens soil and sand (less on rock, little on
        // snow) and a water film makes every layer glossier.
        float porous = (1.0 - 0.5 * rock) * (1.0 - 0.8 * snow);
        albedo.rgb *= 1.0 - 0.55 * u_wetness * porous;
        albedo.a = mix(albedo.a, 0.15, 0.85 * u_wetness);
    }

    Surface surface;
    surface.albedo = albedo.rgb * (1.0 - wire);
    surface.roughness = clamp(albedo.a, 0.05, 1.0);
    surface.normal = shading_n;
    surface.f0 = 0.04;  // dielectric: soil, rock, snow
    surface.lit = true;
    encodeSurface(surface, o_albedo, o_normal);
    o_color = vec4(0.0, 0.0, 0.0, 1.0);  // terrain emits nothing
}
#endif
#endif
