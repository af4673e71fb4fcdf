// Local lights on the GPU: the light buffers, the light grid the culling passes fill, the hashed
// light octree, and the per-light shading. Included by the deferred shading pass
// (light_shade.glsl), the culling pass (light_cull.glsl) and forward passes (transparent
// surfaces): any of them finds a position's candidate lights with lightRange() and shades them
// with shadeLocalLight(). Formulas and layouts: renderer/lights.h, renderer/lighting/local_lights.h.
// Needs common.glsl, gbuffer.glsl and brdf.glsl first. With HAS_SPOT_SHADOWS (fragment stages)
// shadowed spot lights read their tile of the spot shadow atlas; with HAS_POINT_SHADOWS shadowed
// point lights read their depth cube. (The filter taps are included
// outside the #ifdef: the shader library expands each file once, before the GLSL preprocessor,
// so a file first reached inside an #ifdef would be missing for a later includer.)
#include "../../shadows/shaders/shadow_filter.glsl"
#ifdef HAS_SPOT_SHADOWS
#include "../../shadows/shaders/spot_shadows.glsl"
#endif
#ifdef HAS_POINT_SHADOWS
#include "../../shadows/shaders/point_shadows.glsl"
#endif

struct LocalLight {
    vec4 position_radius;  // camera-relative position (m), radius (m)
    vec4 color_scale;      // colour * intensity, spot cone scale (0 for point lights)
    vec4 direction_offset; // unit spot axis, spot cone offset (1 for point lights)
    vec4 shadow;           // x: tile of the spot shadow atlas, y: point shadow cube (-1: unshadowed), zw unused
};
layout(std430, binding = BINDING_LIGHTS) readonly buffer Lights { LocalLight u_lights[]; };
// Per tile or cluster (tiled, clustered): (offset, count) into u_light_indices; count
// kOverflowCount means the list overflowed and every light must be shaded (conservative).
layout(std430, binding = BINDING_LIGHT_CELLS) buffer LightCells { uvec2 u_light_cells[]; };
layout(std430, binding = BINDING_LIGHT_INDICES) buffer LightIndices { uint u_light_indices[]; };
// Hashed: 16 words per level l (0..20) of table descriptors, then the tables (local_lights.cpp).
layout(std430, binding = BINDING_LIGHT_HASH) readonly buffer LightHashTables { uint u_hash[]; };

layout(std140, binding = BINDING_LIGHT_GRID) uniform LightGrid {
    uvec4 u_grid;         // light count, tile px, tiles x, tiles y
    uvec4 u_grid2;        // slices, max lights per cell, pool capacity (entries), hash levels
    vec4 u_slices;        // near_0 (m), 1 / ln(ratio), ln(ratio), tan(fov_y / 2)
    vec4 u_hash_origin;   // camera position minus the hash origin (m), leaf node size (m)
    vec4 u_grid3;         // aspect (width / height), unused
};

const uint kOverflowCount = 0xFFFFFFFFu;
const float kLightFalloffEps = 0.01;  // m^2, renderer/lights.h kFalloffEpsM2

// The lights that may reach one position: indices u_light_indices[first .. first + count), or
// when `all` is set every light (first .. first + count: first > 0 for a later chunk of them).
struct LightRange {
    uint first, count;
    bool all;
};

// The part of a range one draw shades: entries [chunk.x, chunk.x + chunk.y) of it. llvmpipe ends
// a shader invocation's loops after 65,535 iterations in all (gallivm's
// LP_MAX_TGSI_LOOP_ITERATIONS) and silently drops every light past them, so a pass whose ranges
// can be longer draws once per chunk of LocalLights::kLightChunk lights and adds the draws up
// (LocalLights::chunks(); issue 19, defect 6). Every range is cut the same way: "every light"
// (naive, overflowed cells) and lists (hashed lists have no length cap).
LightRange chunkOf(LightRange range, uvec2 chunk) {
    uint begin = min(chunk.x, range.count);
    return LightRange(range.first + begin, min(range.count - begin, chunk.y), range.all);
}

// Exponential depth slice of a view depth (m): floor(ln(depth / near_0) / ln ratio).
uint sliceOf(float view_depth) {
    float k = floor(log(max(view_depth, 1e-30) / u_slices.x) * u_slices.y);
    return uint(clamp(k, 0.0, float(u_grid2.x) - 1.0));
}

LightRange cellRange(uint cell) {
    uvec2 c = u_light_cells[cell];
    if (c.y == kOverflowCount) return LightRange(0u, u_grid.x, true);
    return LightRange(c.x, c.y, false);
}

#if defined(LIGHTS_TILED) || defined(LIGHTS_CLUSTERED)
LightRange lightRange(ivec2 pixel, float view_depth) {
    uvec2 tile = uvec2(pixel) / u_grid.y;
    uint cell = tile.x + u_grid.z * tile.y;
#ifdef LIGHTS_CLUSTERED
    cell += u_grid.z * u_grid.w * sliceOf(view_depth);
#endif
    return cellRange(cell);
}
#elif defined(LIGHTS_HASHED)
// Perfect spatial hash slot of key p in the table whose descriptor starts at word t
// (renderer/lighting/perfect_hash.h: values base, offsets base, mbar, r = rbar^3, Q).
uint hashSlot(uint t, uvec3 p) {
    uint m = u_hash[t + 2u], r = u_hash[t + 3u], q = u_hash[t + 4u];
    uvec3 c = p % m, d = p / m;
    uint h = (c.x * 73856093u) ^ (c.y * 19349663u) ^ (c.z * 83492791u);
    h ^= h >> 16;
    h *= 0x7FEB352Du;
    h ^= h >> 15;
    uint g = (h % r + (d.x + q * (d.y + q * d.z)) % r) % r;
    uint o = u_hash[u_hash[t + 1u] + g];
    uvec3 s = (p + uvec3(o & 1023u, (o >> 10) & 1023u, o >> 20)) % m;
    return s.x + m * (s.y + m * s.z);
}

// The linkless octree lookup of renderer/lighting/light_hash.h for a camera-relative position.
LightRange lightRange(ivec2 pixel, vec3 position) {
    uint levels = u_grid2.w;
    if (levels == 0u) return LightRange(0u, 0u, false);
    vec3 qf = floor((position + u_hash_origin.xyz) / u_hash_origin.w);
    if (any(lessThan(qf, vec3(0.0))) || any(greaterThanEqual(qf, vec3(float(1u << levels))))) return LightRange(0u, 0u, false);
    uvec3 q = uvec3(qf);
    for (uint l = 0u; l < levels; ++l) {
        uvec3 c = q >> (levels - l), k = q >> (levels - l - 1u);
        uint bit = (k.x & 1u) + 2u * (k.y & 1u) + 4u * (k.z & 1u);
        uint node = 16u * l;
        uint v = u_hash[u_hash[node] + hashSlot(node, c)];
        if (((v >> bit) & 1u) != 0u) {
            if (((v >> (8u + bit)) & 1u) == 0u) break;  // an empty leaf
            uint data = 16u * (l + 1u) + 8u;
            uint s = u_hash[data] + 2u * hashSlot(data, k);
            return LightRange(u_hash[s], u_hash[s + 1u], false);
        }
    }
    return LightRange(0u, 0u, false);
}
#endif

uint lightAt(LightRange range, uint i) {
    return range.all ? range.first + i : u_light_indices[range.first + i];
}

// Radiance one light reflects toward the eye (v) from a surface at a camera-relative position:
// colour * intensity * windowed inverse-square falloff * spot cone * BRDF * n.l.
// `reaches` says whether the light reaches the position at all (lights.exact).
vec3 shadeLocalLight(LocalLight light, Surface s, vec3 position, vec3 v, out bool reaches) {
    vec3 d = light.position_radius.xyz - position;
    float d2 = dot(d, d);
    float r = light.position_radius.w;
    vec3 l = d * inversesqrt(max(d2, 1e-20));
    float t = clamp(-dot(l, light.direction_offset.xyz) * light.color_scale.w + light.direction_offset.w, 0.0, 1.0);
    reaches = d2 < r * r && t > 0.0;
    if (!reaches) return vec3(0.0);
    float x = d2 / (r * r);
    float w = clamp(1.0 - x * x, 0.0, 1.0);
    float attenuation = w * w / (d2 + kLightFalloffEps) * (t * t * (3.0 - 2.0 * t));
    float ndotl = dot(s.normal, l);
    if (ndotl <= 0.0) return vec3(0.0);
#ifdef HAS_SPOT_SHADOWS
    int slot = int(light.shadow.x);
    if (slot >= 0) attenuation *= spotShadow(slot, position, s.normal, l, ndotl, shadowNoise(gl_FragCoord.xy, 3) * 6.28318531);
#endif
#ifdef HAS_POINT_SHADOWS
    int cube = int(light.shadow.y);
    if (cube >= 0) attenuation *= pointShadow(cube, position, s.normal, l, ndotl, shadowNoise(gl_FragCoord.xy, 3) * 6.28318531);
#endif
    return evalBrdf(s.albedo, s.roughness, s.f0, s.normal, l, v) * light.color_scale.rgb * (attenuation * ndotl);
}

// The lights of a range shaded at one surface point; `exact` counts those that reach it.
vec3 shadeRange(LightRange range, Surface s, vec3 position, vec3 v, out uint exact) {
    vec3 color = vec3(0.0);
    exact = 0u;
    for (uint i = 0u; i < range.count; ++i) {
        bool reaches;
        color += shadeLocalLight(u_lights[lightAt(range, i)], s, position, v, reaches);
        exact += reaches ? 1u : 0u;
    }
    return color;
}

#if defined(LIGHTS_NAIVE) || defined(LIGHTS_TILED) || defined(LIGHTS_CLUSTERED) || defined(LIGHTS_HASHED)
// The candidate lights of a surface point at a camera-relative position seen through a pixel,
// for the method the program was compiled for (view_depth: its distance along the view axis).
LightRange methodRange(ivec2 pixel, vec3 position, float view_depth) {
#if defined(LIGHTS_TILED) || defined(LIGHTS_CLUSTERED)
    return lightRange(pixel, view_depth);
#elif defined(LIGHTS_HASHED)
    return lightRange(pixel, position);
#else
    return LightRange(0u, u_grid.x, true);
#endif
}

// Forward shading (the sea, transparent surfaces; drawn after lights.cull with
// LocalLights::bindForForward): the candidate lights of a surface at a camera-relative position
// seen through a pixel, the part of them this draw's chunk covers (chunkOf: a forward pass draws
// its surfaces again, additively, for each further chunk).
LightRange forwardRange(vec3 position, ivec2 pixel, uvec2 chunk) {
    return chunkOf(methodRange(pixel, position, max(-(mat3(u_view) * position).z, 0.0)), chunk);
}

// The local light such a surface reflects toward the eye from this draw's chunk of its lights.
// `evaluated` and `exact` count lights shaded and reaching.
vec3 forwardLocalLights(Surface s, vec3 position, ivec2 pixel, uvec2 chunk, out uint evaluated, out uint exact) {
    LightRange range = forwardRange(position, pixel, chunk);
    evaluated = range.count;
    return shadeRange(range, s, position, safeNormalize(-position), exact);
}
#endif
