// Heightmaps the unit tests build from a height function (no file, no GL).
#pragma once

#include "terrain/heightmap.h"

#include <cmath>
#include <cstddef>
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

}  // namespace vista::test
