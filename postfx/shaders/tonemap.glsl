// Exposure, tone mapping (one operator per variant) and sRGB encoding.
#include "../../renderer/shaders/fullscreen.glsl"

#ifdef FRAGMENT_SHADER
#include "../../renderer/shaders/bindings.glsl"
layout(binding = BINDING_TEX_0) uniform sampler2D u_hdr;
layout(location = 0) uniform float u_exposure;  // linear scale, 2^ev
layout(location = 1) uniform float u_white;     // Reinhard: value mapped to 1
layout(location = 0) out vec4 o_color;

// Narkowicz 2015 fit of the ACES RRT+ODT (input scaled so 0.18 stays mid-grey-ish).
vec3 acesFilm(vec3 x) {
    x *= 0.6;
    return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

// Extended Reinhard on luminance, keeping hue.
vec3 reinhard(vec3 c, float white) {
    float l = dot(c, vec3(0.2126, 0.7152, 0.0722));
    float mapped = l * (1.0 + l / (white * white)) / (1.0 + l);
    return l > 0.0 ? clamp(c * (mapped / l), 0.0, 1.0) : vec3(0.0);
}

vec3 linearToSrgb(vec3 c) {
    return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(0.0031308, c));
}

void main() {
    vec3 c = texelFetch(u_hdr, ivec2(gl_FragCoord.xy), 0).rgb * u_exposure;
    // A NaN or Inf that slipped through must not spread: show it as black (and the
    // nonfinite_pixels counter reports it).
    c = (any(isnan(c)) || any(isinf(c))) ? vec3(0.0) : max(c, vec3(0.0));
#if defined(TONEMAP_ACES)
    c = acesFilm(c);
#elif defined(TONEMAP_REINHARD)
    c = reinhard(c, u_white);
#else
    c = clamp(c, 0.0, 1.0);
#endif
    o_color = vec4(linearToSrgb(c), 1.0);
}
#endif
