// Grid errors, the distance bias field and the distance-only calibration (terrain/lod_error.h).
#include "terrain/lod_error.h"

#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <thread>

namespace vista {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

// Largest |full resolution - level grid| (sample units) per leaf cell, for a grid with
// vertices every `spacing` texels, a row of texels at a time.
void levelError(const Heightmap& map, int leaf, int spacing, glm::ivec2 cells, std::vector<float>& out) {
    const int w = map.width, h = map.height;
    out.assign(std::size_t(cells.x) * std::size_t(cells.y), 0.0f);
    std::vector<float> scratch, above, below;
    std::vector<float> row_cells(std::size_t(cells.x));
    auto vertices = [&](int z, std::vector<float>& v) {
        v.resize(std::size_t((w - 2) / spacing + 2));
        for (std::size_t i = 0; i < v.size(); ++i)
            v[i] = map.at(int(std::min<std::int64_t>(std::int64_t(i) * spacing, w - 1)), z);
    };
    int grid_row = -1;
    for (int z = 0; z < h; ++z) {
        const GridRowSpan span = gridRowSpan(z, h, spacing);
        if (span.z0 != grid_row) {
            vertices(span.z0, above);
            vertices(span.z1, below);
            grid_row = span.z0;
        }
        std::fill(row_cells.begin(), row_cells.end(), 0.0f);
        gridRowErrors(&map.samples[std::size_t(z) * std::size_t(w)], above.data(), below.data(), w, spacing, span.fz, leaf,
                      scratch, row_cells.data());
        // A texel on a cell border belongs to both cells (they share it).
        for (int cz = std::max(0, (z - 1) / leaf); cz <= std::min(z / leaf, cells.y - 1); ++cz) {
            if (z < cz * leaf || z > (cz + 1) * leaf) continue;
            float* dst = &out[std::size_t(cz) * std::size_t(cells.x)];
            for (int cx = 0; cx < cells.x; ++cx) dst[cx] = std::max(dst[cx], row_cells[std::size_t(cx)]);
        }
    }
}

}  // namespace

GridRowSpan gridRowSpan(int z, int height, int spacing) {
    GridRowSpan s;
    s.z0 = std::min(z / spacing, (height - 2) / spacing) * spacing;
    s.z1 = std::min(s.z0 + spacing, height - 1);
    s.fz = float(z - s.z0) / float(s.z1 - s.z0);
    return s;
}

// Rows of texels are interpolated on the grid's quads (diagonal from (x+1, z) to (x, z+1), as
// terrain.cpp's index buffer splits them).
void gridRowErrors(const float* row, const float* above, const float* below, int width, int spacing, float fz,
                   int leaf_texels, std::vector<float>& scratch, float* cells) {
    const int w = width;
    scratch.resize(std::size_t(w));
    for (int x0 = 0, i = 0; x0 < w - 1; x0 += spacing, ++i) {
        int x1 = std::min(x0 + spacing, w - 1);
        float h00 = above[i], h10 = above[i + 1], h01 = below[i], h11 = below[i + 1];
        float inv = 1.0f / float(x1 - x0);
        for (int x = x0; x <= x1; ++x) {
            float fx = float(x - x0) * inv;
            float g = fx + fz <= 1.0f ? h00 + (h10 - h00) * fx + (h01 - h00) * fz
                                      : h11 + (h01 - h11) * (1.0f - fx) + (h10 - h11) * (1.0f - fz);
            scratch[std::size_t(x)] = std::abs(row[x] - g);
        }
    }
    const int count = (w - 2) / leaf_texels + 1;
    for (int cx = 0; cx < count; ++cx) {
        float e = cells[cx];
        for (int x = cx * leaf_texels; x <= std::min((cx + 1) * leaf_texels, w - 1); ++x) e = std::max(e, scratch[std::size_t(x)]);
        cells[cx] = e;
    }
}

double screenErrorScale(double fov_y_deg, int height) {
    double t = std::tan(glm::radians(std::clamp(fov_y_deg, 1.0, 179.0)) * 0.5);
    return double(std::max(height, 1)) / (2.0 * t);
}

GridErrors::GridErrors(const Heightmap& map, const TerrainMapping& mapping, int leaf_texels, int levels) {
    if (map.width < 2 || map.height < 2 || levels <= 0) return;
    leaf_texels = std::max(leaf_texels, 1);
    cells_ = {(map.width - 2) / leaf_texels + 1, (map.height - 2) / leaf_texels + 1};
    levels_.resize(std::size_t(levels));
    max_.assign(std::size_t(levels), 0.0f);
    levels_[0].assign(std::size_t(cells_.x) * std::size_t(cells_.y), 0.0f);
    // Levels are independent: split them over the cores.
    unsigned threads = std::clamp(std::thread::hardware_concurrency(), 1u, 8u);
    auto work = [&](unsigned t) {
        for (int level = 1 + int(t); level < levels; level += int(threads)) {
            std::int64_t spacing = std::int64_t(1) << level;
            levelError(map, leaf_texels, int(std::min<std::int64_t>(spacing, 1 << 30)), cells_, levels_[std::size_t(level)]);
        }
    };
    std::vector<std::thread> pool;
    for (unsigned t = 1; t < threads; ++t) pool.emplace_back(work, t);
    work(0);
    for (std::thread& t : pool) t.join();
    const float scale = gridErrorScale(mapping);
    for (std::size_t level = 0; level < levels_.size(); ++level) {
        for (float& e : levels_[level]) {
            e *= scale;
            max_[level] = std::max(max_[level], e);
        }
    }
}

GridErrors::GridErrors(glm::ivec2 cells, std::vector<std::vector<float>> levels_m)
    : cells_(cells), levels_(std::move(levels_m)) {
    max_.assign(levels_.size(), 0.0f);
    for (std::size_t level = 0; level < levels_.size(); ++level)
        for (float e : levels_[level]) max_[level] = std::max(max_[level], e);
}

std::size_t GridErrors::memoryBytes() const {
    std::size_t bytes = max_.capacity() * sizeof(float) + levels_.capacity() * sizeof(std::vector<float>);
    for (const std::vector<float>& level : levels_) bytes += level.capacity() * sizeof(float);
    return bytes;
}

double calibratedBaseRange(const MinMaxQuadtree& tree, const GridErrors& errors, const TerrainMapping& mapping,
                           LodSettings lod, double error_scale, double max_error_px) {
    lod.bias_slope = 0.0;
    std::vector<double> ends, starts;
    auto enough = [&](double base) {
        lod.base_range_m = base;
        lodRanges(tree, mapping, lod, ends, starts);
        for (std::size_t level = 0; level + 1 < ends.size(); ++level)
            if (starts[level] < error_scale * double(errors.maxAt(int(level) + 1)) / max_error_px) return false;
        return true;
    };
    double lo = std::max(lod.base_range_m, 1e-3);
    if (enough(lo)) return lo;
    double hi = lo * 2.0;
    while (!enough(hi) && hi < 1e12) hi *= 2.0;
    for (int i = 0; i < 60 && hi - lo > 1e-6 * hi; ++i) {
        double mid = 0.5 * (lo + hi);
        (enough(mid) ? hi : lo) = mid;
    }
    return hi;
}

double usableBiasSlope(const MinMaxQuadtree& tree, const TerrainMapping& mapping, LodSettings lod, double base,
                       double max_slope) {
    std::vector<double> ends, starts;
    auto needs = [&](double slope) {  // the base range the crack bounds alone ask for
        lod.base_range_m = 1e-3;
        lod.bias_slope = slope;
        lodRanges(tree, mapping, lod, ends, starts);
        return ends.empty() ? 0.0 : ends[0];
    };
    if (needs(max_slope) <= base) return max_slope;
    double lo = 0.0, hi = max_slope;
    if (needs(0.0) >= base) return 0.0;
    for (int i = 0; i < 40; ++i) {
        double mid = 0.5 * (lo + hi);
        (needs(mid) <= base ? lo : hi) = mid;
    }
    return lo;
}

void DistanceBias::resize(const MinMaxQuadtree& tree, const TerrainMapping& mapping) {
    leaf_texels_ = tree.leafTexels();
    map_ = {mapping.width, mapping.height};
    cells_ = tree.levels() ? tree.nodesPerSide(0) : glm::ivec2(0);
    corners_.resize(std::size_t(cells_.x + 1) * std::size_t(cells_.y + 1));
    per_side_.resize(std::size_t(tree.levels()));
    mins_.resize(std::size_t(tree.levels()));
    for (int level = 0; level < tree.levels(); ++level) {
        per_side_[std::size_t(level)] = tree.nodesPerSide(level);
        mins_[std::size_t(level)].resize(std::size_t(per_side_[std::size_t(level)].x) *
                                         std::size_t(per_side_[std::size_t(level)].y));
    }
}

void DistanceBias::clear(const MinMaxQuadtree& tree, const TerrainMapping& mapping) {
    resize(tree, mapping);
    std::fill(corners_.begin(), corners_.end(), 0.0f);
    buildMins();
}

void DistanceBias::build(const MinMaxQuadtree& tree, const GridErrors& errors, const TerrainMapping& mapping,
                         const LodSettings& lod, double error_scale, double max_error_px) {
    resize(tree, mapping);
    if (tree.levels() == 0) return;
    std::vector<double> ends, starts;
    lodRanges(tree, mapping, lod, ends, starts);
    const int top = int(ends.size()) - 1;
    const double per_m = error_scale / std::max(max_error_px, 1e-6);
    // A cell with no error at any level may look as far as the top level's nominal range.
    const float ceiling = float(ends.back());

    // G per cell, then per corner the smallest G of the (up to 4) cells around it: the
    // bilinear field inside a cell never exceeds its corners, so it stays below the cell's G.
    std::vector<float> cell(std::size_t(cells_.x) * std::size_t(cells_.y));
    for (int z = 0; z < cells_.y; ++z)
        for (int x = 0; x < cells_.x; ++x) {
            double g = ceiling;
            for (int level = 0; level < top; ++level) {
                double e = errors.at(level + 1, x, z);
                if (e > 0.0) g = std::min(g, starts[std::size_t(level)] - per_m * e);
            }
            cell[std::size_t(z) * std::size_t(cells_.x) + std::size_t(x)] = float(g);
        }
    const int cw = cells_.x + 1, ch = cells_.y + 1;
    for (int z = 0; z < ch; ++z)
        for (int x = 0; x < cw; ++x) {
            float g = ceiling;
            for (int cz = std::max(z - 1, 0); cz <= std::min(z, cells_.y - 1); ++cz)
                for (int cx = std::max(x - 1, 0); cx <= std::min(x, cells_.x - 1); ++cx)
                    g = std::min(g, cell[std::size_t(cz) * std::size_t(cells_.x) + std::size_t(cx)]);
            corners_[std::size_t(z) * std::size_t(cw) + std::size_t(x)] = std::max(g, 0.0f);
        }

    // The largest field below that with slope <= lambda: neighbouring corners differ by at
    // most lambda / sqrt(2) times their distance (Manhattan envelope, two raster sweeps), so
    // the bilinear field's gradient is at most lambda in any direction.
    const double lambda = std::max(lod.bias_slope, 0.0) / std::sqrt(2.0);
    auto cornerX = [&](int x) { return double(std::min<std::int64_t>(std::int64_t(x) * leaf_texels_, map_.x - 1)) * mapping.texelSizeX(); };
    auto cornerZ = [&](int z) { return double(std::min<std::int64_t>(std::int64_t(z) * leaf_texels_, map_.y - 1)) * mapping.texelSizeZ(); };
    auto at = [&](int x, int z) -> float& { return corners_[std::size_t(z) * std::size_t(cw) + std::size_t(x)]; };
    // Rounded down so float steps never exceed the slope.
    auto step = [&](double metres) { return std::nextafter(float(lambda * metres), 0.0f); };
    for (int z = 0; z < ch; ++z)
        for (int x = 0; x < cw; ++x) {
            if (x > 0) at(x, z) = std::min(at(x, z), at(x - 1, z) + step(cornerX(x) - cornerX(x - 1)));
            if (z > 0) at(x, z) = std::min(at(x, z), at(x, z - 1) + step(cornerZ(z) - cornerZ(z - 1)));
        }
    for (int z = ch - 1; z >= 0; --z)
        for (int x = cw - 1; x >= 0; --x) {
            if (x + 1 < cw) at(x, z) = std::min(at(x, z), at(x + 1, z) + step(cornerX(x + 1) - cornerX(x)));
            if (z + 1 < ch) at(x, z) = std::min(at(x, z), at(x, z + 1) + step(cornerZ(z + 1) - cornerZ(z)));
        }
    buildMins();
}

void DistanceBias::buildMins() {
    const int cw = cells_.x + 1;
    lowest_ = corners_.empty() ? 0.0f : *std::min_element(corners_.begin(), corners_.end());
    highest_ = corners_.empty() ? 0.0f : *std::max_element(corners_.begin(), corners_.end());
    for (std::size_t level = 0; level < mins_.size(); ++level) {
        glm::ivec2 count = per_side_[level];
        for (int z = 0; z < count.y; ++z)
            for (int x = 0; x < count.x; ++x) {
                float g = kInfinity;
                if (level == 0) {
                    for (int cz = z; cz <= z + 1; ++cz)
                        for (int cx = x; cx <= x + 1; ++cx)
                            g = std::min(g, corners_[std::size_t(cz) * std::size_t(cw) + std::size_t(cx)]);
                } else {
                    glm::ivec2 cc = per_side_[level - 1];
                    for (int cz = 2 * z; cz < std::min(2 * z + 2, cc.y); ++cz)
                        for (int cx = 2 * x; cx < std::min(2 * x + 2, cc.x); ++cx)
                            g = std::min(g, mins_[level - 1][std::size_t(cz) * std::size_t(cc.x) + std::size_t(cx)]);
                }
                mins_[level][std::size_t(z) * std::size_t(count.x) + std::size_t(x)] = g;
            }
    }
}

double DistanceBias::at(double tx, double tz) const {
    if (corners_.empty()) return 0.0;
    auto locate = [this](double t, int size, int cells, int& i) {
        t = std::clamp(t, 0.0, double(size - 1));
        i = std::min(int(t / double(leaf_texels_)), cells - 1);
        double t0 = double(i) * leaf_texels_, t1 = std::min(t0 + leaf_texels_, double(size - 1));
        return std::clamp((t - t0) / (t1 - t0), 0.0, 1.0);
    };
    int ix = 0, iz = 0;
    double fx = locate(tx, map_.x, cells_.x, ix), fz = locate(tz, map_.y, cells_.y, iz);
    const int cw = cells_.x + 1;
    auto c = [&](int x, int z) { return double(corners_[std::size_t(z) * std::size_t(cw) + std::size_t(x)]); };
    double top = c(ix, iz) + (c(ix + 1, iz) - c(ix, iz)) * fx;
    double bottom = c(ix, iz + 1) + (c(ix + 1, iz + 1) - c(ix, iz + 1)) * fx;
    return top + (bottom - top) * fz;
}

std::size_t DistanceBias::memoryBytes() const {
    std::size_t bytes = corners_.capacity() * sizeof(float) + per_side_.capacity() * sizeof(glm::ivec2);
    for (const std::vector<float>& level : mins_) bytes += level.capacity() * sizeof(float);
    return bytes;
}

}  // namespace vista
