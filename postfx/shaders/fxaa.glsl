// "postfx.fxaa": FXAA 3.11 (Lottes 2011) with a 6-step edge search (1, 1, 1.5, 2, 4, 12 px). Finds the local
// luma contrast; where it is an edge, walks along it both ways to its ends and samples
// across it by the pixel's distance to the nearer end (plus a sub-pixel blur by how much the
// pixel differs from its 3x3 neighbourhood). FXAA_HDR: the input is linear HDR (placed before
// the tone map), so luma is compressed by l / (1 + l) first.
#include "../../renderer/shaders/fullscreen.glsl"

#ifdef FRAGMENT_SHADER
#include "../../renderer/shaders/bindings.glsl"
layout(binding = BINDING_TEX_0) uniform sampler2D u_image;
#include "fxaa_block.glsl"
layout(location = 0) out vec4 o_color;

float luma(vec3 c) {
    float l = dot(c, vec3(0.299, 0.587, 0.114));
#ifdef FXAA_HDR
    l = (isnan(l) || isinf(l)) ? 0.0 : max(l, 0.0) / (1.0 + max(l, 0.0));
#endif
    return l;
}

float lumaAt(vec2 uv) { return luma(textureLod(u_image, uv, 0.0).rgb); }

// The 3x3 neighbourhood by unfiltered fetches (cheaper than filtered taps on llvmpipe).
float lumaNear(ivec2 p, ivec2 offset) {
    return luma(texelFetch(u_image, clamp(p + offset, ivec2(0), textureSize(u_image, 0) - 1), 0).rgb);
}

void main() {
    vec2 texel = 1.0 / vec2(textureSize(u_image, 0));
    vec2 uv = gl_FragCoord.xy * texel;
    vec4 centre = texelFetch(u_image, ivec2(gl_FragCoord.xy), 0);
    float m = luma(centre.rgb);
    ivec2 p = ivec2(gl_FragCoord.xy);
    float n = lumaNear(p, ivec2(0, 1)), s = lumaNear(p, ivec2(0, -1));
    float e = lumaNear(p, ivec2(1, 0)), w = lumaNear(p, ivec2(-1, 0));
    float lo = min(m, min(min(n, s), min(e, w))), hi = max(m, max(max(n, s), max(e, w)));
    float range = hi - lo;
    if (range < max(u_edge_threshold_min, hi * u_edge_threshold)) {
        o_color = centre;
        return;
    }
    float nw = lumaNear(p, ivec2(-1, 1)), ne = lumaNear(p, ivec2(1, 1));
    float sw = lumaNear(p, ivec2(-1, -1)), se = lumaNear(p, ivec2(1, -1));
    float edge_h = abs(-2.0 * w + nw + sw) + 2.0 * abs(-2.0 * m + n + s) + abs(-2.0 * e + ne + se);
    float edge_v = abs(-2.0 * s + sw + se) + 2.0 * abs(-2.0 * m + w + e) + abs(-2.0 * n + nw + ne);
    bool horizontal = edge_h >= edge_v;

    float average = (2.0 * (n + s + e + w) + nw + ne + sw + se) / 12.0;
    float sub = smoothstep(0.0, 1.0, clamp(abs(average - m) / range, 0.0, 1.0));
    sub = sub * sub * u_subpixel;

    float l1 = horizontal ? s : w, l2 = horizontal ? n : e;
    float g1 = abs(l1 - m), g2 = abs(l2 - m);
    float step_length = horizontal ? texel.y : texel.x;
    float local_average;
    if (g1 >= g2) {
        step_length = -step_length;
        local_average = 0.5 * (l1 + m);
    } else {
        local_average = 0.5 * (l2 + m);
    }
    float gradient = 0.25 * max(g1, g2);
    vec2 edge_uv = uv + (horizontal ? vec2(0.0, 0.5 * step_length) : vec2(0.5 * step_length, 0.0));
    vec2 along = horizontal ? vec2(texel.x, 0.0) : vec2(0.0, texel.y);
    vec2 uv1 = edge_uv - along, uv2 = edge_uv + along;
    float e1 = lumaAt(uv1) - local_average, e2 = lumaAt(uv2) - local_average;
    bool done1 = abs(e1) >= gradient, done2 = abs(e2) >= gradient;
    const float steps[5] = float[5](1.0, 1.5, 2.0, 4.0, 12.0);
    for (int i = 0; i < 5 && !(done1 && done2); ++i) {
        if (!done1) {
            uv1 -= along * steps[i];
            e1 = lumaAt(uv1) - local_average;
            done1 = abs(e1) >= gradient;
        }
        if (!done2) {
            uv2 += along * steps[i];
            e2 = lumaAt(uv2) - local_average;
            done2 = abs(e2) >= gradient;
        }
    }
    float d1 = horizontal ? uv.x - uv1.x : uv.y - uv1.y;
    float d2 = horizontal ? uv2.x - uv.x : uv2.y - uv.y;
    bool nearer1 = d1 < d2;
    float offset = 0.5 - min(d1, d2) / (d1 + d2);
    // Only when the luma at the nearer end moves away from the centre's side of the edge.
    bool centre_below = m < local_average;
    bool good = ((nearer1 ? e1 : e2) < 0.0) != centre_below;
    offset = max(good ? offset : 0.0, sub);
    vec2 final_uv = uv + (horizontal ? vec2(0.0, offset * step_length) : vec2(offset * step_length, 0.0));
    o_color = vec4(textureLod(u_image, final_uv, 0.0).rgb, centre.a);
}
#endif
