// CPU mirror of terrain/shaders/material.glsl: where the terrain is sand, grass, rock, snow or
// dirt. Grass placement tests use it to check where blades may grow.
#pragma once

#include <algorithm>
#include <cmath>

namespace vista::material {

struct Bands {
    double sand_top = 0.135, grass_top = 0.45, snow_start = 0.70, blend = 0.03;  // heightmap units
};

inline double smoothstep(double e0, double e1, double x) {
    double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

inline double bands(double h, const Bands& b) {
    return std::clamp((h - b.sand_top) / b.blend, 0.0, 1.0) + std::clamp((h - b.grass_top) / b.blend, 0.0, 1.0) +
           std::clamp((h - b.snow_start) / b.blend, 0.0, 1.0);
}

inline double bandJitter(double noise, double band_jitter) { return (noise - 0.45) * 2.0 * band_jitter; }

inline double rockWeight(double normal_y, double rock_slope) {
    return 1.0 - smoothstep(rock_slope - 0.06, rock_slope + 0.06, normal_y);
}

inline double dirtWeight(double normal_y, double rock_slope, double rock, double l) {
    double lower_two = std::min(std::floor(l), 3.0) <= 1.5 ? 1.0 : 0.0;
    return 0.7 * (1.0 - smoothstep(rock_slope + 0.04, rock_slope + 0.12, normal_y)) * (1.0 - rock) * lower_two;
}

inline double grassWeight(double l, double rock, double dirt) {
    double band = std::min(l, 1.0) - std::clamp(l - 1.0, 0.0, 1.0);
    return band * (1.0 - rock) * (1.0 - dirt);
}

// Grass weight at a heightmap value h (already jittered) and terrain normal y.
inline double grassAt(double h, double normal_y, const Bands& b, double rock_slope) {
    double l = bands(h, b);
    double rock = rockWeight(normal_y, rock_slope);
    return grassWeight(l, rock, dirtWeight(normal_y, rock_slope, rock, l));
}

}  // namespace vista::material
