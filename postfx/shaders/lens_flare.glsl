// "postfx.lens_flare": adds to the image, times the sun's visibility and intensity * illuminance:
// - ghosts: soft discs at sun + k * spacing * (centre - sun), k = 1..ghosts, of varying size and
//   tint, fainter towards the ends;
// - a halo: a ring of radius halo_radius around the centre, brightest on the sun's side;
// - chromatic aberration: red and blue evaluated along the axis scaled by 1 -+ chromatic;
// - a starburst: 12 rays of uneven length around the sun, falling off with distance.
// Image NaN/Inf are left to the passes that sanitise (the flare itself is finite).
#include "../../renderer/shaders/fullscreen.glsl"

#ifdef FRAGMENT_SHADER
#include "postfx_bindings.glsl"
#include "../../renderer/shaders/bindings.glsl"
layout(binding = BINDING_TEX_0) uniform sampler2D u_image;
layout(std430, binding = POSTFX_BINDING_FLARE_VISIBILITY) readonly buffer FlareVisibility {
    float visibility;
    float target;
    float valid;
    float pad;
};
#include "lens_flare_block.glsl"
layout(location = 0) out vec4 o_color;

// Ghosts and halo for one colour channel, with the axis scaled by `scale`.
float flare(vec2 uv, float aspect, float scale) {
    vec2 axis = (vec2(0.5) - u_sun_uv) * scale;
    float sum = 0.0;
    int n = int(u_ghosts);
    for (int k = 1; k <= n; ++k) {
        vec2 pos = u_sun_uv + axis * (float(k) * u_ghost_spacing);
        float size = 0.03 + 0.05 * fract(float(k) * 0.618034);
        float d = length((uv - pos) * vec2(aspect, 1.0));
        sum += (1.0 - smoothstep(0.7 * size, size, d)) * (0.6 / float(k) + 0.2);
    }
    vec2 from_centre = (uv - vec2(0.5)) * vec2(aspect, 1.0);
    float r = length(from_centre) / scale;
    vec2 to_sun = (u_sun_uv - vec2(0.5)) * vec2(aspect, 1.0);
    float side = length(to_sun) > 1e-4 && r > 1e-4 ? max(dot(from_centre / max(length(from_centre), 1e-6), normalize(to_sun)), 0.0) : 1.0;
    float ring = exp(-pow((r - u_halo_radius) / 0.02, 2.0)) * (0.3 + 0.7 * side * side);
    return sum + ring;
}

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec2 size = vec2(textureSize(u_image, 0));
    vec4 src = texelFetch(u_image, p, 0);
    vec2 uv = gl_FragCoord.xy / size;
    float aspect = size.x / size.y;
    vec3 ghosts = vec3(flare(uv, aspect, 1.0 - u_chromatic), flare(uv, aspect, 1.0), flare(uv, aspect, 1.0 + u_chromatic));
    ghosts *= vec3(1.0, 0.8, 0.6);
    vec2 d = (uv - u_sun_uv) * vec2(aspect, 1.0);
    float r = length(d);
    float angle = atan(d.y, d.x);
    float rays = pow(abs(cos(angle * 6.0)), 40.0) * (0.6 + 0.4 * sin(angle * 17.0 + 1.3));
    float burst = u_starburst * (rays * exp(-r / 0.15) + exp(-r / 0.01)) ;
    float v = clamp(visibility, 0.0, 1.0);
    if (isnan(v)) v = 0.0;
    vec3 add = u_strength * v * (0.05 * ghosts + vec3(1.0, 0.95, 0.85) * burst);
    o_color = vec4(src.rgb + add, src.a);
}
#endif
