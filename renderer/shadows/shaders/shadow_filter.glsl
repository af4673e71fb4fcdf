// Shared by the sun cascades (shadows.glsl) and the spot shadow atlas (spot_shadows.glsl): the
// filter kernel's taps and the per-pixel rotation that turns banding into fine noise.
// Tap i of n on the unit disk: golden-angle spiral (evenly spread like a Poisson disk),
// rotated per pixel by `angle`.
#include "../../shaders/common.glsl"
#include "../../shaders/blue_noise.glsl"
vec2 vogelTap(int i, int n, float angle) {
    float r = sqrt((float(i) + 0.5) / float(n));
    float a = float(i) * 2.39996323 + angle;
    return r * vec2(cos(a), sin(a));
}

// The kernel's per-pixel rotation in [0, 1) turns: spatiotemporal blue noise
// (renderer/shaders/blue_noise.glsl) at the screen estimators' frame index u_time.w (it moves
// each frame only while TAA averages it), channel 2 for the sun cascades and 3 for spot and point
// lights, so the rotations of one pixel's shadows are not the same.
float shadowNoise(vec2 pixel, int channel) {
    return blueNoise(ivec2(pixel), uint(u_time.w), channel);
}
