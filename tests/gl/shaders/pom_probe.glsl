// Test probe (tests/gl/terrain_detail_test.cpp): pomMarch (terrain/shaders/pom.glsl) over one
// layer of the material relief (the detail array's alpha, mip 0, repeating) for a grid of view
// rays, in texture units (the surface is the plane y = 0, its normal +y). Each pixel: start
// point (u, v) spread over two texture repeats, so rays cross the repeat's borders; view
// azimuth from x, view zenith angle 0..85 deg from y. Output: the hit point's u, v, the hit's t.
#include "../../../renderer/shaders/fullscreen.glsl"

#ifdef FRAGMENT_SHADER
#include "../../../renderer/shaders/bindings.glsl"
layout(binding = BINDING_TEX_0) uniform sampler2DArray u_relief;
#include "pom_probe_block.glsl"
layout(location = 0) out vec4 o_probe;

float pomHeight(vec3 p) {
    return textureLod(u_relief, vec3(p.xz, float(u_params.x)), 0.0).a;
}
#include "../../../terrain/shaders/pom.glsl"

void main() {
    vec2 px = floor(gl_FragCoord.xy);
    float azimuth = 6.2831853 * (px.x + 0.5) / float(u_params.w);
    float zenith = radians(85.0) * px.y / max(u_probe.y - 1.0, 1.0);
    vec3 to_eye = vec3(sin(zenith) * cos(azimuth), cos(zenith), sin(zenith) * sin(azimuth));
    vec3 p0 = vec3(fract(px.x * 0.618034) * 2.0 - 0.5, 0.0, fract(px.y * 0.754878 + px.x * 0.1) * 2.0 - 0.5);
    vec3 n = vec3(0.0, 1.0, 0.0);
    vec3 span = pomSpan(to_eye, n, u_probe.x);
    float t = pomMarch(p0, span, pomSteps(dot(to_eye, n), u_params.y), u_params.z);
    vec3 hit = p0 - span * t;
    o_probe = vec4(hit.x, hit.z, t, 1.0);
}
#endif
