// Sun shadows from the cascaded shadow maps (renderer/shadows/cascades.h, renderer/shadows/sun_shadows.h):
// cascade chosen by view depth with a cross-fade band, receiver moved along its normal and a
// constant depth bias against acne, filtered by a rotated Vogel (golden-angle) disk of
// hardware depth compares (PCF), or PCSS: a blocker search first, then a kernel as wide as the
// penumbra the sun's disk casts over the blocker-receiver distance.
#include "shadow_filter.glsl"

#define SHADOW_MAX_CASCADES 5  // kMaxSunCascades in renderer/shadows/cascades.h

layout(std140, binding = BINDING_SHADOW_UNIFORMS) uniform ShadowUniforms {
    mat4 u_cascade_matrix[SHADOW_MAX_CASCADES];  // camera-relative world -> clip x, y, depth
    vec4 u_cascade_range[SHADOW_MAX_CASCADES];   // x near, y far (view depth, m), z texel (m), w depth extent (m)
    vec4 u_cascade_info[SHADOW_MAX_CASCADES];    // x 1 = has casters (0: all lit), y PCF radius (texels)
    vec4 u_shadow_params;  // x cascade count, y blend band, z taps, w filter (0 hard, 1 pcf, 2 pcss)
    vec4 u_shadow_bias;    // x normal offset (texels), y depth bias (texels), z PCSS penumbra radius per metre, w max penumbra (texels)
};
layout(binding = BINDING_SHADOW_MAP) uniform sampler2DArrayShadow u_shadow_map;
layout(binding = BINDING_SHADOW_DEPTH) uniform sampler2DArray u_shadow_depth;

// Visibility (0 shadowed .. 1 lit) of camera-relative pos with normal n in cascade c.
float cascadeVisibility(int c, vec3 pos, vec3 n, float ndotl, float angle) {
    if (u_cascade_info[c].x < 0.5) return 1.0;  // nothing casts into this cascade
    float texel = u_cascade_range[c].z;
    float sin_l = sqrt(clamp(1.0 - ndotl * ndotl, 0.0, 1.0));
    vec3 p = pos + n * (u_shadow_bias.x * texel * sin_l);
    vec4 q = u_cascade_matrix[c] * vec4(p, 1.0);
    vec2 uv = q.xy * 0.5 + 0.5;
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) return 1.0;
    float z = q.z - u_shadow_bias.y * texel / u_cascade_range[c].w;
    vec2 size = vec2(textureSize(u_shadow_depth, 0).xy);
    int mode = int(u_shadow_params.w);
    if (mode == 0) return texture(u_shadow_map, vec4(uv, float(c), z));
    int taps = int(u_shadow_params.z);
    float radius = u_cascade_info[c].y;
#ifndef SHADOW_NO_PCSS  // programs for a hard or pcf filter leave the blocker search out
    if (mode == 2) {
        // Blocker search over the largest penumbra: mean depth of the samples nearer the sun.
        float search = u_shadow_bias.w;
        float blockers = 0.0, sum = 0.0;
        for (int i = 0; i < taps; ++i) {
            float d = textureLod(u_shadow_depth, vec3(uv + vogelTap(i, taps, angle) * search / size, float(c)), 0.0).r;
            if (d < z) {
                sum += d;
                blockers += 1.0;
            }
        }
        if (blockers == 0.0) return 1.0;
        float distance_m = (z - sum / blockers) * u_cascade_range[c].w;  // blocker to receiver along the light
        radius = clamp(distance_m * u_shadow_bias.z / texel, radius, u_shadow_bias.w);
    }
#endif
    float lit = 0.0;
    for (int i = 0; i < taps; ++i)
        lit += texture(u_shadow_map, vec4(uv + vogelTap(i, taps, angle) * radius / size, float(c), z));
    return lit / float(taps);
}

// The cascade a view depth falls in (-1: beyond the shadows' reach).
int shadowCascade(float view_depth) {
    int count = int(u_shadow_params.x);
    for (int c = 0; c < count; ++c)
        if (view_depth < u_cascade_range[c].y) return c;
    return -1;
}

// Sun visibility at pos (camera-relative), cross-fading into the next cascade over the last
// `blend band` of each cascade's depth range, and into "lit" at the end of the last one.
float sunShadow(vec3 pos, vec3 n, float ndotl, float view_depth, vec2 pixel) {
    int c = shadowCascade(view_depth);
    if (c < 0) return 1.0;
    float angle = shadowNoise(pixel, 2) * 6.28318531;
    float near = u_cascade_range[c].x, far = u_cascade_range[c].y;
    float band_start = far - u_shadow_params.y * (far - near);
    float v = cascadeVisibility(c, pos, n, ndotl, angle);
    if (view_depth > band_start) {
        float t = (view_depth - band_start) / max(far - band_start, 1e-6);
        float next = c + 1 < int(u_shadow_params.x) ? cascadeVisibility(c + 1, pos, n, ndotl, angle) : 1.0;
        v = mix(v, next, t);
    }
    return v;
}

vec3 cascadeColor(float view_depth) {
    const vec3 colors[SHADOW_MAX_CASCADES] = vec3[](vec3(1.0, 0.35, 0.3), vec3(0.35, 1.0, 0.35), vec3(0.35, 0.5, 1.0),
                                                    vec3(1.0, 0.9, 0.3), vec3(0.9, 0.4, 1.0));
    int c = shadowCascade(view_depth);
    return c < 0 ? vec3(1.0) : colors[c];
}
