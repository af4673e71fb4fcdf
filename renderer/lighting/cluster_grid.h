// Screen tiles and clustered shading's depth slices (Olsson et al. 2012, as in 002), with a
// CPU reference light assignment that the GPU culling is tested against, and the projected
// bounds of a sphere (Mara & McGuire 2012) that tiled culling uses.
//
// View space: right-handed, the camera at the origin looking along -z, so a point's view depth is
// -z (m). Tiles are tile_px squares of the framebuffer from its lower-left corner (GL window
// coordinates): tile (tx, ty) covers pixels [tx * tile_px, (tx + 1) * tile_px) in x, the same in
// y, the last row and column cut by the framebuffer's edge. A pixel column at x_px has NDC
// x = 2 x_px / width - 1 and view-space slope x / depth = NDC x * tan(fov_y / 2) * aspect.
//
// Depth slices (002): near_k = near_0 * ratio^k, so slice k = floor(ln(depth / near_0) / ln ratio).
// 002's cubic clusters take ratio = 1 + 2 tan(theta) / S_y (theta = half the vertical field of
// view, S_y = tiles in y): a slice is then as deep as a tile is wide at its depth. Slice 0 also
// takes every depth below near_0 and the last slice every depth beyond its start, so each depth
// >= 0 has a slice.
#pragma once

#include "renderer/lights.h"

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace vista {

// 1 + 2 tan(fov_y / 2) / tiles_y: the slice ratio of cubic clusters.
double cubicSliceRatio(double fov_y_deg, int tiles_y);
// Slices from near_0 up to far_m with ratio: the smallest S with near_0 * ratio^S >= far_m (>= 1).
int slicesToReach(double near0_m, double far_m, double ratio);

struct ClusterGridParams {
    int width_px = 1, height_px = 1;  // framebuffer
    int tile_px = 16;
    double fov_y_deg = 60.0;          // vertical field of view
    double near0_m = 0.1;             // near_0 of the slices (usually the camera's near plane), > 0
    double far_m = 4000.0;            // depth the bounded slices reach, > near0_m
    int slices = 0;                   // > 0: exactly this many, ratio = (far / near_0)^(1 / slices);
                                      // 0: cubic clusters, slicesToReach(near_0, far, cubic ratio)
    int max_slices = 64;              // cap of the cubic count; above it the ratio grows to reach far
};

struct ClusterGrid {
    int width_px = 1, height_px = 1, tile_px = 16;
    int tiles_x = 1, tiles_y = 1, slices = 1;
    double tan_half_fov_y = 0.0, aspect = 1.0;  // aspect = width / height
    double near0_m = 0.1, far_m = 4000.0;
    double ratio = 2.0, log_ratio = 0.0;        // near_{k+1} / near_k and its natural log

    int clusterCount() const { return tiles_x * tiles_y * slices; }
    int index(int tx, int ty, int k) const { return tx + tiles_x * (ty + tiles_y * k); }
    // near_0 * ratio^k (the formula; k may be 0..slices).
    double sliceNear(int k) const;
    // Depth range a slice holds: [0, near_1) for slice 0, [near_{S-1}, inf) for the last.
    glm::dvec2 sliceRange(int k) const;
    // floor(ln(depth / near_0) / ln ratio) clamped to [0, slices - 1]; depths <= near_0 (and NaN) give 0.
    int sliceOf(double depth_m) const;
    // View-space slopes (x / depth, y / depth) of a tile's edges: (x0, x1, y0, y1).
    glm::dvec4 tileSlopes(int tx, int ty) const;
};

ClusterGrid makeClusterGrid(const ClusterGridParams& params);

// Conservative sphere-cluster overlap in view space: false only when the sphere cannot touch
// the cluster (tile's frustum between the slice's depths). The sphere must clear one of the
// tile's four side planes, or its depth range [depth - r, depth + r] must miss the slice's, or it
// must miss the axis-aligned box around the cluster cut to that depth range. Slice depths are
// widened by kSliceGuard (relative) so a fragment the GPU puts in a neighbouring slice by
// rounding is still covered. A sphere of radius <= 0 touches nothing.
inline constexpr double kSliceGuard = 1e-4;
bool sphereTouchesCluster(const ClusterGrid& grid, int tx, int ty, int k, const Sphere& view_sphere);

// Per-cluster light lists in one index array (the layout the GPU uses): cluster c's lights are
// indices[offset[c] .. offset[c] + count[c]), in increasing light order.
struct ClusterLists {
    std::vector<std::uint32_t> offset, count;  // per cluster, ClusterGrid::index order
    std::vector<std::uint32_t> indices;        // light indices
    std::uint64_t pairs = 0;     // (cluster, light) overlaps found, kept or not
    std::uint64_t overflow = 0;  // overlaps dropped because a list held max_per_cluster already
};

// CPU reference assignment: each light (a view-space bounding sphere, index = its position in
// view_spheres) goes to every cluster sphereTouchesCluster accepts, up to max_per_cluster per
// cluster (the lowest light indices are kept; the rest count as overflow).
void assignLights(const ClusterGrid& grid, std::span<const Sphere> view_spheres, int max_per_cluster,
                  ClusterLists& out);

// Bounds in NDC (x0, x1, y0, y1, each clamped to [-1, 1]) of a view-space sphere's projection
// under a perspective with the given tan(fov_y / 2) and aspect, after Mara & McGuire 2012: in
// each of the x-z and y-z planes the tangents from the eye to the circle of radius r at distance c
// touch it at distance t = sqrt(c^2 - r^2), their directions (t * c_hat +- r * c_perp) / c bound the
// projection. A side whose tangent turns past 90 degrees is unbounded (clamped to the edge).
// Returns false when the sphere is wholly behind near_m; the eye inside the sphere gives the
// whole screen. Conservative: it bounds the part of the sphere in front of the eye.
bool projectedSphereBounds(const Sphere& view_sphere, double tan_half_fov_y, double aspect, double near_m,
                           glm::dvec4& ndc_bounds);

}  // namespace vista
