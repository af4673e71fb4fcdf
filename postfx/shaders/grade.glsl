// "postfx.grade": lift/gamma/gain per channel (on display values, so grade belongs after the
// tone map), saturation around Rec.709 luma, and a smooth vignette towards the corners.
#include "../../renderer/shaders/fullscreen.glsl"

#ifdef FRAGMENT_SHADER
#include "../../renderer/shaders/bindings.glsl"
layout(binding = BINDING_TEX_0) uniform sampler2D u_image;
layout(location = 0) uniform vec3 u_lift;
layout(location = 1) uniform vec3 u_inv_gamma;  // 1 / gamma
layout(location = 2) uniform vec3 u_gain;
layout(location = 3) uniform vec3 u_shape;      // saturation, vignette, vignette_start
layout(location = 0) out vec4 o_color;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec2 size = vec2(textureSize(u_image, 0));
    vec4 src = texelFetch(u_image, p, 0);
    vec3 c = max(src.rgb, vec3(0.0));
    c = u_gain * (c + u_lift * (1.0 - c));
    c = pow(max(c, vec3(0.0)), u_inv_gamma);
    float l = dot(c, vec3(0.2126, 0.7152, 0.0722));
    c = max(mix(vec3(l), c, u_shape.x), vec3(0.0));
    // 0 at the centre, 1 in the corners, round on screen.
    vec2 d = (gl_FragCoord.xy / size - 0.5) * vec2(size.x / size.y, 1.0);
    float r = length(d) / length(vec2(0.5 * size.x / size.y, 0.5));
    c *= 1.0 - u_shape.y * smoothstep(u_shape.z, 1.0, r);
    o_color = vec4(c, src.a);
}
#endif
