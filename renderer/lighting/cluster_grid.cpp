// Cluster grid maths and the CPU reference light assignment. Everything is double precision;
// tests compare the GPU's lists against assignLights.
#include "renderer/lighting/cluster_grid.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace vista {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Signed slack of a sphere against the plane through the eye where slope * depth = coordinate,
// with the inside on the side `sign` (+1: coordinate >= slope * depth). Negative beyond -r: outside.
bool clearsPlane(double coord, double depth, double slope, double sign, double r) {
    double dist = sign * (coord - slope * depth) / std::sqrt(1.0 + slope * slope);
    return dist < -r;
}

// [lo, hi] of slope * depth over slopes in [s0, s1] and depths in [d0, d1] (d0 >= 0).
glm::dvec2 slopeRange(double s0, double s1, double d0, double d1) {
    double a = s0 * d0, b = s0 * d1, c = s1 * d0, d = s1 * d1;
    return {std::min({a, b, c, d}), std::max({a, b, c, d})};
}

// One axis of projectedSphereBounds: u across, w = depth forward. Returns false when the circle
// lies wholly behind the eye; else the slope range u / w of its visible part.
bool tangentSlopes(double u, double w, double r, double& lo, double& hi) {
    double c2 = u * u + w * w;
    if (c2 <= r * r) {  // the eye is inside
        lo = -kInf, hi = kInf;
        return true;
    }
    double c = std::sqrt(c2), t = std::sqrt(c2 - r * r);
    glm::dvec2 dir(u / c, w / c), perp(w / c, -u / c);  // perp: turns from +w toward +u
    glm::dvec2 plus = (t * dir + r * perp) / c;         // the tangent turned toward +u
    glm::dvec2 minus = (t * dir - r * perp) / c;        // ... toward -u
    // A tangent at or past 90 degrees (w <= 0) leaves that side open, or, if it has turned the
    // other way round, means the whole circle is behind the eye.
    if (plus.y > 0.0) hi = plus.x / plus.y;
    else if (plus.x > 0.0) hi = kInf;
    else return false;
    if (minus.y > 0.0) lo = minus.x / minus.y;
    else if (minus.x < 0.0) lo = -kInf;
    else return false;
    return lo <= hi;
}

}  // namespace

double cubicSliceRatio(double fov_y_deg, int tiles_y) {
    return 1.0 + 2.0 * std::tan(fov_y_deg * std::numbers::pi / 360.0) / double(std::max(tiles_y, 1));
}

int slicesToReach(double near0_m, double far_m, double ratio) {
    if (!(far_m > near0_m) || !(ratio > 1.0)) return 1;
    double s = std::ceil(std::log(far_m / near0_m) / std::log(ratio) - 1e-9);
    return int(std::clamp(s, 1.0, 1e6));
}

double ClusterGrid::sliceNear(int k) const { return near0_m * std::exp(log_ratio * double(k)); }

glm::dvec2 ClusterGrid::sliceRange(int k) const {
    return {k == 0 ? 0.0 : sliceNear(k), k >= slices - 1 ? kInf : sliceNear(k + 1)};
}

int ClusterGrid::sliceOf(double depth_m) const {
    if (!(depth_m > near0_m)) return 0;
    double k = std::floor(std::log(depth_m / near0_m) / log_ratio);
    return int(std::clamp(k, 0.0, double(slices - 1)));
}

glm::dvec4 ClusterGrid::tileSlopes(int tx, int ty) const {
    double sx = tan_half_fov_y * aspect, sy = tan_half_fov_y;
    double x0 = double(tx * tile_px), x1 = double(std::min((tx + 1) * tile_px, width_px));
    double y0 = double(ty * tile_px), y1 = double(std::min((ty + 1) * tile_px, height_px));
    return {(2.0 * x0 / width_px - 1.0) * sx, (2.0 * x1 / width_px - 1.0) * sx,
            (2.0 * y0 / height_px - 1.0) * sy, (2.0 * y1 / height_px - 1.0) * sy};
}

ClusterGrid makeClusterGrid(const ClusterGridParams& p) {
    ClusterGrid g;
    g.width_px = std::max(p.width_px, 1);
    g.height_px = std::max(p.height_px, 1);
    g.tile_px = std::max(p.tile_px, 1);
    g.tiles_x = (g.width_px + g.tile_px - 1) / g.tile_px;
    g.tiles_y = (g.height_px + g.tile_px - 1) / g.tile_px;
    g.tan_half_fov_y = std::tan(p.fov_y_deg * std::numbers::pi / 360.0);
    g.aspect = double(g.width_px) / double(g.height_px);
    g.near0_m = p.near0_m > 0.0 ? p.near0_m : 0.1;
    g.far_m = std::max(p.far_m, g.near0_m * 1.001);
    double span = std::log(g.far_m / g.near0_m);
    if (p.slices > 0) {
        g.slices = p.slices;
        g.log_ratio = span / double(g.slices);
    } else {
        double ratio = cubicSliceRatio(p.fov_y_deg, g.tiles_y);
        g.slices = slicesToReach(g.near0_m, g.far_m, ratio);
        g.log_ratio = std::log(ratio);
        if (g.slices > std::max(p.max_slices, 1)) {
            g.slices = std::max(p.max_slices, 1);
            g.log_ratio = span / double(g.slices);
        }
    }
    g.ratio = std::exp(g.log_ratio);
    return g;
}

bool sphereTouchesCluster(const ClusterGrid& g, int tx, int ty, int k, const Sphere& s) {
    double r = s.radius;
    if (!(r > 0.0)) return false;
    double depth = -s.center.z;
    glm::dvec2 range = g.sliceRange(k);
    double d0 = std::max(range.x * (1.0 - kSliceGuard), depth - r);
    double d1 = std::min(range.y * (1.0 + kSliceGuard), depth + r);
    if (d1 < std::max(d0, 0.0)) return false;
    d0 = std::max(d0, 0.0);
    glm::dvec4 sl = g.tileSlopes(tx, ty);
    if (clearsPlane(s.center.x, depth, sl.x, 1.0, r) || clearsPlane(s.center.x, depth, sl.y, -1.0, r) ||
        clearsPlane(s.center.y, depth, sl.z, 1.0, r) || clearsPlane(s.center.y, depth, sl.w, -1.0, r))
        return false;
    // The cluster cut to the sphere's depth range is bounded, so its box is finite.
    glm::dvec2 xr = slopeRange(sl.x, sl.y, d0, d1), yr = slopeRange(sl.z, sl.w, d0, d1);
    glm::dvec3 lo(xr.x, yr.x, -d1), hi(xr.y, yr.y, -d0);
    glm::dvec3 v = glm::clamp(s.center, lo, hi) - s.center;
    return glm::dot(v, v) <= r * r;
}

void assignLights(const ClusterGrid& g, std::span<const Sphere> spheres, int max_per_cluster, ClusterLists& out) {
    std::size_t clusters = std::size_t(g.clusterCount());
    out.offset.assign(clusters, 0);
    out.count.assign(clusters, 0);
    out.indices.clear();
    out.pairs = out.overflow = 0;
    std::vector<std::uint32_t> hits;  // (cluster) per overlap, light by light
    std::vector<std::uint32_t> light_of;
    std::vector<int> cols, rows;
    for (std::size_t i = 0; i < spheres.size(); ++i) {
        const Sphere& s = spheres[i];
        double r = s.radius, depth = -s.center.z;
        if (!(r > 0.0) || depth + r < 0.0) continue;
        // Columns and rows whose side planes the sphere does not clear, then slices by depth.
        cols.clear();
        rows.clear();
        for (int tx = 0; tx < g.tiles_x; ++tx) {
            glm::dvec4 sl = g.tileSlopes(tx, 0);
            if (!clearsPlane(s.center.x, depth, sl.x, 1.0, r) && !clearsPlane(s.center.x, depth, sl.y, -1.0, r))
                cols.push_back(tx);
        }
        for (int ty = 0; ty < g.tiles_y; ++ty) {
            glm::dvec4 sl = g.tileSlopes(0, ty);
            if (!clearsPlane(s.center.y, depth, sl.z, 1.0, r) && !clearsPlane(s.center.y, depth, sl.w, -1.0, r))
                rows.push_back(ty);
        }
        int k0 = std::max(g.sliceOf((depth - r) * (1.0 - kSliceGuard)) - 1, 0);
        int k1 = std::min(g.sliceOf((depth + r) * (1.0 + kSliceGuard)) + 1, g.slices - 1);
        for (int k = k0; k <= k1; ++k)
            for (int ty : rows)
                for (int tx : cols)
                    if (sphereTouchesCluster(g, tx, ty, k, s)) {
                        hits.push_back(std::uint32_t(g.index(tx, ty, k)));
                        light_of.push_back(std::uint32_t(i));
                    }
    }
    out.pairs = hits.size();
    std::uint32_t cap = std::uint32_t(std::max(max_per_cluster, 0));
    for (std::uint32_t c : hits) out.count[c] = std::min(out.count[c] + 1, cap);
    std::uint32_t total = 0;
    for (std::size_t c = 0; c < clusters; ++c) out.offset[c] = total, total += out.count[c];
    out.indices.resize(total);
    std::vector<std::uint32_t> fill(clusters, 0);
    for (std::size_t h = 0; h < hits.size(); ++h) {  // lights in increasing order: the lowest are kept
        std::uint32_t c = hits[h];
        if (fill[c] < out.count[c]) out.indices[out.offset[c] + fill[c]++] = light_of[h];
        else ++out.overflow;
    }
}

bool projectedSphereBounds(const Sphere& s, double tan_half_fov_y, double aspect, double near_m,
                           glm::dvec4& ndc) {
    double r = std::max(s.radius, 0.0), depth = -s.center.z;
    if (depth + r < near_m) return false;
    double x0, x1, y0, y1;
    if (!tangentSlopes(s.center.x, depth, r, x0, x1) || !tangentSlopes(s.center.y, depth, r, y0, y1)) return false;
    double sx = 1.0 / (tan_half_fov_y * aspect), sy = 1.0 / tan_half_fov_y;
    ndc = {std::clamp(x0 * sx, -1.0, 1.0), std::clamp(x1 * sx, -1.0, 1.0), std::clamp(y0 * sy, -1.0, 1.0),
           std::clamp(y1 * sy, -1.0, 1.0)};
    return true;
}

}  // namespace vista
