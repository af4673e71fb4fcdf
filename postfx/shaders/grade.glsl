// "postfx.grade": lift/gamma/gain per channel (on display values, so grade belongs after the
// tone map), saturation around Rec.709 luma, a smooth vignette towards the corners, and film
// grain weighted by luminance (none at black and white), a new pattern grain_rate times a second.
#include "../../renderer/shaders/fullscreen.glsl"

#ifdef FRAGMENT_SHADER
#include "../../renderer/shaders/bindings.glsl"
#include "hash_noise.glsl"
layout(binding = BINDING_TEX_0) uniform sampler2D u_image;
#include "grade_block.glsl"
#ifdef GRADE_LUT
layout(binding = BINDING_TEX_1) uniform sampler3D u_lut;
#endif
layout(location = 0) out vec4 o_color;


void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec2 size = vec2(textureSize(u_image, 0));
    vec4 src = texelFetch(u_image, p, 0);
    vec3 c = max(src.rgb, vec3(0.0));
    c = u_gain * (c + u_lift * (1.0 - c));
    c = pow(max(c, vec3(0.0)), u_inv_gamma);
    float l = dot(c, vec3(0.2126, 0.7152, 0.0722));
    c = max(mix(vec3(l), c, u_saturation), vec3(0.0));
#ifdef GRADE_LUT
    c = max(texture(u_lut, c * u_lut_scale + u_lut_offset).rgb, vec3(0.0));
#endif
    // 0 at the centre, 1 in the corners, round on screen.
    vec2 d = (gl_FragCoord.xy / size - 0.5) * vec2(size.x / size.y, 1.0);
    float r = length(d) / length(vec2(0.5 * size.x / size.y, 0.5));
    c *= 1.0 - u_vignette * smoothstep(u_vignette_start, 1.0, r);
    if (u_grain > 0.0) {
        // Zero-mean grain, strongest at mid-grey: 4 l (1 - l) keeps black black and white white.
        float lum = clamp(dot(c, vec3(0.2126, 0.7152, 0.0722)), 0.0, 1.0);
        float g = hashNoise(uvec3(uvec2(p), uint(u_grain_index))) - 0.5;
        c = max(c + u_grain * 4.0 * lum * (1.0 - lum) * g, vec3(0.0));
    }
    o_color = vec4(c, src.a);
}
#endif
