// Sky gradient and sun disk (see sky/background.cpp).
#include "../../renderer/shaders/fullscreen.glsl"

#ifdef FRAGMENT_SHADER
#include "../../renderer/shaders/common.glsl"
layout(location = 0) uniform vec3 u_zenith;
layout(location = 1) uniform vec3 u_horizon;
in vec2 v_uv;
layout(location = 0) out vec4 o_color;

void main() {
    vec3 dir = viewRay(v_uv);
    vec3 sun = u_sun_dir.xyz;
    float up = max(dir.y, 0.0);
    // Brighter towards the horizon and around the sun; darker below the horizon.
    vec3 sky = mix(u_horizon, u_zenith, sqrt(up));
    float day = smoothstep(-0.2, 0.1, sun.y);
    float glow = pow(max(dot(dir, sun), 0.0), 8.0) * 0.5;
    sky = sky * (0.02 + day) + glow * vec3(1.0, 0.8, 0.6) * day;
    vec3 ground = u_horizon * 0.25 * (0.02 + day);
    vec3 color = dir.y >= 0.0 ? sky : mix(sky, ground, smoothstep(0.0, 0.05, -dir.y));
    // Sun disk: 0.53 degrees across, smoothed over a pixel-ish band.
    float disk = smoothstep(0.99997, 0.999985, dot(dir, sun));
    color += disk * u_sun_dir.w * 50.0 * vec3(1.0, 0.95, 0.9) * step(-0.01, sun.y);
    o_color = vec4(color * u_sun_dir.w * 0.25, 1.0);
}
#endif
