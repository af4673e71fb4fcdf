// Test probe (tests/gl/weather_test.cpp): rainRippleNormal (sky/weather/shaders/rain_ripples.glsl) at a
// grid of points and times, intensity 0.8, for comparison with the CPU mirror
// (sky/weather/weather_model.h); alpha is 1 where intensity 0 gives exactly (0, 1, 0).
#include "../../../renderer/shaders/fullscreen.glsl"

#ifdef FRAGMENT_SHADER
#include "../../../sky/weather/shaders/rain_ripples.glsl"
layout(location = 0) out vec4 o_probe;

void main() {
    vec2 p = floor(gl_FragCoord.xy);
    vec2 xz = vec2(p.x * 0.0131 + 0.003, p.y * 0.0173 + 0.007);
    float t = (p.x + p.y) * 0.0371;
    vec3 n = rainRippleNormal(xz, t, 0.8);
    bool flat_ = rainRippleNormal(xz, t, 0.0) == vec3(0.0, 1.0, 0.0);
    o_probe = vec4(n, flat_ ? 1.0 : 0.0);
}
#endif
