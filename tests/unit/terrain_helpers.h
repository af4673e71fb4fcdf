// Heightmaps and quadtrees the unit tests build from a height function (no file, no GL).
#pragma once

#include "renderer/camera.h"
#include "terrain/cdlod.h"
#include "terrain/heightmap.h"

#include <cmath>
#include <cstddef>
#include <random>
#include <vector>

namespace vista::test {

// n x n samples of height(x, z), row z = 0 first.
template <class Height>
Heightmap heightmapOf(int n, Height&& height) {
    Heightmap map{n, n, std::vector<float>(std::size_t(n) * std::size_t(n))};
    for (int z = 0; z < n; ++z)
        for (int x = 0; x < n; ++x) map.samples[std::size_t(z) * std::size_t(n) + std::size_t(x)] = float(height(x, z));
    return map;
}

// Rolling bumps 0.25..0.75: 0.5 + 0.25 sin(fx x) cos(fz z).
inline Heightmap bumpyHeightmap(int n, double fx, double fz) {
    return heightmapOf(n, [=](int x, int z) { return 0.5 + 0.25 * std::sin(x * fx) * std::cos(z * fz); });
}

// A 257 x 257 bumpy map over 4096 m, 600 m high, its min-max quadtree (16-texel leaves) and an
// LOD whose level 0 reaches 100 m: many levels and nodes for selection tests.
struct BumpyQuadtree {
    static constexpr int kSamples = 257;
    TerrainMapping mapping{4096.0, 600.0, 0.0, kSamples, kSamples};
    MinMaxQuadtree tree;
    LodSettings lod;
    BumpyQuadtree(double fx, double fz) : tree(bumpyHeightmap(kSamples, fx, fz), mapping, 16) { lod.base_range_m = 100.0; }
};

// A random 320x180 view within +-extent/2 m of the origin, altitude base_m + [0, rise_m), any
// heading, looking 5 to 45 degrees down.
inline ViewParams randomView(std::mt19937& rng, double extent_m, double base_m, double rise_m) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const double x = (u(rng) - 0.5) * extent_m, y = base_m + u(rng) * rise_m, z = (u(rng) - 0.5) * extent_m;
    const double yaw = u(rng) * 360, pitch = -5 - u(rng) * 40;
    return ViewParams{{x, y, z}, yaw, pitch, 60.0, 0.1, 320, 180};
}

}  // namespace vista::test
