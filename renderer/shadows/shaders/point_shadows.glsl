// Point light shadows from the depth cubes (renderer/shadows/point_shadows.h): light slot -> cube,
// the receiver moved along its normal and towards the light by texel footprints (a face texel
// covers z * u_point_range.z metres at face distance z, the largest |component| of the offset
// from the light), then one hardware compare (hard), a rotated Vogel disk of compares (pcf) or
// PCSS (a blocker search, then a kernel as wide as the penumbra), as the spot shadows filter.
// The taps lie on the plane through the receiver across the light's direction; each compares the
// depth of the point where its ray from the light meets the receiver's own tangent plane (the
// receiver-plane bias of spot_shadows.glsl, here in world space: the face a tap falls on, and so
// its depth, is the hardware's pick), so a wide kernel does not shadow the receiver it lies on
// and taps cross cube seams freely. Reversed-Z: a larger depth is nearer the light.
#include "shadow_filter.glsl"

#define POINT_SHADOW_MAX 16  // kMaxPointShadows in renderer/shadows/point_shadows.h

layout(std140, binding = BINDING_POINT_SHADOW_UNIFORMS) uniform PointShadowUniforms {
    vec4 u_point_light[POINT_SHADOW_MAX];  // camera-relative light position (m), unused
    vec4 u_point_range[POINT_SHADOW_MAX];  // near (m), far (m), texel footprint per metre of face distance, unused
    vec4 u_point_params;  // x filter (0 hard, 1 pcf, 2 pcss), y taps, z face px, w max penumbra (texels)
    vec4 u_point_bias;    // x normal offset (texels), y depth bias (texels), z PCF radius (texels), w light radius (m)
};
layout(binding = BINDING_POINT_SHADOW_MAP) uniform samplerCubeArrayShadow u_point_map;
layout(binding = BINDING_POINT_SHADOW_DEPTH) uniform samplerCubeArray u_point_depth;

float pointFaceDistance(vec3 d) {
    vec3 a = abs(d);
    return max(a.x, max(a.y, a.z));
}

// The depth a cube holds at face distance z (pointFaceDepth in point_shadows.h).
float pointDepthAt(int slot, float z) {
    float n = u_point_range[slot].x, f = u_point_range[slot].y;
    return n * (f - z) / (max(z, 1e-6) * (f - n));
}

// Where the ray from the light along dir meets the plane through p with normal n (all relative
// to the light); dir itself where the ray runs along the plane or meets it far off.
vec3 pointOnPlane(vec3 dir, vec3 p, vec3 n) {
    float num = dot(p, n), den = dot(dir, n);
    if (abs(den) < 1e-6 * abs(num)) return dir;
    float t = num / den;
    return t > 0.5 && t < 2.0 ? dir * t : dir;
}

// Visibility (0 shadowed .. 1 lit) of camera-relative pos, normal n, unit direction l to the
// light, through the light's cube `slot`; angle rotates the kernel per pixel.
float pointShadow(int slot, vec3 pos, vec3 n, vec3 l, float ndotl, float angle) {
    vec3 d = pos - u_point_light[slot].xyz;  // light -> receiver
    float z = pointFaceDistance(d);
    float texel = z * u_point_range[slot].z;
    float sin_l = sqrt(clamp(1.0 - ndotl * ndotl, 0.0, 1.0));
    vec3 p = d + n * (u_point_bias.x * texel * sin_l) + l * (u_point_bias.y * texel);
    float layer = float(slot);
    int mode = int(u_point_params.x);
    if (mode == 0) return texture(u_point_map, vec4(p, layer), pointDepthAt(slot, pointFaceDistance(p)));
    int taps = int(u_point_params.y);
    float radius = u_point_bias.z;
    // The kernel's plane: across the light's direction, texel-sized steps at the receiver.
    vec3 axis = safeNormalize(p);
    vec3 t1 = safeNormalize(cross(axis, abs(axis.y) < 0.9 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0)));
    vec3 t2 = cross(axis, t1);
    float dist = length(p);
    if (mode == 2) {
        // Blocker search over the largest penumbra: mean distance of the samples nearer the light.
        float search = u_point_params.w;
        float blockers = 0.0, sum = 0.0;
        for (int i = 0; i < taps; ++i) {
            vec2 o = vogelTap(i, taps, angle) * search * texel;
            vec3 q = p + t1 * o.x + t2 * o.y;
            vec3 r = pointOnPlane(q, p, n);
            float zr = pointFaceDistance(r);
            float depth = textureLod(u_point_depth, vec4(q, layer), 0.0).r;
            if (depth > pointDepthAt(slot, zr)) {
                // The blocker's face distance back to metres along the tap's ray.
                float n_m = u_point_range[slot].x, f_m = u_point_range[slot].y;
                float zb = n_m * f_m / (n_m + depth * (f_m - n_m));
                sum += zb / max(zr, 1e-6) * length(r);
                blockers += 1.0;
            }
        }
        if (blockers == 0.0) return 1.0;
        float blocker = sum / blockers;
        float penumbra_m = max(dist - blocker, 0.0) * u_point_bias.w / max(blocker, 1e-4);
        radius = clamp(penumbra_m / max(texel, 1e-8), radius, u_point_params.w);
    }
    float lit = 0.0;
    for (int i = 0; i < taps; ++i) {
        vec2 o = vogelTap(i, taps, angle) * radius * texel;
        vec3 q = p + t1 * o.x + t2 * o.y;
        lit += texture(u_point_map, vec4(q, layer), pointDepthAt(slot, pointFaceDistance(pointOnPlane(q, p, n))));
    }
    return lit / float(taps);
}
