// A Catmull-Rom fetch of a bilinearly filtered texture with 5 bilinear taps (the corners of the
// 4x4 kernel dropped; Jimenez 2016, MJP's "SampleTextureCatmullRom"). Sharper than one bilinear
// tap, so a history reprojected frame after frame does not blur; negative lobes clamped at 0.
// Used by TAA (postfx/shaders/taa.glsl) and the cloud history (clouds_temporal.glsl).
vec4 textureCatmullRom(sampler2D tex, vec2 uv, vec2 size) {
    vec2 pos = uv * size;
    vec2 centre = floor(pos - 0.5) + 0.5;
    vec2 f = pos - centre;
    vec2 w0 = f * (-0.5 + f * (1.0 - 0.5 * f));
    vec2 w1 = 1.0 + f * f * (-2.5 + 1.5 * f);
    vec2 w2 = f * (0.5 + f * (2.0 - 1.5 * f));
    vec2 w3 = f * f * (-0.5 + 0.5 * f);
    vec2 w12 = w1 + w2;
    vec2 t0 = (centre - 1.0) / size, t3 = (centre + 2.0) / size;
    vec2 t12 = (centre + w2 / w12) / size;
    vec4 c = texture(tex, vec2(t12.x, t0.y)) * (w12.x * w0.y) + texture(tex, vec2(t0.x, t12.y)) * (w0.x * w12.y) +
             texture(tex, t12) * (w12.x * w12.y) + texture(tex, vec2(t3.x, t12.y)) * (w3.x * w12.y) +
             texture(tex, vec2(t12.x, t3.y)) * (w12.x * w3.y);
    float w = w12.x * w0.y + w0.x * w12.y + w12.x * w12.y + w3.x * w12.y + w12.x * w3.y;
    return max(c / w, vec4(0.0));
}
