// "postfx.bloom.downN": Jimenez 2014's 13-tap downsample to half size: five overlapping 2x2
// boxes (centre 0.5, four corners 0.125 each) from 13 bilinear taps. BLOOM_FIRST (the first
// level) also replaces NaN/Inf by 0, clamps highlights and weights each box by
// 1 / (1 + luma) (Karis average), so one very bright pixel cannot flicker into a large blob.
#include "../../renderer/shaders/fullscreen.glsl"

#ifdef FRAGMENT_SHADER
#include "../../renderer/shaders/bindings.glsl"
layout(binding = BINDING_TEX_0) uniform sampler2D u_source;
#include "bloom_block.glsl"
layout(location = 0) out vec4 o_color;

vec3 tap(vec2 uv) {
    vec3 c = textureLod(u_source, uv, 0.0).rgb;
#ifdef BLOOM_FIRST
    c = (any(isnan(c)) || any(isinf(c))) ? vec3(0.0) : clamp(c, vec3(0.0), vec3(u_clamp));
#endif
    return c;
}

float karis(vec3 box) {
#ifdef BLOOM_FIRST
    return 1.0 / (1.0 + dot(box, vec3(0.2126, 0.7152, 0.0722)));
#else
    return 1.0;
#endif
}

void main() {
    // This texel's centre in uv (the level is floor(source / 2): with odd sizes the centre of
    // the image stays the centre of a texel at every level).
    vec2 uv = gl_FragCoord.xy / vec2(max(textureSize(u_source, 0) / 2, ivec2(1)));
    vec3 a = tap(uv + u_texel * vec2(-2.0, 2.0)), b = tap(uv + u_texel * vec2(0.0, 2.0)), c = tap(uv + u_texel * vec2(2.0, 2.0));
    vec3 d = tap(uv + u_texel * vec2(-2.0, 0.0)), e = tap(uv), f = tap(uv + u_texel * vec2(2.0, 0.0));
    vec3 g = tap(uv + u_texel * vec2(-2.0, -2.0)), h = tap(uv + u_texel * vec2(0.0, -2.0)), i = tap(uv + u_texel * vec2(2.0, -2.0));
    vec3 j = tap(uv + u_texel * vec2(-1.0, 1.0)), k = tap(uv + u_texel * vec2(1.0, 1.0));
    vec3 l = tap(uv + u_texel * vec2(-1.0, -1.0)), m = tap(uv + u_texel * vec2(1.0, -1.0));
    vec3 boxes[5] = vec3[5]((j + k + l + m) * 0.25, (a + b + d + e) * 0.25, (b + c + e + f) * 0.25,
                            (d + e + g + h) * 0.25, (e + f + h + i) * 0.25);
    const float share[5] = float[5](0.5, 0.125, 0.125, 0.125, 0.125);
    vec3 sum = vec3(0.0);
    float weight = 0.0;
    for (int n = 0; n < 5; ++n) {
        float w = share[n] * karis(boxes[n]);
        sum += boxes[n] * w;
        weight += w;
    }
    o_color = vec4(sum / weight, 1.0);
}
#endif
