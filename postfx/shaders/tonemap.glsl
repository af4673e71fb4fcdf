// Exposure, tone mapping (one operator per variant) and sRGB encoding: HDR in, RGBA8 out.
#include "../../renderer/shaders/fullscreen.glsl"

#ifdef FRAGMENT_SHADER
#include "../../renderer/shaders/bindings.glsl"
#include "exposure.glsl"
layout(binding = BINDING_TEX_0) uniform sampler2D u_hdr;
#include "tonemap_block.glsl"
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

// AgX (Sobotka) for Rec.709 input, after Wrensch's fit: inset matrix, log2 encoding over
// [-12.47, 4.03] stops around 0.18, a polynomial fit of the default contrast curve, outset
// matrix, then the curve's 2.2 power back to linear light for the sRGB encoding below.
// The fit is -0.0023 at 0; the max() after the outset keeps black at exactly 0.
vec3 agx(vec3 c) {
    const mat3 inset = mat3(0.842479062253094, 0.0423282422610123, 0.0423756549057051,
                            0.0784335999999992, 0.878468636469772, 0.0784336,
                            0.0792237451477643, 0.0791661274605434, 0.879142973793104);
    const mat3 outset = mat3(1.19687900512017, -0.0528968517574562, -0.0529716355144438,
                             -0.0980208811401368, 1.15190312990417, -0.0980434501171241,
                             -0.0990297440797205, -0.0989611768448433, 1.15107367264116);
    const float min_ev = -12.47393, max_ev = 4.026069;
    c = inset * c;
    c = (clamp(log2(max(c, vec3(1e-10))), min_ev, max_ev) - min_ev) / (max_ev - min_ev);
    vec3 x2 = c * c, x4 = x2 * x2;
    c = 15.5 * x4 * x2 - 40.14 * x4 * c + 31.96 * x4 - 6.868 * x2 * c + 0.4298 * x2 + 0.1191 * c - 0.00232;
    c = outset * c;
    return clamp(pow(max(c, vec3(0.0)), vec3(2.2)), 0.0, 1.0);
}

vec3 linearToSrgb(vec3 c) {
    return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(0.0031308, c));
}

void main() {
    vec3 c = texelFetch(u_hdr, ivec2(gl_FragCoord.xy), 0).rgb * exposureScale(u_exposure);
    // A NaN or Inf that slipped through must not spread: show it as black (and the
    // nonfinite_pixels counter reports it).
    c = (any(isnan(c)) || any(isinf(c))) ? vec3(0.0) : max(c, vec3(0.0));
#if defined(TONEMAP_ACES)
    c = acesFilm(c);
#elif defined(TONEMAP_REINHARD)
    c = reinhard(c, u_white);
#elif defined(TONEMAP_AGX)
    c = agx(c);
#else
    c = clamp(c, 0.0, 1.0);
#endif
    o_color = vec4(linearToSrgb(c), 1.0);
}
#endif
