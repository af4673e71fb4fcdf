// Test probe (tests/gl/lights_test.cpp): the radiance light 0 reflects from a white-ish
// up-facing surface at a grid of camera-relative points, through shadeLocalLight() and
// evalBrdf(), for comparison with the CPU mirror (renderer/lights.h, renderer/lighting/brdf.h).
#include "../../../renderer/shaders/fullscreen.glsl"

#ifdef FRAGMENT_SHADER
#include "../../../renderer/shaders/common.glsl"
#include "../../../renderer/shaders/gbuffer.glsl"
#include "../../../renderer/lighting/shaders/brdf.glsl"
#include "../../../renderer/lighting/shaders/lights.glsl"
layout(location = 0) out vec4 o_probe;

void main() {
    vec2 p = floor(gl_FragCoord.xy);
    vec3 position = vec3(p.x * 0.5 - 20.0, -6.0 + 0.05 * p.y, -2.0 - 0.5 * p.y);  // tests mirror this
    Surface s;
    s.albedo = vec3(0.8, 0.6, 0.4);
    s.roughness = 0.35;
    s.normal = normalize(vec3(0.1, 1.0, 0.2));
    s.f0 = 0.04;
    s.lit = true;
    bool reaches;
    vec3 c = shadeLocalLight(u_lights[0], s, position, safeNormalize(-position), reaches);
    o_probe = vec4(c, reaches ? 1.0 : 0.0);
}
#endif
