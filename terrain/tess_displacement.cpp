// The displacement of terrain_tess.glsl in double (the GL test's reference).
#include "terrain/tess_displacement.h"

#include <algorithm>
#include <cmath>

namespace vista {

TessRelief tessRelief(double depth_m, double range_m, double period_m) {
    TessRelief r;
    r.depth_m = depth_m;
    r.period_m = period_m;
    r.fade_start_m = 0.5 * range_m;
    r.fade_end_m = 0.9 * range_m;
    return r;
}

double tessFade(const TessRelief& r, double distance_m) {
    const double t = std::clamp((distance_m - r.fade_start_m) / (r.fade_end_m - r.fade_start_m), 0.0, 1.0);
    return 1.0 - t * t * (3.0 - 2.0 * t);
}

double reliefAt(const MaterialImages& m, int layer, double u, double v) {
    const int n = m.size;
    const double x = u * n - 0.5, y = v * n - 0.5;
    const double fx = std::floor(x), fy = std::floor(y);
    auto at = [&](double xx, double yy) {
        const int i = int((static_cast<long long>(xx) % n + n) % n), j = int((static_cast<long long>(yy) % n + n) % n);
        return double(materialHeight(m, layer, i, j));
    };
    const double ax = x - fx, ay = y - fy;
    const double top = at(fx, fy) + (at(fx + 1, fy) - at(fx, fy)) * ax;
    const double bottom = at(fx, fy + 1) + (at(fx + 1, fy + 1) - at(fx, fy + 1)) * ax;
    return top + (bottom - top) * ay;
}

double tessDisplacement(const MaterialImages& m, const TessRelief& r, const glm::dvec3& rel, const glm::dvec2& world_xz) {
    const double fade = tessFade(r, glm::length(rel));
    if (fade <= 0.0) return 0.0;
    const double h = reliefAt(m, r.layer, world_xz.x / r.period_m, world_xz.y / r.period_m);
    return (h - 1.0) * r.depth_m * fade;
}

}  // namespace vista
