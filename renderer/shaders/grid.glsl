// Infinite reference grid on y = 0 (see renderer/debug_grid.cpp).
#include "fullscreen.glsl"

#ifdef FRAGMENT_SHADER
#include "common.glsl"
#include "grid_block.glsl"
in vec2 v_uv;
layout(location = 0) out vec4 o_color;

// 1 on a line of the unit grid, 0 between; width about one pixel, fading out where
// cells get smaller than a few pixels.
float gridLines(vec2 c) {
    vec2 w = max(fwidth(c), vec2(1e-6));
    vec2 d = abs(fract(c - 0.5) - 0.5) / w;
    float line = 1.0 - min(min(d.x, d.y), 1.0);
    float fade = 1.0 - smoothstep(0.15, 0.5, max(w.x, w.y));
    return line * fade;
}

void main() {
    vec3 ray = viewRay(v_uv);
    // The plane is below the camera when u_height > 0: rays must point down (and vice versa).
    if (abs(ray.y) < 1e-6 || -u_height / ray.y <= 0.0) discard;
    float t = -u_height / ray.y;
    vec3 rel = ray * t;
    vec2 c = (u_origin + rel.xz) / u_spacing;
    float minor = gridLines(c);
    float major = gridLines(c * 0.1);
    vec3 albedo = vec3(0.32, 0.33, 0.30);
    albedo = mix(albedo, vec3(0.12), minor * 0.6);
    albedo = mix(albedo, vec3(0.85, 0.85, 0.80), major);
    vec3 n = vec3(0.0, sign(u_height + 1e-30), 0.0);
    float sun = max(dot(n, u_sun_dir.xyz), 0.0) * u_sun_dir.w;
    vec3 ambient = mix(vec3(0.3), vec3(0.25, 0.3, 0.4) * 1.5, u_sky.x);
    o_color = vec4(albedo * (sun + ambient), 1.0);
    vec4 clip = u_view_proj * vec4(rel, 1.0);
    gl_FragDepth = clamp(clip.z / clip.w, 0.0, 1.0);
}
#endif
