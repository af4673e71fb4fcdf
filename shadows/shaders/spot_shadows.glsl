// Spot light shadows from the atlas (shadows/spot_shadows.h): light slot -> tile, the receiver
// moved along its normal and towards the light by texel footprints (a texel covers
// z * u_spot_range.z metres at distance z), then one hardware compare (hard), a rotated Vogel
// disk of compares (pcf), or PCSS after 000: a blocker search, then a kernel as wide as the
// penumbra w = (d_receiver - d_blocker) * w_light / d_blocker. Reversed-Z: a larger depth is
// nearer the light, and the compare passes (lit) where the receiver is at least as near.
#include "shadow_filter.glsl"

#define SPOT_SHADOW_MAX 64  // kMaxSpotShadows in shadows/spot_shadows.h

layout(std140, binding = BINDING_SPOT_SHADOW_UNIFORMS) uniform SpotShadowUniforms {
    mat4 u_spot_matrix[SPOT_SHADOW_MAX];  // camera-relative world -> clip (reversed-Z perspective)
    vec4 u_spot_rect[SPOT_SHADOW_MAX];    // atlas uv offset xy, uv scale zw
    vec4 u_spot_range[SPOT_SHADOW_MAX];   // near (m), far (m), texel footprint per metre of distance, unused
    vec4 u_spot_params;  // x filter (0 hard, 1 pcf, 2 pcss), y taps, z tile px, w max penumbra (texels)
    vec4 u_spot_bias;    // x normal offset (texels), y depth bias (texels), z PCF radius (texels), w light radius (m)
};
layout(binding = BINDING_SPOT_SHADOW_MAP) uniform sampler2DShadow u_spot_map;
layout(binding = BINDING_SPOT_SHADOW_DEPTH) uniform sampler2D u_spot_depth;

// Distance along the light's axis (m) of an atlas depth (spotLinearDepth in spot_shadows.h).
float spotLinearDepth(float depth, float near_m, float far_m) {
    return near_m * far_m / (near_m + depth * (far_m - near_m));
}

// Atlas coordinates of tile coordinates uv, kept half a texel inside the tile (no bleeding).
vec2 spotAtlasUv(int slot, vec2 uv) {
    float half_texel = 0.5 / u_spot_params.z;
    return u_spot_rect[slot].xy + clamp(uv, vec2(half_texel), vec2(1.0 - half_texel)) * u_spot_rect[slot].zw;
}

// Visibility (0 shadowed .. 1 lit) of camera-relative pos, normal n, unit direction l to the
// light, through the light's tile `slot`; angle rotates the kernel per pixel.
float spotShadow(int slot, vec3 pos, vec3 n, vec3 l, float ndotl, float angle) {
    float z = (u_spot_matrix[slot] * vec4(pos, 1.0)).w;  // distance along the axis
    if (z <= 0.0) return 1.0;
    float texel = z * u_spot_range[slot].z;
    float sin_l = sqrt(clamp(1.0 - ndotl * ndotl, 0.0, 1.0));
    vec3 p = pos + n * (u_spot_bias.x * texel * sin_l) + l * (u_spot_bias.y * texel);
    vec4 q = u_spot_matrix[slot] * vec4(p, 1.0);
    if (q.w <= 0.0) return 1.0;
    vec3 ndc = q.xyz / q.w;
    vec2 uv = ndc.xy * 0.5 + 0.5;
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) return 1.0;  // outside the cone
    float depth = ndc.z;
    int mode = int(u_spot_params.x);
    if (mode == 0) return texture(u_spot_map, vec3(spotAtlasUv(slot, uv), depth));
    int taps = int(u_spot_params.y);
    float tile = u_spot_params.z;
    float radius = u_spot_bias.z;
    if (mode == 2) {
        // Blocker search over the largest penumbra: mean distance of the samples nearer the light.
        float search = u_spot_params.w;
        float blockers = 0.0, sum = 0.0;
        for (int i = 0; i < taps; ++i) {
            float d = textureLod(u_spot_depth, spotAtlasUv(slot, uv + vogelTap(i, taps, angle) * search / tile), 0.0).r;
            if (d > depth) {
                sum += spotLinearDepth(d, u_spot_range[slot].x, u_spot_range[slot].y);
                blockers += 1.0;
            }
        }
        if (blockers == 0.0) return 1.0;
        float blocker = sum / blockers;
        float penumbra_m = max(q.w - blocker, 0.0) * u_spot_bias.w / max(blocker, 1e-4);  // half of 000's w
        radius = clamp(penumbra_m / max(texel, 1e-8), radius, u_spot_params.w);
    }
    float lit = 0.0;
    for (int i = 0; i < taps; ++i)
        lit += texture(u_spot_map, vec3(spotAtlasUv(slot, uv + vogelTap(i, taps, angle) * radius / tile), depth));
    return lit / float(taps);
}
