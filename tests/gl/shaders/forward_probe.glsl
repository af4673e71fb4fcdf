// Test probe for forward light lists (tests/gl/lights_test.cpp): each pixel places a surface
// point between 3 and 63 m in front of the camera along its view ray (in front of the opaque
// terrain) and shades it through forwardLocalLights(); it writes the lights that reach the point
// but were not in its list (must be 0), the lights that reach it (all of them, by a full loop)
// and the lights its list held.
#include "../../../renderer/shaders/fullscreen.glsl"

#ifdef FRAGMENT_SHADER
#include "../../../renderer/shaders/common.glsl"
#include "../../../renderer/shaders/gbuffer.glsl"
#include "../../../renderer/lighting/shaders/brdf.glsl"
#include "../../../renderer/lighting/shaders/lights.glsl"
layout(location = 0) out vec4 o_probe;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec3 ray = viewRay((vec2(p) + 0.5) * u_viewport.zw);
    uint h = uint(p.x) * 73856093u ^ uint(p.y) * 19349663u;
    h ^= h >> 13;
    h *= 0x5bd1e995u;
    h ^= h >> 15;
    float depth = 3.0 + 60.0 * float(h & 0xFFFFu) / 65535.0;
    vec3 position = ray * depth / max(-(mat3(u_view) * ray).z, 1e-3);
    Surface s;
    s.albedo = vec3(1.0);
    s.roughness = 0.5;
    s.normal = vec3(0.0, 1.0, 0.0);
    s.f0 = 0.04;
    s.lit = true;
    uint evaluated, exact;
    vec3 color = forwardLocalLights(s, position, p, uvec2(0u, 0xFFFFFFFFu), evaluated, exact);  // the whole range
    uint reaching = 0u;
    for (uint i = 0u; i < u_grid.x; ++i) {
        bool reaches;
        shadeLocalLight(u_lights[i], s, position, -ray, reaches);
        reaching += reaches ? 1u : 0u;
    }
    o_probe = vec4(float(reaching - exact), float(reaching), float(evaluated), color.r);
}
#endif
