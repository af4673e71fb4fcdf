// Spot light shadows from the atlas (renderer/shadows/spot_shadows.h): light slot -> tile, the receiver
// moved along its normal and towards the light by texel footprints (a texel covers
// z * u_spot_range.z metres at distance z), then one hardware compare (hard), a rotated Vogel
// disk of compares each against the receiver plane's depth at its tap (pcf), or PCSS after 000: a blocker search, then a kernel as wide as the
// penumbra w = (d_receiver - d_blocker) * w_light / d_blocker. Reversed-Z: a larger depth is
// nearer the light, and the compare passes (lit) where the receiver is at least as near.
#include "shadow_filter.glsl"

#define SPOT_SHADOW_MAX 64  // kMaxSpotShadows in renderer/shadows/spot_shadows.h

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

// Tile uv and depth of a camera-relative point (w <= 0: behind the light).
vec4 spotProject(int slot, vec3 p) {
    vec4 q = u_spot_matrix[slot] * vec4(p, 1.0);
    return vec4(q.xy / q.w * 0.5 + 0.5, q.z / q.w, q.w);
}

// Receiver-plane depth bias (after Isidoro 2006), exact here: over a planar receiver 1/z is
// affine in the tile's uv under the perspective projection, and the depth is affine in 1/z, so
// the depth is affine in uv. Two points of the tangent plane give its gradient d depth / d uv;
// each kernel tap then compares the plane's own depth at its uv, so a wide kernel does not
// shadow the receiver it lies on. Zero where the plane is seen edge-on from the light.
vec2 spotDepthGradient(int slot, vec3 p, vec3 n, vec4 center, float step_m) {
    vec3 t1 = safeNormalize(cross(n, abs(n.y) < 0.9 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0)));
    vec3 t2 = cross(n, t1);
    vec4 a = spotProject(slot, p + t1 * step_m), b = spotProject(slot, p + t2 * step_m);
    if (a.w <= 0.0 || b.w <= 0.0) return vec2(0.0);
    vec2 du1 = a.xy - center.xy, du2 = b.xy - center.xy;
    float dd1 = a.z - center.z, dd2 = b.z - center.z;
    float det = du1.x * du2.y - du1.y * du2.x;
    if (abs(det) < 1e-14) return vec2(0.0);
    return vec2(dd1 * du2.y - dd2 * du1.y, du1.x * dd2 - du2.x * dd1) / det;
}

// Visibility (0 shadowed .. 1 lit) of camera-relative pos, normal n, unit direction l to the
// light, through the light's tile `slot`; angle rotates the kernel per pixel.
float spotShadow(int slot, vec3 pos, vec3 n, vec3 l, float ndotl, float angle) {
    float z = (u_spot_matrix[slot] * vec4(pos, 1.0)).w;  // distance along the axis
    if (z <= 0.0) return 1.0;
    float texel = z * u_spot_range[slot].z;
    float sin_l = sqrt(clamp(1.0 - ndotl * ndotl, 0.0, 1.0));
    vec3 p = pos + n * (u_spot_bias.x * texel * sin_l) + l * (u_spot_bias.y * texel);
    vec4 c = spotProject(slot, p);
    if (c.w <= 0.0) return 1.0;
    vec2 uv = c.xy;
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) return 1.0;  // outside the cone
    float depth = c.z;
    int mode = int(u_spot_params.x);
    if (mode == 0) return texture(u_spot_map, vec3(spotAtlasUv(slot, uv), depth));
    int taps = int(u_spot_params.y);
    float tile = u_spot_params.z;
    float radius = u_spot_bias.z;
    vec2 gradient = spotDepthGradient(slot, p, n, c, texel);
    if (mode == 2) {
        // Blocker search over the largest penumbra: mean distance of the samples nearer the light.
        float search = u_spot_params.w;
        float blockers = 0.0, sum = 0.0;
        for (int i = 0; i < taps; ++i) {
            vec2 offset = vogelTap(i, taps, angle) * search / tile;
            float d = textureLod(u_spot_depth, spotAtlasUv(slot, uv + offset), 0.0).r;
            if (d > depth + dot(gradient, offset)) {
                sum += spotLinearDepth(d, u_spot_range[slot].x, u_spot_range[slot].y);
                blockers += 1.0;
            }
        }
        if (blockers == 0.0) return 1.0;
        float blocker = sum / blockers;
        float penumbra_m = max(c.w - blocker, 0.0) * u_spot_bias.w / max(blocker, 1e-4);  // half of 000's w
        radius = clamp(penumbra_m / max(texel, 1e-8), radius, u_spot_params.w);
    }
    float lit = 0.0;
    for (int i = 0; i < taps; ++i) {
        vec2 offset = vogelTap(i, taps, angle) * radius / tile;
        lit += texture(u_spot_map, vec3(spotAtlasUv(slot, uv + offset), depth + dot(gradient, offset)));
    }
    return lit / float(taps);
}
