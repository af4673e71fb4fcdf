// The sea grid's visible sectors (see grid_sectors.h). A point q of the still surface displaced
// by d (|d.x|, |d.z| <= chop, |d.y| <= height) is inside the frustum only if q is inside every
// plane widened by the displacement's largest reach along its normal. Those widened planes cut
// the surface plane y = -h in half-planes; clipping the grid's bounding square by them leaves a
// convex polygon that holds every rest point that can be seen. Seen from the eye's x, z (the
// grid's centre) it spans an angle under 180 degrees unless it holds the centre; the segments
// over that angle are the ones drawn.
#include "terrain/water/grid_sectors.h"

#include "terrain/water/water.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace vista {

namespace {

using Polygon = std::vector<glm::dvec2>;

// Keeps the part of `poly` where a x + c z + d >= 0 (Sutherland-Hodgman).
Polygon clipHalfPlane(const Polygon& poly, double a, double c, double d) {
    Polygon out;
    const std::size_t n = poly.size();
    for (std::size_t i = 0; i < n; ++i) {
        const glm::dvec2 p = poly[i], q = poly[(i + 1) % n];
        const double fp = a * p.x + c * p.y + d, fq = a * q.x + c * q.y + d;
        if (fp >= 0.0) out.push_back(p);
        if ((fp >= 0.0) != (fq >= 0.0)) out.push_back(p + (q - p) * (fp / (fp - fq)));
    }
    return out;
}

}  // namespace

SectorRange visibleSectors(const WaterGrid& grid, double height_above_m, double max_height_m, double max_chop_m,
                           const Frustum& frustum) {
    const SectorRange all{0, grid.segments};
    const double outer = grid.ring_constant * std::expm1(grid.angle * double(grid.rings));
    Polygon poly = {{-outer, -outer}, {outer, -outer}, {outer, outer}, {-outer, outer}};
    for (const glm::dvec4& p : frustum) {
        // Widened by the displacement's reach along the normal; on the plane y = -h.
        const double d = p.w + max_chop_m * (std::abs(p.x) + std::abs(p.z)) + max_height_m * std::abs(p.y) -
                         p.y * height_above_m;
        poly = clipHalfPlane(poly, p.x, p.z, d);
        if (poly.empty()) return {0, 0};
    }
    // Clipping keeps the square's counter-clockwise winding in (x, z): the centre is inside (or on
    // an edge) when it is left of every edge p -> q, i.e. cross(p, q) >= 0; then every direction
    // may be seen. The tolerance errs towards drawing.
    bool inside = true;
    for (std::size_t i = 0; i < poly.size() && inside; ++i) {
        const glm::dvec2 p = poly[i], q = poly[(i + 1) % poly.size()];
        inside = p.x * q.y - p.y * q.x >= -1e-12 * (glm::dot(p, p) + glm::dot(q, q)) - 1e-9;
    }
    if (inside) return all;
    // Angles about the direction of the polygon's mean vertex (the polygon spans under pi).
    glm::dvec2 mean(0.0);
    for (const glm::dvec2& p : poly) mean += p;
    const double base = std::atan2(mean.y, mean.x);
    double lo = 0.0, hi = 0.0;
    for (const glm::dvec2& p : poly) {
        double t = std::atan2(p.y, p.x) - base;
        t = std::remainder(t, 2.0 * std::numbers::pi);
        lo = std::min(lo, t);
        hi = std::max(hi, t);
    }
    if (hi - lo >= std::numbers::pi) return all;
    const int first = int(std::floor((base + lo) / grid.angle));
    const int last = int(std::floor((base + hi) / grid.angle));  // inclusive
    const int count = std::min(last - first + 1, grid.segments);
    const int wrapped = ((first % grid.segments) + grid.segments) % grid.segments;
    return {wrapped, count};
}

}  // namespace vista
