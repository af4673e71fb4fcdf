// "postfx.bloom.upN": a 3x3 tent (1 2 1, from four bilinear taps) over the coarser level, mixed with this level's
// downsample: up = mix(down, tent(coarser), u_mix) (radius: how much the wider levels
// count). BLOOM_COMPOSITE (the last step, at full size) mixes the tent into the image itself:
// out = mix(image, tent, intensity), after replacing NaN/Inf in the image by 0 and clamping it to
// the half-float range, so a bad pixel stays one bad (now finite) pixel.
#include "../../renderer/shaders/fullscreen.glsl"

#ifdef FRAGMENT_SHADER
#include "../../renderer/shaders/bindings.glsl"
layout(binding = BINDING_TEX_0) uniform sampler2D u_fine;  // this level's downsample, or the image
layout(binding = BINDING_TEX_1) uniform sampler2D u_coarse;
#include "bloom_block.glsl"
layout(location = 0) out vec4 o_color;

void main() {
    vec2 uv = gl_FragCoord.xy / vec2(textureSize(u_fine, 0));
    vec2 t = 1.0 / vec2(textureSize(u_coarse, 0));
    // The 3x3 tent (1 2 1) from four bilinear taps half a texel off each diagonal: exact where
    // this pixel sits on a coarse texel centre, a smooth symmetric kernel elsewhere.
    vec3 tent = textureLod(u_coarse, uv + 0.5 * vec2(-t.x, -t.y), 0.0).rgb + textureLod(u_coarse, uv + 0.5 * vec2(t.x, -t.y), 0.0).rgb +
                textureLod(u_coarse, uv + 0.5 * vec2(-t.x, t.y), 0.0).rgb + textureLod(u_coarse, uv + 0.5 * t, 0.0).rgb;
    tent *= 0.25;
    vec4 fine = texelFetch(u_fine, ivec2(gl_FragCoord.xy), 0);
#ifdef BLOOM_COMPOSITE
    fine.rgb = (any(isnan(fine.rgb)) || any(isinf(fine.rgb))) ? vec3(0.0) : clamp(fine.rgb, vec3(-65504.0), vec3(65504.0));
#endif
    o_color = vec4(mix(fine.rgb, tent, u_mix), fine.a);
}
#endif
