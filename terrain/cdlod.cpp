// CDLOD (Strugar 2009): min/max quadtree build, frustum planes, LOD selection and the CPU
// replica of the vertex morph. Everything is double precision; outputs are camera-relative.
//
// Why the range bound in cdlod.h holds. Selection puts a level-L area C next to a finer area F
// only when C's box is beyond range[L-1] (C was not refined), while F lies inside a level-(L-1)
// node G that was within range[L-1] (G was selected whole or refined). G's side facing C lies
// on C's side (both are unions of level-(L-1) cells), and heights on a shared edge are samples
// of that edge, inside both boxes' y ranges. So a vertex v on the shared edge has
//     range[L-1] < |v - camera| <= |q - camera| + |v - q| <= range[L-1] + D_{L-1}
// with q G's point nearest the camera. The left side puts F's edge vertices past F's morph end
// (k = 1: snapped onto level L's grid); the right side keeps C's edge vertices before C's morph
// start, which is never below range[L-1] + D_{L-1} (k = 0: C's own grid). Both edges are then
// the same level-L vertex row: no crack, no T-junction. s_k >= D_{k-1} / max(m, 1/2) keeps that
// start inside the span (the user's start when m >= 1/2; else a morph region >= s_k / 2).
// If F were two or more levels finer, the level-(L-1) node G holding it was refined, so within
// range[L-2], and it touches C: the point p of C's side level with q (same along-edge coordinate,
// height clamped into C's y range) has |p - q| <= E_{L-1}, so range[L-1] < range[L-2] + E_{L-1},
// which s_{L-1} >= E_{L-1} rules out.
// With a distance bias g of slope <= lambda (terrain/lod_error.h) the distance is
// d_eff = |p - camera| + g(p), a (1 + lambda)-Lipschitz function, and a node's distance is its
// box distance plus its smallest g (a lower bound of d_eff over it). The argument above goes
// through with D and E replaced by (1 + lambda) D: the box-nearest point and the point of
// smallest g may differ, but both lie in G, so any v in G has d_eff(v) <= node distance +
// (1 + lambda) D_{L-1}.
#include "terrain/cdlod.h"

#include "terrain/lod_error.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace vista {
namespace {

int ceilDiv(std::int64_t a, std::int64_t b) { return int((a + b - 1) / b); }

// Float bounds that still contain the double heights they round (outward rounding).
float floatBelow(double v) {
    float f = float(v);
    return double(f) > v ? std::nextafter(f, -std::numeric_limits<float>::infinity()) : f;
}
float floatAbove(double v) {
    float f = float(v);
    return double(f) < v ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
}

// GL_LINEAR on texel centres with clamp-to-edge, at continuous texel coordinates.
double bilinear(const Heightmap& map, double tx, double tz) {
    tx = std::clamp(tx, 0.0, double(map.width - 1));
    tz = std::clamp(tz, 0.0, double(map.height - 1));
    int x0 = std::min(int(tx), map.width - 2), z0 = std::min(int(tz), map.height - 2);
    double fx = tx - x0, fz = tz - z0;
    double top = map.at(x0, z0) + (map.at(x0 + 1, z0) - map.at(x0, z0)) * fx;
    double bottom = map.at(x0, z0 + 1) + (map.at(x0 + 1, z0 + 1) - map.at(x0, z0 + 1)) * fx;
    return top + (bottom - top) * fz;
}

struct Box {
    glm::dvec3 lo, hi;  // camera-relative
};

double distance2(const Box& b) {  // from the camera (the origin)
    glm::dvec3 p = glm::clamp(glm::dvec3(0.0), b.lo, b.hi);
    return glm::dot(p, p);
}

// Conservative: false only when the box is wholly outside one plane.
bool intersects(const Frustum& f, const Box& b) {
    for (const glm::dvec4& p : f) {
        glm::dvec3 corner(p.x >= 0 ? b.hi.x : b.lo.x, p.y >= 0 ? b.hi.y : b.lo.y, p.z >= 0 ? b.hi.z : b.lo.z);
        if (glm::dot(glm::dvec3(p), corner) + p.w < 0.0) return false;
    }
    return true;
}

// A union of frusta: the box meets at least one.
bool intersects(std::span<const Frustum> frusta, const Box& b) {
    return std::ranges::any_of(frusta, [&](const Frustum& f) { return intersects(f, b); });
}

// One selection pass: Strugar's LODSelect with quadrants as separate entries.
struct Selector {
    const MinMaxQuadtree& tree;
    const TerrainMapping& mapping;
    std::span<const Frustum> frustum;
    glm::dvec3 camera;
    const std::vector<double>& ranges;
    const DistanceBias* bias;
    int top;
    std::vector<SelectedNode>& out;

    std::int64_t texels(int level) const { return std::int64_t(tree.leafTexels()) << level; }

    Box box(int level, int x, int z) const {
        std::int64_t n = texels(level);
        double tx = mapping.texelSizeX(), tz = mapping.texelSizeZ();
        double half_x = mapping.sizeX() * 0.5, half_z = mapping.sizeZ() * 0.5;
        glm::vec2 mm = tree.minMax(level, x, z);
        Box b;
        b.lo = glm::dvec3(double(x * n) * tx - half_x, mm.x, double(z * n) * tz - half_z) - camera;
        b.hi = glm::dvec3(double(std::min<std::int64_t>((x + 1) * n, mapping.width - 1)) * tx - half_x, mm.y,
                          double(std::min<std::int64_t>((z + 1) * n, mapping.height - 1)) * tz - half_z) - camera;
        return b;
    }

    void add(int level, int node_level, int x, int z, const Box& b) {
        std::int64_t n = texels(node_level);
        SelectedNode s;
        s.level = level;
        s.node_level = node_level;
        s.x = x;
        s.z = z;
        s.min_rel = b.lo;
        s.max_rel = b.hi;
        s.origin_rel = glm::dvec2(b.lo.x, b.lo.z);
        s.size_m = glm::dvec2(double(n) * mapping.texelSizeX(), double(n) * mapping.texelSizeZ());
        out.push_back(s);
    }

    // False when the node is out of range[level]: its parent then draws the area.
    // The top level is never out of range: it covers what no finer level does.
    bool select(int level, int x, int z, const Box& b) {
        double d = std::sqrt(distance2(b)) + (bias ? double(bias->minAt(level, x, z)) : 0.0);
        if (level != top && d > ranges[std::size_t(level)]) return false;
        if (!intersects(frustum, b)) return true;  // handled: nothing visible
        if (level == 0 || d > ranges[std::size_t(level - 1)]) {
            add(level, level, x, z, b);
            return true;
        }
        glm::ivec2 count = tree.nodesPerSide(level - 1);
        for (int cz = 2 * z; cz < std::min(2 * z + 2, count.y); ++cz)
            for (int cx = 2 * x; cx < std::min(2 * x + 2, count.x); ++cx) {
                Box cb = box(level - 1, cx, cz);
                if (!select(level - 1, cx, cz, cb) && intersects(frustum, cb)) add(level, level - 1, cx, cz, cb);
            }
        return true;
    }
};

}  // namespace

MinMaxQuadtree::MinMaxQuadtree(const Heightmap& map, const TerrainMapping& mapping, int leaf_texels)
    : leaf_texels_(std::max(leaf_texels, 1)) {
    const int w = map.width, h = map.height;
    if (w < 2 || h < 2 || map.samples.size() < std::size_t(w) * std::size_t(h)) return;
    for (int level = 0;; ++level) {
        std::int64_t n = std::int64_t(leaf_texels_) << level;
        per_side_.push_back({ceilDiv(w - 1, n), ceilDiv(h - 1, n)});
        if (per_side_.back() == glm::ivec2(1)) break;
    }
    levels_.resize(per_side_.size());

    // Leaves from samples (each sample is read by at most 4 leaves), in sample units.
    const int n0 = leaf_texels_;
    glm::ivec2 c0 = per_side_[0];
    levels_[0].resize(std::size_t(c0.x) * std::size_t(c0.y));
    for (int z = 0; z < c0.y; ++z)
        for (int x = 0; x < c0.x; ++x) {
            glm::vec2 mm(std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity());
            for (int tz = z * n0; tz <= std::min((z + 1) * n0, h - 1); ++tz)
                for (int tx = x * n0; tx <= std::min((x + 1) * n0, w - 1); ++tx) {
                    float s = map.at(tx, tz);
                    mm = glm::vec2(std::min(mm.x, s), std::max(mm.y, s));
                }
            levels_[0][std::size_t(z) * std::size_t(c0.x) + std::size_t(x)] = mm;
        }
    buildParents();
    // Samples to metres (a negative scale swaps min and max) and the per-level spans.
    span_.resize(levels_.size());
    for (std::size_t level = 0; level < levels_.size(); ++level) {
        double span = 0.0;
        for (glm::vec2& mm : levels_[level]) {
            double a = mapping.height_offset_m + mapping.height_scale_m * double(mm.x);
            double b = mapping.height_offset_m + mapping.height_scale_m * double(mm.y);
            mm = glm::vec2(floatBelow(std::min(a, b)), floatAbove(std::max(a, b)));
            span = std::max(span, double(mm.y) - double(mm.x));
        }
        span_[level] = span;
    }
}

MinMaxQuadtree::MinMaxQuadtree(const TerrainMapping& mapping, int leaf_texels, std::vector<glm::vec2> leaves_m)
    : leaf_texels_(std::max(leaf_texels, 1)) {
    const int w = mapping.width, h = mapping.height;
    if (w < 2 || h < 2) return;
    for (int level = 0;; ++level) {
        std::int64_t n = std::int64_t(leaf_texels_) << level;
        per_side_.push_back({ceilDiv(w - 1, n), ceilDiv(h - 1, n)});
        if (per_side_.back() == glm::ivec2(1)) break;
    }
    if (leaves_m.size() != std::size_t(per_side_[0].x) * std::size_t(per_side_[0].y)) {
        per_side_.clear();
        return;
    }
    levels_.resize(per_side_.size());
    levels_[0] = std::move(leaves_m);
    buildParents();
    span_.resize(levels_.size());
    for (std::size_t level = 0; level < levels_.size(); ++level) {
        double span = 0.0;
        for (const glm::vec2& mm : levels_[level]) span = std::max(span, double(mm.y) - double(mm.x));
        span_[level] = span;
    }
}

void MinMaxQuadtree::buildParents() {
    // Parents from their (up to 4) children: the union of the children's texel ranges.
    for (std::size_t level = 1; level < levels_.size(); ++level) {
        glm::ivec2 c = per_side_[level], cc = per_side_[level - 1];
        const std::vector<glm::vec2>& child = levels_[level - 1];
        std::vector<glm::vec2>& node = levels_[level];
        node.resize(std::size_t(c.x) * std::size_t(c.y));
        for (int z = 0; z < c.y; ++z)
            for (int x = 0; x < c.x; ++x) {
                glm::vec2 mm = child[std::size_t(2 * z) * std::size_t(cc.x) + std::size_t(2 * x)];
                for (int cz = 2 * z; cz < std::min(2 * z + 2, cc.y); ++cz)
                    for (int cx = 2 * x; cx < std::min(2 * x + 2, cc.x); ++cx) {
                        glm::vec2 m = child[std::size_t(cz) * std::size_t(cc.x) + std::size_t(cx)];
                        mm = glm::vec2(std::min(mm.x, m.x), std::max(mm.y, m.y));
                    }
                node[std::size_t(z) * std::size_t(c.x) + std::size_t(x)] = mm;
            }
    }
}

glm::ivec2 MinMaxQuadtree::nodesPerSide(int level) const { return per_side_[std::size_t(level)]; }

glm::vec2 MinMaxQuadtree::minMax(int level, int x, int z) const {
    return levels_[std::size_t(level)][std::size_t(z) * std::size_t(per_side_[std::size_t(level)].x) + std::size_t(x)];
}

std::size_t MinMaxQuadtree::memoryBytes() const {
    std::size_t bytes = per_side_.capacity() * sizeof(glm::ivec2) + span_.capacity() * sizeof(double) +
                        levels_.capacity() * sizeof(std::vector<glm::vec2>);
    for (const std::vector<glm::vec2>& level : levels_) bytes += level.capacity() * sizeof(glm::vec2);
    return bytes;
}

void lodRanges(const MinMaxQuadtree& tree, const TerrainMapping& mapping, const LodSettings& lod,
               std::vector<double>& ends, std::vector<double>& starts) {
    ends.clear();
    starts.clear();
    if (tree.levels() == 0) return;
    const int levels = lod.levels > 0 ? std::min(lod.levels, tree.levels()) : tree.levels();
    const double ratio = std::max(lod.range_ratio, 1.01);
    const double m = std::clamp(lod.morph_start, 0.0, 0.99);
    const double lipschitz = 1.0 + std::max(lod.bias_slope, 0.0);

    // Raise the base range to the bound derived at the top of this file.
    auto bounds = [&](int k) {  // D_k, E_k (scaled by the distance's Lipschitz constant)
        std::int64_t n = std::int64_t(tree.leafTexels()) << k;
        double ex = double(std::min<std::int64_t>(n, mapping.width - 1)) * mapping.texelSizeX();
        double ez = double(std::min<std::int64_t>(n, mapping.height - 1)) * mapping.texelSizeZ();
        double h2 = tree.heightSpan(k) * tree.heightSpan(k);
        double diagonal = std::sqrt(ex * ex + ez * ez + h2);
        double side = lod.bias_slope > 0.0 ? diagonal : std::sqrt(std::max(ex * ex, ez * ez) + h2);
        return glm::dvec2(diagonal, side) * lipschitz;
    };
    double base = std::max(lod.base_range_m, 1e-3);
    for (int k = 1; k < levels; ++k) {
        double need = bounds(k - 1).x / std::max(m, 0.5);
        if (k <= levels - 2) need = std::max(need, bounds(k).y);
        base = std::max(base, need / (std::pow(ratio, k - 1) * (ratio - 1.0)));
    }
    double prev = 0.0;
    for (int level = 0; level < levels; ++level) {
        double end = base * std::pow(ratio, level);
        ends.push_back(end);
        starts.push_back(level == 0 ? m * end : prev + std::max(m * (end - prev), bounds(level - 1).x));
        prev = end;
    }
}

void selectNodes(const MinMaxQuadtree& tree, const TerrainMapping& mapping, const LodSettings& lod,
                 const glm::dvec3& camera, const Frustum& frustum, Selection& out, const DistanceBias* bias) {
    selectNodes(tree, mapping, lod, camera, std::span<const Frustum>(&frustum, 1), out, bias);
}

void selectNodes(const MinMaxQuadtree& tree, const TerrainMapping& mapping, const LodSettings& lod,
                 const glm::dvec3& camera, std::span<const Frustum> frustum, Selection& out, const DistanceBias* bias) {
    out.nodes.clear();
    out.morph_consts.clear();
    lodRanges(tree, mapping, lod, out.ranges, out.morph_starts);
    if (tree.levels() == 0) return;
    const int levels = int(out.ranges.size());

    // The top level has no coarser level to hand over to, so its range reaches the farthest
    // corner of the map: the whole map is always drawn, however few levels the tree has.
    double low = tree.minMax(levels - 1, 0, 0).x, high = low;
    glm::ivec2 top_count = tree.nodesPerSide(levels - 1);
    for (int z = 0; z < top_count.y; ++z)
        for (int x = 0; x < top_count.x; ++x) {
            glm::vec2 mm = tree.minMax(levels - 1, x, z);
            low = std::min(low, double(mm.x));
            high = std::max(high, double(mm.y));
        }
    glm::dvec3 far(std::abs(camera.x) + mapping.sizeX() * 0.5, std::max(std::abs(camera.y - low), std::abs(camera.y - high)),
                   std::abs(camera.z) + mapping.sizeZ() * 0.5);
    for (int level = 0; level < levels; ++level) {
        double& end = out.ranges[std::size_t(level)];
        double start = out.morph_starts[std::size_t(level)];
        if (level == levels - 1) end = std::max(end, glm::length(far) * 1.001);
        // The top level has no coarser grid to morph into: k stays 0 (c = (1, 0)).
        out.morph_consts.push_back(level == levels - 1 ? glm::dvec2(1.0, 0.0)
                                                       : glm::dvec2(end / (end - start), 1.0 / (end - start)));
    }

    const int top = levels - 1;
    Selector s{tree, mapping, frustum, camera, out.ranges, bias, top, out.nodes};
    glm::ivec2 count = tree.nodesPerSide(top);
    for (int z = 0; z < count.y; ++z)
        for (int x = 0; x < count.x; ++x) s.select(top, x, z, s.box(top, x, z));
}

void cullSelection(const Selection& from, const Frustum& frustum, Selection& out) {
    out.ranges = from.ranges;
    out.morph_starts = from.morph_starts;
    out.morph_consts = from.morph_consts;
    out.nodes.clear();
    for (const SelectedNode& n : from.nodes)
        if (intersects(frustum, Box{n.min_rel, n.max_rel})) out.nodes.push_back(n);
}

glm::dvec2 morphVertex(const SelectedNode& node, const Selection& sel, const TerrainMapping& mapping,
                       const Heightmap& map, const glm::dvec3& camera, int grid, int gx, int gz, double* morph_k,
                       const DistanceBias* bias) {
    glm::dvec2 step = node.size_m * double(1 << (node.level - node.node_level)) / double(grid);
    glm::dvec2 g(gx, gz);
    glm::dvec2 rel = node.origin_rel + g * step;
    glm::dvec2 map_min = -0.5 * glm::dvec2(mapping.sizeX(), mapping.sizeZ()) - glm::dvec2(camera.x, camera.z);
    // Distance from the unmorphed vertex with its sampled height, as the shader has it.
    double h = mapping.height_offset_m - camera.y +
               mapping.height_scale_m * bilinear(map, (rel.x - map_min.x) / mapping.texelSizeX(),
                                                 (rel.y - map_min.y) / mapping.texelSizeZ());
    double d = glm::length(glm::dvec3(rel.x, h, rel.y));
    if (bias) d += bias->at((rel.x - map_min.x) / mapping.texelSizeX(), (rel.y - map_min.y) / mapping.texelSizeZ());
    glm::dvec2 c = sel.morph_consts[std::size_t(node.level)];
    double k = 1.0 - std::clamp(c.x - d * c.y, 0.0, 1.0);
    if (morph_k) *morph_k = k;
    // Odd vertices slide onto their even neighbour below. A vertex at or past the map's far
    // edge keeps its place on that axis, so the border never pulls inward.
    glm::dvec2 map_max = map_min + glm::dvec2(mapping.sizeX(), mapping.sizeZ());
    glm::dvec2 inside(rel.x < map_max.x ? 1.0 : 0.0, rel.y < map_max.y ? 1.0 : 0.0);
    g -= glm::fract(g * 0.5) * 2.0 * k * inside;
    rel = glm::clamp(node.origin_rel + g * step, map_min, map_max);
    return rel + glm::dvec2(camera.x, camera.z);
}

}  // namespace vista
