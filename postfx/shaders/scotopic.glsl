// "postfx.scotopic" (postfx/scotopic.h): the rods' share w per pixel from its luminance in
// cd/m^2; the colour mixed towards the rods' blue-shifted luminance, itself averaged over a
// disk of w * radius pixels (rod vision's lost acuity). NaN/Inf count as 0.
#include "../../renderer/shaders/fullscreen.glsl"

#ifdef FRAGMENT_SHADER
#include "../../renderer/shaders/bindings.glsl"
layout(binding = BINDING_TEX_0) uniform sampler2D u_image;
#include "scotopic_block.glsl"
layout(location = 0) out vec4 o_color;

// Krawczyk et al. 2005's tint of the rods' image (luminance ~1).
const vec3 kRodTint = vec3(1.05, 0.97, 1.27);

vec3 fetch(ivec2 p) {
    vec3 c = texelFetch(u_image, clamp(p, ivec2(0), textureSize(u_image, 0) - 1), 0).rgb;
    return (any(isnan(c)) || any(isinf(c))) ? vec3(0.0) : max(c, vec3(0.0));
}

// Scotopic luminance, V = Y for D65 white (postfx/scotopic.cpp scotopicLuminance).
float scotopic(vec3 c) {
    float x = dot(c, vec3(0.4124, 0.3576, 0.1805));
    float y = dot(c, vec3(0.2126, 0.7152, 0.0722));
    float z = dot(c, vec3(0.0193, 0.1192, 0.9505));
    return x > 0.0 ? max(y * (1.33 * (1.0 + (y + z) / x) - 1.68), 0.0) / 2.5694 : 0.0;
}

float rodShare(float luminance_cd) {
    if (!(luminance_cd > 0.0)) return 1.0;
    return smoothstep(0.0, 1.0, (log(5.0) / log(10.0) - log(luminance_cd) / log(10.0)) / 3.0);
}

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec4 src = texelFetch(u_image, p, 0);
    vec3 c = fetch(p);
    float w = rodShare(dot(c, vec3(0.2126, 0.7152, 0.0722)) * u_cd_per_value);
#ifdef ROD_SHARE_VIEW
    o_color = vec4(vec3(w), src.a);
#else
    // The rods' luminance over a disk: the centre and two rings of six (radii r/2 and r).
    float r = w * u_blur_px;
    float v = scotopic(c);
    if (r >= 0.5) {
        float sum = v, weight = 1.0;
        for (int i = 0; i < 6; ++i) {
            float a = float(i) * 1.0471976;
            vec2 d = vec2(cos(a), sin(a));
            sum += 0.75 * scotopic(fetch(p + ivec2(round(d * 0.5 * r))));
            sum += 0.4 * scotopic(fetch(p + ivec2(round(vec2(d.x * 0.866 - d.y * 0.5, d.x * 0.5 + d.y * 0.866) * r))));
            weight += 0.75 + 0.4;
        }
        v = sum / weight;
    }
    vec3 rods = v * mix(vec3(1.0), kRodTint, u_blue_shift);
    o_color = vec4(mix(c, rods, w), src.a);
#endif
}
#endif
