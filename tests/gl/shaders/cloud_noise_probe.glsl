// Test probe (tests/gl/clouds_test.cpp): the clouds' value noise (r) and 5-octave fBm (g) at a
// grid of points, for comparison with the CPU mirror (sky/clouds/cloud_model.h). The test mirrors the
// point formula.
#include "../../../renderer/shaders/fullscreen.glsl"

#ifdef FRAGMENT_SHADER
#include "../../../sky/clouds/shaders/cloud_noise.glsl"
layout(location = 0) out vec4 o_probe;

void main() {
    vec2 p = floor(gl_FragCoord.xy);
    vec3 q = vec3(p.x * 1.37 - 40.0, p.y * 0.29 + 0.11, p.y * 2.13 - p.x * 0.71);
    o_probe = vec4(cloudValueNoise(q, CLOUD_NOISE_PERIOD, 12345u), cloudFbm(q, 5, 777u), 0.0, 1.0);
}
#endif
