// Debug views of scene targets ([debug] view), one program with the view as a uniform:
//   1 depth:   log2 of the view distance mapped to grey, infinity (sky) dark blue;
//   2 albedo:  the G-buffer's base colour (linear, shown as sRGB by the display);
//   3 normals: the G-buffer's world normal as colour (n * 0.5 + 0.5); unlit pixels black;
//   7 shadow:  the sun's visibility lighting.sun wrote into the HDR target (white lit);
//   4 lights:  heat map of local-light evaluations per pixel (lights.shade's count target),
//              blue 0 .. green .. yellow .. red at u_heat.x and above, sky dark.
#include "fullscreen.glsl"

#ifdef FRAGMENT_SHADER
#include "common.glsl"
#include "gbuffer.glsl"
layout(binding = BINDING_TEX_0) uniform sampler2D u_depth;
layout(binding = BINDING_TEX_1) uniform sampler2D u_source;   // albedo, normal or heat
#include "debug_view_block.glsl"
layout(location = 0) out vec4 o_color;

vec3 heat(float t) {
    const vec3 ramp[5] = vec3[](vec3(0.0, 0.0, 0.35), vec3(0.0, 0.45, 1.0), vec3(0.1, 0.9, 0.2), vec3(1.0, 0.9, 0.0),
                                vec3(1.0, 0.05, 0.0));
    float x = clamp(t, 0.0, 1.0) * 4.0;
    int i = min(int(x), 3);
    return mix(ramp[i], ramp[i + 1], x - float(i));
}

vec3 linearToSrgb(vec3 c) {
    return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(0.0031308, c));
}

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    float depth = texelFetch(u_depth, p, 0).r;
    vec3 sky = vec3(0.05, 0.07, 0.15);
    if (depth <= 0.0) {
        o_color = vec4(sky, 1.0);
        return;
    }
    vec3 c;
    if (u_debug_view.x == 2) {
        c = linearToSrgb(decodeSurface(texelFetch(u_source, p, 0), vec4(0.5, 0.5, 0.0, 1.0)).albedo);
    } else if (u_debug_view.x == 3) {
        vec4 n = texelFetch(u_source, p, 0);
        c = n.w > 0.5 ? decodeNormal(n.xy) * 0.5 + 0.5 : vec3(0.0);
    } else if (u_debug_view.x == 7) {
        c = vec3(clamp(texelFetch(u_source, p, 0).r, 0.0, 1.0));  // sun visibility (lighting.sun, SHADOW_TERM_VIEW)
    } else if (u_debug_view.x == 4) {
        float count = u_heat.x < 0.0 ? 0.0 : texelFetch(u_source, p, 0).r;  // < 0: no local lights
        // Lights evaluated at this pixel; 0 stays dark blue so light-free areas show.
        c = count > 0.0 ? heat(count / max(u_heat.x, 1.0)) : vec3(0.0, 0.0, 0.15);
    } else {
        // 1 m .. 64 km spread over the grey ramp.
        float t = clamp(log2(max(linearDepth(depth), 1e-3)) / 16.0, 0.0, 1.0);
        c = vec3(1.0 - t);
    }
    o_color = vec4(c, 1.0);
}
#endif
