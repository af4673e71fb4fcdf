// Screen-space error control for CDLOD. Distance-only CDLOD gives every node of a level the
// same range, so one rough spot sets the detail of the whole map. Here each leaf cell knows
// how far each LOD level's grid strays from the full-resolution surface, and a distance bias
// field g >= 0 (metres, one value per leaf-cell corner, bilinear between) is added to the
// morph and selection distance:  d_eff(p) = |p - camera| + g(p).  The ranges are those that
// distance-only selection needs for the roughest cell (calibratedBaseRange); smooth cells get
// a large g (they look farther away, so they stay coarse), the roughest ones g = 0.
//
// The bound. A level-L vertex is drawn with d_eff in [range[L-1], range[L]], morphing toward
// level L+1 from start[L]. Its vertical error is at most e_{L+1}(cell) (the coarser grid's
// error, errors below); seen from distance d that is about e * error_scale / d pixels. So
// the error stays <= max_error_px wherever
//     g(p) <= G(cell) = min over L < top with e_{L+1} > 0 of  start[L] - error_scale * e_{L+1}(cell) / max_error_px,
// since then d = d_eff - g >= start[L] - g >= error_scale * e / max_error_px. g is the largest
// function below G whose slope is at most bias_slope (lambda), so d_eff is (1 + lambda)-Lipschitz
// and cdlod.cpp's crack-free range bounds hold with node diagonals scaled by 1 + lambda.
// Distance-only selection meets the same bound with g = 0 and a base range raised until every
// start[L] >= error_scale * max e_{L+1} / max_error_px (calibratedBaseRange).
#pragma once

#include "terrain/cdlod.h"

#include <glm/vec2.hpp>

#include <cmath>
#include <cstddef>
#include <vector>

namespace vista {

// Pixels of screen error per metre of vertical error seen from 1 m away on the view axis:
// height / (2 tan(fov/2)). Off the axis a segment projects up to 1 / cos^2 of its angle
// longer; the bound leaves that out (at 60 degrees and 16:9 it would more than double every
// range) and relies on the per-cell maxima being far above typical errors: vista bench
// terrain measures the rendered error, and the tests check it stays within the bound.
double screenErrorScale(double fov_y_deg, int height);

// The two rows of a level grid around texel row z of a map `height` texels high, the grid having
// vertices every `spacing` texels and on the last row: texel rows z0 <= z <= z1 and z's fraction
// between them. Columns are the same with the map's width.
struct GridRowSpan {
    int z0 = 0, z1 = 0;
    float fz = 0.0f;
};
GridRowSpan gridRowSpan(int z, int height, int spacing);

// The error (sample units) of one texel row of `width` samples against that grid between its rows
// z0 and z1 (gridRowSpan), given as the grid's vertices only (vertex i at texel
// min(i * spacing, width - 1)), per leaf cell: cells[cx] = max(cells[cx], the largest error over
// the cell's texels of this row, both borders included). scratch: any vector (holds width floats).
// GridErrors and the tile cache's writer (terrain/tile_cache.h) both measure through this.
void gridRowErrors(const float* row, const float* above, const float* below, int width, int spacing, float fz,
                   int leaf_texels, std::vector<float>& scratch, float* cells);

// Sample units to metres for grid errors.
inline float gridErrorScale(const TerrainMapping& mapping) { return float(std::abs(mapping.height_scale_m)); }

// Vertical error (m) of each LOD level's grid against the full-resolution surface, per leaf
// cell. Level L's grid has vertices every 2^L texels (clamped to the map's far edge) with
// heights sampled there, each quad split along its (x+1, z)-(x, z+1) diagonal as the terrain
// mesh is; the full-resolution surface is the same triangulation of every texel. Both are
// piecewise linear on a common refinement whose vertices are the texels, so the largest
// difference over a cell is the largest over its texels (edges included): exact.
class GridErrors {
public:
    GridErrors() = default;
    // levels: as many as the quadtree has (level 0, the full-resolution grid, has no error).
    GridErrors(const Heightmap& map, const TerrainMapping& mapping, int leaf_texels, int levels);
    // Given per level, per leaf cell (row-major, cells.x * cells.y each; m): the exact errors
    // above as a tile cache stores them (TileCache::gridErrors).
    GridErrors(glm::ivec2 cells, std::vector<std::vector<float>> levels_m);

    int levels() const { return int(levels_.size()); }
    glm::ivec2 cells() const { return cells_; }
    float at(int level, int x, int z) const {
        return levels_[std::size_t(level)][std::size_t(z) * std::size_t(cells_.x) + std::size_t(x)];
    }
    float maxAt(int level) const { return max_[std::size_t(level)]; }
    std::size_t memoryBytes() const;

private:
    glm::ivec2 cells_{0};
    std::vector<std::vector<float>> levels_;  // per level, row-major per leaf cell (m)
    std::vector<float> max_;
};

// The smallest base range >= lod.base_range_m at which distance-only selection (g = 0,
// lod.bias_slope ignored) keeps the error bound above.
double calibratedBaseRange(const MinMaxQuadtree& tree, const GridErrors& errors, const TerrainMapping& mapping,
                           LodSettings lod, double error_scale, double max_error_px);

// The largest bias slope <= max_slope that leaves the ranges at `base` (the calibrated
// distance-only base range): the crack bounds grow with 1 + slope, and a slope that raised the
// ranges beyond what the error needs would add triangles near the camera instead of saving them.
double usableBiasSlope(const MinMaxQuadtree& tree, const TerrainMapping& mapping, LodSettings lod, double base,
                       double max_slope);

class DistanceBias {
public:
    // g for the bound above; lod.bias_slope is lambda (> 0). Reuses its storage.
    void build(const MinMaxQuadtree& tree, const GridErrors& errors, const TerrainMapping& mapping,
               const LodSettings& lod, double error_scale, double max_error_px);
    // g = 0 everywhere (distance-only), sized for tree.
    void clear(const MinMaxQuadtree& tree, const TerrainMapping& mapping);

    // Corner values, row-major ((cells.x + 1) x (cells.y + 1)), metres.
    const std::vector<float>& corners() const { return corners_; }
    glm::ivec2 cornerCount() const { return cells_ + 1; }
    int leafTexels() const { return leaf_texels_; }
    // g at continuous texel coordinates: bilinear between the corners of the leaf cell that
    // holds them (a cell at the map's far edge may be narrower), as the vertex shader does.
    double at(double tx, double tz) const;
    // Smallest g over a quadtree node's area (corners are where a bilinear field is extreme).
    float minAt(int level, int x, int z) const {
        return mins_[std::size_t(level)][std::size_t(z) * std::size_t(per_side_[std::size_t(level)].x) + std::size_t(x)];
    }
    float lowest() const { return lowest_; }
    float highest() const { return highest_; }
    std::size_t memoryBytes() const;

private:
    void resize(const MinMaxQuadtree& tree, const TerrainMapping& mapping);
    void buildMins();

    int leaf_texels_ = 1;
    glm::ivec2 cells_{0}, map_{0};
    std::vector<float> corners_;
    std::vector<glm::ivec2> per_side_;
    std::vector<std::vector<float>> mins_;  // per quadtree level, row-major
    float lowest_ = 0.0f, highest_ = 0.0f;
};

}  // namespace vista
