// Procedural material layers: periodic value-noise fBm shaped per layer (ripples for sand,
// blades for grass, strata for rock, soft drifts for snow, clods for dirt).
#include "terrain/materials.h"

#include <algorithm>
#include <cmath>

namespace vista {
namespace {

std::uint32_t hash(std::uint32_t x, std::uint32_t y, std::uint32_t seed) {
    std::uint32_t h = x * 0x8da6b343u ^ y * 0xd8163841u ^ seed * 0xcb1ab31fu;
    h ^= h >> 15;
    h *= 0x2c1b3c6du;
    h ^= h >> 12;
    h *= 0x297a2d39u;
    h ^= h >> 15;
    return h;
}

float lattice(int x, int y, int period, std::uint32_t seed) {
    auto wrap = [period](int v) { return std::uint32_t(((v % period) + period) % period); };
    return float(hash(wrap(x), wrap(y), seed) & 0xffffu) / 65535.0f;
}

// Value noise that tiles with the given period (in lattice cells).
float periodicNoise(float x, float y, int period, std::uint32_t seed) {
    int xi = int(std::floor(x)), yi = int(std::floor(y));
    float fx = x - float(xi), fy = y - float(yi);
    float ux = fx * fx * (3.0f - 2.0f * fx), uy = fy * fy * (3.0f - 2.0f * fy);
    float a = lattice(xi, yi, period, seed), b = lattice(xi + 1, yi, period, seed);
    float c = lattice(xi, yi + 1, period, seed), d = lattice(xi + 1, yi + 1, period, seed);
    return (a + (b - a) * ux) + ((c + (d - c) * ux) - (a + (b - a) * ux)) * uy;
}

// fBm over [0,1)^2 that tiles: octave k has period base << k.
float fbm(float u, float v, int base, int octaves, std::uint32_t seed) {
    float sum = 0.0f, amp = 0.5f, norm = 0.0f;
    for (int k = 0; k < octaves; ++k) {
        int period = base << k;
        sum += amp * periodicNoise(u * float(period), v * float(period), period, seed + std::uint32_t(k));
        norm += amp;
        amp *= 0.5f;
    }
    return sum / norm;
}

struct Layer {
    float r, g, b;        // base albedo (sRGB 0..1)
    float variation;      // albedo change with the noise
    float roughness;
    float bump;           // normal strength
    std::uint32_t seed;
};

constexpr Layer kLayers[int(MaterialLayer::Count)] = {
    {0.76f, 0.70f, 0.52f, 0.18f, 0.90f, 1.5f, 11u},  // sand
    {0.26f, 0.33f, 0.15f, 0.35f, 0.85f, 2.0f, 23u},  // grass
    {0.42f, 0.40f, 0.38f, 0.45f, 0.70f, 4.0f, 37u},  // rock
    {0.92f, 0.94f, 0.97f, 0.06f, 0.45f, 1.0f, 41u},  // snow
    {0.36f, 0.28f, 0.20f, 0.40f, 0.95f, 3.0f, 53u},  // dirt
};

float layerHeight(MaterialLayer layer, float u, float v) {
    const Layer& l = kLayers[int(layer)];
    float n = fbm(u, v, 4, 6, l.seed);
    switch (layer) {
        case MaterialLayer::Sand:  // wind ripples
            return 0.6f * n + 0.4f * (0.5f + 0.5f * std::sin(6.2831853f * (u * 24.0f + 3.0f * n)));
        case MaterialLayer::Grass: return std::pow(fbm(u, v, 32, 3, l.seed + 7u), 2.0f) * 0.6f + 0.4f * n;
        case MaterialLayer::Rock: {  // strata plus cracks
            float strata = 0.5f + 0.5f * std::sin(6.2831853f * (v * 6.0f + 2.5f * n));
            return 0.55f * n + 0.45f * strata * strata;
        }
        case MaterialLayer::Snow: return fbm(u, v, 2, 5, l.seed);
        default: return std::abs(n * 2.0f - 1.0f);
    }
}

std::uint8_t unorm(float v) { return std::uint8_t(std::clamp(v, 0.0f, 1.0f) * 255.0f + 0.5f); }

}  // namespace

MaterialImages generateMaterialImages(int size) {
    MaterialImages out;
    out.size = size;
    out.layers = int(MaterialLayer::Count);
    std::size_t texels = std::size_t(size) * std::size_t(size);
    out.albedo.resize(texels * 4 * std::size_t(out.layers));
    out.normal.resize(texels * 4 * std::size_t(out.layers));
    std::vector<float> h(texels);
    for (int layer = 0; layer < out.layers; ++layer) {
        const Layer& l = kLayers[layer];
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x)
                h[std::size_t(y * size + x)] = layerHeight(MaterialLayer(layer), (float(x) + 0.5f) / float(size),
                                                           (float(y) + 0.5f) / float(size));
        // The relief keeps the whole 8-bit range: stretched so the layer's lowest texel is 0 and its
        // highest 1 ([terrain.pom] depth_m says how deep that is).
        const auto [lo, hi] = std::minmax_element(h.begin(), h.end());
        const float h_min = *lo, h_range = std::max(*hi - *lo, 1e-6f);
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) {
                std::size_t i = std::size_t(y * size + x), o = (std::size_t(layer) * texels + i) * 4;
                float n = h[i];
                float shade = 1.0f + l.variation * (n - 0.5f);
                out.albedo[o + 0] = unorm(l.r * shade);
                out.albedo[o + 1] = unorm(l.g * shade);
                out.albedo[o + 2] = unorm(l.b * shade);
                out.albedo[o + 3] = unorm(l.roughness);
                // Central differences with wrap-around: the normal map tiles like the albedo.
                auto at = [&](int xx, int yy) { return h[std::size_t(((yy + size) % size) * size + (xx + size) % size)]; };
                float dx = (at(x + 1, y) - at(x - 1, y)) * l.bump, dy = (at(x, y + 1) - at(x, y - 1)) * l.bump;
                float len = std::sqrt(dx * dx + dy * dy + 1.0f);
                out.normal[o + 0] = unorm(0.5f - 0.5f * dx / len);
                out.normal[o + 1] = unorm(0.5f - 0.5f * dy / len);
                out.normal[o + 2] = unorm(0.5f + 0.5f / len);
                out.normal[o + 3] = unorm((n - h_min) / h_range);
            }
    }
    return out;
}

}  // namespace vista
