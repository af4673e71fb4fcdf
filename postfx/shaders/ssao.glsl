// "postfx.ssao": horizon-based ambient occlusion (HBAO style) from depth and G-buffer normals.
// Per pixel, u_counts.x directions (rotated by spatiotemporal blue noise) are marched in screen
// space over the projection of radius_m; along each the highest horizon above the tangent plane
// (sine of its elevation, less the bias, faded by distance) is the occlusion from that side.
// Writes r = ambient visibility (1 = open), g = view distance along the axis (for the blur);
// sky and unlit pixels are open with g = 0.
#include "../../renderer/shaders/fullscreen.glsl"

#ifdef FRAGMENT_SHADER
#include "../../renderer/shaders/common.glsl"
#include "../../renderer/shaders/gbuffer.glsl"
#include "../../renderer/shaders/blue_noise.glsl"
layout(binding = BINDING_TEX_0) uniform sampler2D u_depth;
layout(binding = BINDING_TEX_1) uniform sampler2D u_normal;
#include "ssao_block.glsl"
layout(location = 0) out vec4 o_ao;

void main() {
    ivec2 full = textureSize(u_depth, 0);
    ivec2 p = min(ivec2(gl_FragCoord.xy) * int(u_params.w), full - 1);
    float depth = texelFetch(u_depth, p, 0).r;
    vec4 encoded = texelFetch(u_normal, p, 0);
    if (depth <= 0.0 || encoded.w < 0.5) {
        o_ao = vec4(1.0, 0.0, 0.0, 1.0);
        return;
    }
    vec3 origin = positionFromDepth((vec2(p) + 0.5) / vec2(full), depth);
    vec3 n = decodeNormal(encoded.xy);
    float z = linearDepth(depth);
    float radius = u_params.x, bias = u_params.z;
    // The radius in pixels at this distance, bounded so that near surfaces stay affordable.
    float radius_px = min(radius * u_proj[1][1] * 0.5 * float(full.y) / z, 0.25 * float(full.y));
    if (radius_px < 1.0) {
        o_ao = vec4(1.0, z, 0.0, 1.0);
        return;
    }
    // Spatiotemporal blue noise per SSAO texel (channel 1), moving each frame while TAA averages it.
    float noise = blueNoise(ivec2(gl_FragCoord.xy), uint(u_time.w), 1);
    float step_px = radius_px / float(u_counts.y);
    float occlusion = 0.0;
    for (int d = 0; d < u_counts.x; ++d) {
        float angle = (float(d) + noise) * (6.28318531 / float(u_counts.x));
        vec2 dir = vec2(cos(angle), sin(angle));
        float horizon = 0.0;
        for (int s = 0; s < u_counts.y; ++s) {
            ivec2 q = ivec2(vec2(p) + 0.5 + dir * ((float(s) + 0.5 + 0.5 * noise) * step_px));
            if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, full))) break;
            if (q == p) continue;
            float sample_depth = texelFetch(u_depth, q, 0).r;
            if (sample_depth <= 0.0) continue;
            vec3 h = positionFromDepth((vec2(q) + 0.5) / vec2(full), sample_depth) - origin;
            float len2 = dot(h, h);
            if (len2 >= radius * radius || len2 < 1e-12) continue;
            float sine = dot(h, n) * inversesqrt(len2);
            horizon = max(horizon, (sine - bias) / (1.0 - bias) * (1.0 - len2 / (radius * radius)));
        }
        occlusion += horizon;
    }
    float ao = clamp(1.0 - u_params.y * occlusion / float(u_counts.x), 0.0, 1.0);
    o_ao = vec4(ao, z, 0.0, 1.0);
}
#endif
