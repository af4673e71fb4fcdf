// "postfx.night_vision" (after 000's night vision): luminance amplified by gain, plus noise that
// changes noise_rate times per second of scene time (the same time gives the same image), shown
// in a phosphor tint inside a round scope whose edge darkens by `vignette`. On display values:
// NaN/Inf count as 0 and the result is clamped to [0, 1].
#include "../../renderer/shaders/fullscreen.glsl"

#ifdef FRAGMENT_SHADER
#include "../../renderer/shaders/bindings.glsl"
#include "hash_noise.glsl"
layout(binding = BINDING_TEX_0) uniform sampler2D u_image;
#include "night_vision_block.glsl"
layout(location = 0) out vec4 o_color;


void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec2 size = vec2(textureSize(u_image, 0));
    vec4 src = texelFetch(u_image, p, 0);
    vec3 c = (any(isnan(src.rgb)) || any(isinf(src.rgb))) ? vec3(0.0) : max(src.rgb, vec3(0.0));
    float l = dot(c, vec3(0.2126, 0.7152, 0.0722)) * u_gain;
    l += u_noise * (hashNoise(uvec3(uvec2(p), uint(u_noise_index))) - 0.5);
    // The scope: a circle of the image height, soft over its outer 15 %.
    float r = length((gl_FragCoord.xy - 0.5 * size) / (0.5 * size.y));
    l *= 1.0 - u_scope_vignette * smoothstep(0.85, 1.0, r);
    o_color = vec4(clamp(l * u_tint, 0.0, 1.0), src.a);
}
#endif
