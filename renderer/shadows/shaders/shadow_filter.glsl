// Shared by the sun cascades (shadows.glsl) and the spot shadow atlas (spot_shadows.glsl): the
// filter kernel's taps and the per-pixel rotation that turns banding into fine noise.
// Tap i of n on the unit disk: golden-angle spiral (evenly spread like a Poisson disk),
// rotated per pixel by `angle`.
vec2 vogelTap(int i, int n, float angle) {
    float r = sqrt((float(i) + 0.5) / float(n));
    float a = float(i) * 2.39996323 + angle;
    return r * vec2(cos(a), sin(a));
}

// Interleaved gradient noise (Jimenez 2014): a per-pixel rotation without a texture.
float shadowNoise(vec2 pixel) {
    return fract(52.9829189 * fract(dot(pixel, vec2(0.06711056, 0.00583715))));
}
