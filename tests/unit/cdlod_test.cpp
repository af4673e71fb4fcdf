// CDLOD: quadtree bounds against brute force, frustum planes against the camera's projection,
// and selection invariants over many random cameras: exact cover of the visible map, level
// steps of at most one between neighbours, and morphed shared edges that coincide (no cracks).
#include "renderer/camera.h"
#include "terrain/cdlod.h"
#include "terrain/lod_error.h"
#include "terrain/terrain.h"  // casterDecimation

#include <doctest/doctest.h>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <random>

using namespace vista;

namespace {

double uniform(std::mt19937& rng, double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }

// Smooth waves plus noise (smooth) or white noise, in [0, 1]-ish.
Heightmap randomMap(int w, int h, std::uint32_t seed, bool smooth) {
    std::mt19937 rng(seed);
    Heightmap m{w, h, std::vector<float>(std::size_t(w) * std::size_t(h))};
    double fx[3], fz[3], ph[3];
    for (int i = 0; i < 3; ++i) fx[i] = uniform(rng, 0.02, 0.2), fz[i] = uniform(rng, 0.02, 0.2), ph[i] = uniform(rng, 0, 6.3);
    for (int z = 0; z < h; ++z)
        for (int x = 0; x < w; ++x) {
            double v = uniform(rng, 0.0, 1.0);
            if (smooth) {
                v = 0.5 + 0.05 * (v - 0.5);
                for (int i = 0; i < 3; ++i) v += 0.15 * std::sin(fx[i] * x + fz[i] * z + ph[i]);
            }
            m.samples[std::size_t(z) * std::size_t(w) + std::size_t(x)] = float(v);
        }
    return m;
}

struct TestTerrain {
    Heightmap map;
    TerrainMapping mapping;
    MinMaxQuadtree tree;
    TestTerrain(int w, int h, int leaf, double size_m, double scale_m, std::uint32_t seed)
        : map(randomMap(w, h, seed, true)), mapping{size_m, scale_m, -20.0, w, h}, tree(map, mapping, leaf) {}
    double half() const { return mapping.size_m * 0.5; }
};

Frustum frustumFor(const ViewParams& v) { return frustumFromViewProj(glm::dmat4(viewMatrices(v).view_proj)); }

ViewParams randomView(std::mt19937& rng, double half) {
    ViewParams v;
    double y = rng() % 4 == 0 ? uniform(rng, 500, 3000) : uniform(rng, -30, 400);
    v.position = {uniform(rng, -1.5, 1.5) * half, y, uniform(rng, -1.5, 1.5) * half};
    v.yaw_deg = uniform(rng, -180, 180);
    v.pitch_deg = uniform(rng, -89, 30);
    v.fov_deg = uniform(rng, 20, 110);
    v.width = 1280;
    v.height = 720;
    return v;
}

LodSettings randomLod(std::mt19937& rng) {
    const double ratios[] = {1.5, 2.0, 2.5, 3.0}, morphs[] = {0.0, 0.3, 0.7, 0.95};
    const int levels[] = {0, 0, 2, 3};
    LodSettings lod;
    lod.base_range_m = uniform(rng, 10, 400);
    lod.range_ratio = ratios[rng() % 4];
    lod.morph_start = morphs[rng() % 4];
    lod.levels = levels[rng() % 4];
    return lod;
}

// A selected area in whole texels [x0, x1] x [z0, z1] (clamped to the map).
struct Rect {
    int x0, z0, x1, z1;
};

int texelIndex(double world, double half, double texel, int& bad) {
    double t = (world + half) / texel;
    double r = std::round(t);
    bad += std::abs(t - r) > 1e-6;
    return int(r);
}

Rect texelRect(const SelectedNode& n, const TestTerrain& t, const glm::dvec3& cam, int& bad) {
    double tx = t.mapping.texelSizeX(), tz = t.mapping.texelSizeZ();
    return {texelIndex(n.min_rel.x + cam.x, t.half(), tx, bad), texelIndex(n.min_rel.z + cam.z, t.half(), tz, bad),
            texelIndex(n.max_rel.x + cam.x, t.half(), tx, bad), texelIndex(n.max_rel.z + cam.z, t.half(), tz, bad)};
}

// Morphed x/z of node n's grid vertices on the texel segment at `fixed` (along x when
// vertical, else along z) between lo and hi.
std::vector<glm::dvec2> edgeVertices(const SelectedNode& n, const Rect& r, const Selection& sel, const TestTerrain& t,
                                     const glm::dvec3& cam, int grid, bool vertical, int fixed, int lo, int hi,
                                     std::vector<double>* ks = nullptr, const DistanceBias* bias = nullptr) {
    double step = double(t.tree.leafTexels() << n.level) / double(grid);  // texels
    int quads = grid >> (n.level - n.node_level);
    std::vector<glm::dvec2> out;
    int g_fixed = int(std::lround((fixed - (vertical ? r.x0 : r.z0)) / step));
    for (int g = 0; g <= quads; ++g) {
        double k = 0;
        glm::dvec2 p = vertical ? morphVertex(n, sel, t.mapping, t.map, cam, grid, g_fixed, g, &k, bias)
                                : morphVertex(n, sel, t.mapping, t.map, cam, grid, g, g_fixed, &k, bias);
        // Keep the vertices that land on the shared stretch, after morphing and clamping to
        // the map (a vertex past the map's edge lands on it).
        double along = vertical ? (p.y + t.half()) / t.mapping.texelSizeZ() : (p.x + t.half()) / t.mapping.texelSizeX();
        if (along < lo - 1e-6 || along > hi + 1e-6) continue;
        out.push_back(p);
        if (ks) ks->push_back(k);
    }
    return out;
}

// Every point of a coincides with a point of b (within tol).
bool covered(const std::vector<glm::dvec2>& a, const std::vector<glm::dvec2>& b, double tol) {
    for (const glm::dvec2& p : a)
        if (std::none_of(b.begin(), b.end(), [&](const glm::dvec2& q) { return glm::length(p - q) <= tol; })) return false;
    return true;
}

struct Report {
    int nodes = 0, bad_texels = 0, overlaps = 0, gaps = 0, out_of_range = 0, culled_drawn = 0;
    int pairs = 0, fine_coarse_pairs = 0, level_jumps = 0, cracks = 0;
};

// All selection invariants for one camera, with an optional distance bias (its node
// distances are box distance + the node's smallest bias; the top level has no outer range).
Report checkSelection(const TestTerrain& t, const ViewParams& v, const LodSettings& lod, int grid,
                      const Selection* given = nullptr, const DistanceBias* bias = nullptr) {
    Frustum frustum = frustumFor(v);
    Selection own;
    if (!given) selectNodes(t.tree, t.mapping, lod, v.position, frustum, own, bias);
    const Selection& sel = given ? *given : own;
    const glm::dvec3 cam = v.position;
    Report rep;
    rep.nodes = int(sel.nodes.size());

    // Ranges: a whole node or quadrant lies within its level's range and beyond the finer one.
    for (const SelectedNode& n : sel.nodes) {
        glm::dvec3 p = glm::clamp(glm::dvec3(0.0), n.min_rel, n.max_rel);
        double d = glm::length(p) + (bias ? double(bias->minAt(n.node_level, n.x, n.z)) : 0.0);
        double r = sel.ranges[std::size_t(n.level)];
        if (n.node_level == n.level && n.level + 1 < int(sel.ranges.size())) rep.out_of_range += d > r;
        if (n.level > 0) rep.out_of_range += d <= sel.ranges[std::size_t(n.level - 1)];
        for (const glm::dvec4& pl : frustum) {
            glm::dvec3 c(pl.x >= 0 ? n.max_rel.x : n.min_rel.x, pl.y >= 0 ? n.max_rel.y : n.min_rel.y,
                         pl.z >= 0 ? n.max_rel.z : n.min_rel.z);
            rep.culled_drawn += glm::dot(glm::dvec3(pl), c) + pl.w < 0;
        }
    }

    // Rasterise the areas at texel resolution (their edges are texel lines).
    const int cw = t.map.width - 1, ch = t.map.height - 1;
    std::vector<int> owner(std::size_t(cw) * std::size_t(ch), -1);
    std::vector<Rect> rects;
    for (std::size_t i = 0; i < sel.nodes.size(); ++i) {
        Rect r = texelRect(sel.nodes[i], t, cam, rep.bad_texels);
        rects.push_back(r);
        for (int z = r.z0; z < r.z1; ++z)
            for (int x = r.x0; x < r.x1; ++x) {
                int& o = owner[std::size_t(z) * std::size_t(cw) + std::size_t(x)];
                rep.overlaps += o >= 0;
                o = int(i);
            }
    }
    // A texel column (x/z square, leaf min/max in y) that reaches inside the top range and is
    // not wholly outside any frustum plane must be drawn: its ancestors all pass both tests.
    const double top = bias ? 1e300 : sel.ranges.back() - 1e-6;
    const double tx = t.mapping.texelSizeX(), tz = t.mapping.texelSizeZ();
    for (int z = 0; z < ch; ++z)
        for (int x = 0; x < cw; ++x) {
            if (owner[std::size_t(z) * std::size_t(cw) + std::size_t(x)] >= 0) continue;
            glm::vec2 mm = t.tree.minMax(0, x / t.tree.leafTexels(), z / t.tree.leafTexels());
            glm::dvec3 lo = glm::dvec3(x * tx - t.half(), mm.x, z * tz - t.half()) - cam;
            glm::dvec3 hi = glm::dvec3((x + 1) * tx - t.half(), mm.y, (z + 1) * tz - t.half()) - cam;
            glm::dvec3 p = glm::clamp(glm::dvec3(0.0), lo, hi);
            bool visible = glm::dot(p, p) <= top * top;
            for (const glm::dvec4& pl : frustum) {
                glm::dvec3 c(pl.x >= 0 ? hi.x : lo.x, pl.y >= 0 ? hi.y : lo.y, pl.z >= 0 ? hi.z : lo.z);
                visible = visible && glm::dot(glm::dvec3(pl), c) + pl.w > 1e-6;
            }
            rep.gaps += visible;
        }

    // Neighbours: areas sharing an edge of positive length.
    const double tol = 1e-9 * t.mapping.size_m;
    for (std::size_t i = 0; i < rects.size(); ++i)
        for (std::size_t j = i + 1; j < rects.size(); ++j) {
            const Rect &a = rects[i], &b = rects[j];
            bool vertical = (a.x1 == b.x0 || b.x1 == a.x0) && std::min(a.z1, b.z1) > std::max(a.z0, b.z0);
            bool horizontal = (a.z1 == b.z0 || b.z1 == a.z0) && std::min(a.x1, b.x1) > std::max(a.x0, b.x0);
            if (!vertical && !horizontal) continue;
            ++rep.pairs;
            const SelectedNode &na = sel.nodes[i], &nb = sel.nodes[j];
            rep.level_jumps += std::abs(na.level - nb.level) > 1;
            rep.fine_coarse_pairs += na.level != nb.level;
            int fixed = vertical ? (a.x1 == b.x0 ? a.x1 : a.x0) : (a.z1 == b.z0 ? a.z1 : a.z0);
            int lo = vertical ? std::max(a.z0, b.z0) : std::max(a.x0, b.x0);
            int hi = vertical ? std::min(a.z1, b.z1) : std::min(a.x1, b.x1);
            auto ea = edgeVertices(na, a, sel, t, cam, grid, vertical, fixed, lo, hi, nullptr, bias);
            auto eb = edgeVertices(nb, b, sel, t, cam, grid, vertical, fixed, lo, hi, nullptr, bias);
            rep.cracks += !covered(ea, eb, tol) || !covered(eb, ea, tol);
        }
    return rep;
}

void requireClean(const Report& r) {
    CHECK(r.bad_texels == 0);
    CHECK(r.overlaps == 0);
    CHECK(r.gaps == 0);
    CHECK(r.out_of_range == 0);
    CHECK(r.culled_drawn == 0);
    CHECK(r.level_jumps == 0);
    CHECK(r.cracks == 0);
}

}  // namespace

TEST_CASE("cdlod: quadtree min/max equals brute force over each node's texels") {
    const int sizes[][2] = {{2, 2}, {37, 23}, {65, 65}, {129, 97}, {3, 50}};
    const int leaves[] = {1, 3, 8, 16, 64};
    std::uint32_t seed = 1;
    for (auto [w, h] : sizes)
        for (int leaf : leaves) {
            CAPTURE(w);
            CAPTURE(h);
            CAPTURE(leaf);
            Heightmap map = randomMap(w, h, seed++, false);
            double scale = seed % 2 ? 600.0 : -3.5;  // a negative scale swaps min and max
            TerrainMapping mapping{1000.0, scale, 12.5, w, h};
            MinMaxQuadtree tree(map, mapping, leaf);
            REQUIRE(tree.levels() >= 1);
            CHECK(tree.nodesPerSide(tree.levels() - 1) == glm::ivec2(1));
            if (tree.levels() > 1) CHECK(tree.nodesPerSide(tree.levels() - 2) != glm::ivec2(1));
            std::size_t node_bytes = 0;
            int mismatches = 0;
            for (int level = 0; level < tree.levels(); ++level) {
                double span = 0;
                int n = leaf << level;
                glm::ivec2 count = tree.nodesPerSide(level);
                CHECK(count == glm::ivec2((w - 1 + n - 1) / n, (h - 1 + n - 1) / n));
                node_bytes += std::size_t(count.x) * std::size_t(count.y) * sizeof(glm::vec2);
                for (int z = 0; z < count.y; ++z)
                    for (int x = 0; x < count.x; ++x) {
                        double lo = 1e300, hi = -1e300;
                        for (int tz = z * n; tz <= std::min((z + 1) * n, h - 1); ++tz)
                            for (int tx = x * n; tx <= std::min((x + 1) * n, w - 1); ++tx) {
                                double m = mapping.height_offset_m + scale * double(map.at(tx, tz));
                                lo = std::min(lo, m), hi = std::max(hi, m);
                            }
                        glm::vec2 mm = tree.minMax(level, x, z);
                        double slack = 1e-6 * std::max(1.0, std::abs(lo) + std::abs(hi));
                        mismatches += !(mm.x <= lo && mm.x >= lo - slack && mm.y >= hi && mm.y <= hi + slack);
                        span = std::max(span, hi - lo);
                    }
                CHECK(tree.heightSpan(level) >= span);
                CHECK(tree.heightSpan(level) == doctest::Approx(span).epsilon(1e-6));
            }
            CHECK(mismatches == 0);
            CHECK(tree.memoryBytes() >= node_bytes);
        }
}

TEST_CASE("cdlod: frustum planes of the reversed-Z infinite projection") {
    std::mt19937 rng(7);
    for (int i = 0; i < 200; ++i) {
        ViewParams v = randomView(rng, 1000.0);
        v.near_m = uniform(rng, 0.05, 2.0);
        ViewMatrices m = viewMatrices(v);
        Frustum f = frustumFromViewProj(glm::dmat4(m.view_proj));
        for (const glm::dvec4& p : f) {
            double len = glm::length(glm::dvec3(p));
            CHECK((std::abs(len - 1.0) < 1e-9 || p == glm::dvec4(0, 0, 0, 1)));
        }
        CHECK(f[5] == glm::dvec4(0, 0, 0, 1));  // the far plane is at infinity
        auto inside = [&f](const glm::dvec3& p) {
            return std::all_of(f.begin(), f.end(), [&](const glm::dvec4& pl) { return glm::dot(glm::dvec3(pl), p) + pl.w >= 0; });
        };
        double ty = std::tan(glm::radians(v.fov_deg) * 0.5), tx = ty * double(v.width) / double(v.height);
        // Camera space (u, v in units of the half-extent at that depth) to camera-relative world.
        auto point = [&](double u, double w, double depth) { return m.right * (u * tx * depth) + m.up * (w * ty * depth) + m.forward * depth; };
        for (int j = 0; j < 20; ++j) {
            double depth = v.near_m * std::exp(uniform(rng, 0.1, 15.0));
            CHECK(inside(point(uniform(rng, -0.95, 0.95), uniform(rng, -0.95, 0.95), depth)));
            double out = uniform(rng, 1.05, 3.0) * (rng() % 2 ? 1 : -1);
            CHECK_FALSE(inside(point(out, uniform(rng, -0.9, 0.9), depth)));
            CHECK_FALSE(inside(point(uniform(rng, -0.9, 0.9), out, depth)));
            CHECK_FALSE(inside(point(0.0, 0.0, -depth)));                              // behind
            CHECK_FALSE(inside(point(0.1, 0.1, v.near_m * uniform(rng, 0.01, 0.95))));  // before the near plane
        }
    }
}

TEST_CASE("cdlod: ranges and morph constants respect the node-size bound") {
    TestTerrain t(129, 97, 8, 2048.0, 300.0, 3);
    auto box = [&t](int k, bool side) {  // D_k (diagonal) or E_k (longer side with height)
        double ex = std::min(8 << k, 128) * t.mapping.texelSizeX(), ez = std::min(8 << k, 96) * t.mapping.texelSizeZ();
        double h = t.tree.heightSpan(k);
        return side ? std::hypot(std::max(ex, ez), h) : std::sqrt(ex * ex + ez * ez + h * h);
    };
    std::mt19937 rng(11);
    for (int i = 0; i < 100; ++i) {
        LodSettings lod = randomLod(rng);
        if (i % 10 == 0) lod.base_range_m = 1e5;  // large enough: used as given
        Selection sel;
        selectNodes(t.tree, t.mapping, lod, {0, 500, 0}, frustumFor(ViewParams{}), sel);
        int n = lod.levels > 0 ? std::min(lod.levels, t.tree.levels()) : t.tree.levels();
        REQUIRE(int(sel.ranges.size()) == n);
        REQUIRE(int(sel.morph_consts.size()) == n);
        CHECK(sel.ranges[0] >= lod.base_range_m);
        if (lod.base_range_m == 1e5) CHECK(sel.ranges[0] == 1e5);
        for (int k = 0; k < n; ++k) {
            double prev = k ? sel.ranges[std::size_t(k - 1)] : 0.0, end = sel.ranges[std::size_t(k)];
            glm::dvec2 c = sel.morph_consts[std::size_t(k)];
            if (k == n - 1) {  // the top level never morphs
                CHECK(c == glm::dvec2(1.0, 0.0));
                CHECK(end / std::max(prev, 1e-300) >= (k ? lod.range_ratio * (1 - 1e-12) : 0.0));
                continue;
            }
            double start = end - 1.0 / c.y;
            CHECK(c.x / c.y == doctest::Approx(end));
            CHECK(start >= prev + lod.morph_start * (end - prev) - 1e-6 * end);
            CHECK(start < end);
            if (k == 0) continue;
            CHECK(end / prev == doctest::Approx(lod.range_ratio));
            CHECK(end - prev >= box(k - 1, false) / std::max(lod.morph_start, 0.5) * (1 - 1e-12));
            if (k <= n - 2) CHECK(end - prev >= box(k, true) * (1 - 1e-12));
            CHECK(start >= prev + box(k - 1, false) * (1 - 1e-12));
            if (lod.morph_start >= 0.5) CHECK(start == doctest::Approx(prev + lod.morph_start * (end - prev)));
        }
    }
}

TEST_CASE("cdlod: selection covers the visible map exactly once") {
    TestTerrain terrains[] = {TestTerrain(129, 97, 8, 2048.0, 300.0, 3), TestTerrain(257, 257, 16, 4096.0, 500.0, 4),
                              TestTerrain(37, 23, 4, 500.0, 80.0, 5)};
    const int grids[] = {8, 32, 4};
    std::mt19937 rng(21);
    for (int ti = 0; ti < 3; ++ti) {
        const TestTerrain& t = terrains[ti];
        for (int i = 0; i < 60; ++i) {
            ViewParams v = randomView(rng, t.half());
            LodSettings lod = randomLod(rng);
            CAPTURE(ti);
            CAPTURE(i);
            requireClean(checkSelection(t, v, lod, grids[ti]));
        }
        // High above, looking straight down, wide: every texel exactly once.
        ViewParams v;
        v.position = {0.0, t.mapping.size_m * 2.0, 0.0};
        v.pitch_deg = -90.0;
        v.fov_deg = 100.0;
        LodSettings lod;
        lod.base_range_m = t.mapping.size_m;
        Selection sel;
        selectNodes(t.tree, t.mapping, lod, v.position, frustumFor(v), sel);
        Report r = checkSelection(t, v, lod, grids[ti], &sel);
        requireClean(r);
        double area = 0;
        for (const SelectedNode& n : sel.nodes) area += (n.max_rel.x - n.min_rel.x) * (n.max_rel.z - n.min_rel.z);
        CHECK(area == doctest::Approx(t.mapping.size_m * t.mapping.size_m));
    }
}

TEST_CASE("cdlod: neighbours differ by at most one level and their morphed edges coincide") {
    TestTerrain t(257, 257, 8, 4096.0, 400.0, 8);
    std::mt19937 rng(5);
    int fine_coarse = 0;
    for (int i = 0; i < 80; ++i) {
        ViewParams v = randomView(rng, t.half());
        v.position.y = uniform(rng, 0, 300);  // low: many levels in view
        LodSettings lod = randomLod(rng);
        lod.levels = 0;
        CAPTURE(i);
        Report r = checkSelection(t, v, lod, i % 2 ? 8 : 16);
        requireClean(r);
        fine_coarse += r.fine_coarse_pairs;
    }
    CHECK(fine_coarse > 100);  // the crack check saw plenty of level changes
}

TEST_CASE("cdlod: a camera path sweeps the morph factor over 0..1 without cracks") {
    TestTerrain t(257, 257, 8, 4096.0, 400.0, 9);
    LodSettings lod;
    lod.base_range_m = 200.0;
    int bins[6] = {};  // k == 0, (0, .25), [.25, .5), [.5, .75), [.75, 1), k == 1
    for (int i = 0; i < 40; ++i) {
        ViewParams v;
        v.position = {-1800.0 + 90.0 * i, 350.0 - 8.0 * i, 300.0 - 20.0 * i};
        v.yaw_deg = 30.0 + 3.0 * i;
        v.pitch_deg = -20.0;
        v.fov_deg = 70.0;
        v.width = 16, v.height = 9;
        Selection sel;
        selectNodes(t.tree, t.mapping, lod, v.position, frustumFor(v), sel);
        CAPTURE(i);
        requireClean(checkSelection(t, v, lod, 8, &sel));
        for (const SelectedNode& n : sel.nodes)
            for (int g = 0; g <= (8 >> (n.level - n.node_level)); ++g) {
                double k = 0;
                morphVertex(n, sel, t.mapping, t.map, v.position, 8, g, g, &k);
                ++bins[k == 0 ? 0 : k == 1 ? 5 : 1 + std::min(3, int(k * 4))];
            }
    }
    for (int b : bins) CHECK(b > 0);
}

TEST_CASE("cdlod: morphVertex follows the shader formula") {
    // Flat map at height 0 so distances are known exactly.
    Heightmap flat{65, 65, std::vector<float>(65 * 65, 0.0f)};
    TerrainMapping mapping{640.0, 100.0, 0.0, 65, 65};  // 10 m texels
    Selection sel;
    sel.ranges = {100, 200};
    sel.morph_consts = {{100.0 / 30.0, 1.0 / 30.0}, {200.0 / 30.0, 1.0 / 30.0}};  // morph over [70, 100] and [170, 200]
    const glm::dvec3 cam(0.0, 0.0, 0.0);
    auto node = [&](int level, int node_level, int x, int z) {
        SelectedNode n;
        n.level = level;
        n.node_level = node_level;
        n.x = x, n.z = z;
        n.size_m = glm::dvec2(80.0 * (1 << node_level));  // leaf 8 texels
        n.origin_rel = glm::dvec2(x, z) * n.size_m - 320.0;
        n.min_rel = glm::dvec3(n.origin_rel.x, 0, n.origin_rel.y);
        n.max_rel = n.min_rel + glm::dvec3(n.size_m.x, 0, n.size_m.y);
        return n;
    };

    SUBCASE("exact morph factors from the camera height") {
        SelectedNode n = node(0, 0, 4, 4);  // origin at world (0, 0)
        for (double k : {0.0, 0.25, 0.5, 0.75, 1.0}) {
            glm::dvec3 above(30.0, 100.0 - 30.0 * (1.0 - k), 0.0);  // straight above vertex (3, 0)
            SelectedNode moved = n;
            moved.origin_rel -= glm::dvec2(above.x, above.z);
            double got = -1;
            glm::dvec2 p = morphVertex(moved, sel, mapping, flat, above, 8, 3, 0, &got);
            CHECK(got == doctest::Approx(k).epsilon(1e-12));
            CHECK(p.x == doctest::Approx(30.0 - 10.0 * k));  // odd x slides toward x = 2
            CHECK(p.y == doctest::Approx(0.0));
            glm::dvec2 even = morphVertex(moved, sel, mapping, flat, above, 8, 2, 0);
            CHECK(even.x == doctest::Approx(20.0));  // even vertices never move
        }
    }

    SUBCASE("a fine/coarse edge coincides only when fine k = 1 and coarse k = 0") {
        // Fine node (level 0) at world x in [0, 80]; coarse quadrant (level 1, area of a level-0
        // node) to its right. Sweep the camera away along -x so both edges' k go 0 -> 1.
        SelectedNode fine = node(0, 0, 4, 4), coarse = node(1, 0, 5, 4);
        int matches = 0;
        for (double k : {0.0, 0.25, 0.5, 0.75, 1.0}) {
            for (double kc : {0.0, 0.5}) {
                // Distances to the shared edge (world x = 80) set each level's k independently.
                Selection s = sel;
                s.morph_consts[0] = {1.0 - k, 0.0};
                s.morph_consts[1] = {1.0 - kc, 0.0};
                std::vector<glm::dvec2> ef, ec;
                for (int g = 0; g <= 8; ++g) ef.push_back(morphVertex(fine, s, mapping, flat, cam, 8, 8, g));
                for (int g = 0; g <= 4; ++g) ec.push_back(morphVertex(coarse, s, mapping, flat, cam, 8, 0, g));
                bool ok = covered(ef, ec, 1e-9) && covered(ec, ef, 1e-9);
                CHECK(ok == (k == 1.0 && kc == 0.0));
                matches += ok;
            }
        }
        CHECK(matches == 1);
    }

    SUBCASE("same-level neighbours coincide at every k") {
        // A whole level-1 node (x, z in [0, 160]) and, right of it, a level-1 quadrant
        // (x in [160, 240], z in [80, 160]) whose siblings are finer.
        SelectedNode whole = node(1, 1, 2, 2), quadrant = node(1, 0, 6, 5);
        for (double k : {0.0, 0.25, 0.5, 0.75, 1.0}) {
            Selection s = sel;
            s.morph_consts[1] = {1.0 - k, 0.0};
            std::vector<glm::dvec2> ew, eq;
            for (int g = 4; g <= 8; ++g) ew.push_back(morphVertex(whole, s, mapping, flat, cam, 8, 8, g));
            for (int g = 0; g <= 4; ++g) eq.push_back(morphVertex(quadrant, s, mapping, flat, cam, 8, 0, g));
            CHECK(covered(ew, eq, 1e-9));
            CHECK(covered(eq, ew, 1e-9));
        }
    }

    SUBCASE("vertices past the map's edge are clamped to it") {
        SelectedNode n = node(0, 0, 7, 7);  // covers [240, 320] x [240, 320]: the map ends at 320
        n.size_m = glm::dvec2(160.0);       // a node reaching past the edge
        glm::dvec2 p = morphVertex(n, sel, mapping, flat, cam, 8, 8, 8);
        CHECK(p == glm::dvec2(320.0));
    }
}

TEST_CASE("cdlod: reusing a selection does not allocate") {
    TestTerrain t(257, 257, 8, 4096.0, 400.0, 12);
    ViewParams v;
    v.position = {100.0, 150.0, 200.0};
    v.pitch_deg = -15.0;
    LodSettings lod;
    Frustum f = frustumFor(v);
    Selection sel;
    selectNodes(t.tree, t.mapping, lod, v.position, f, sel);
    REQUIRE(!sel.nodes.empty());
    const SelectedNode* data = sel.nodes.data();
    std::size_t capacity = sel.nodes.capacity(), ranges = sel.ranges.capacity(), consts = sel.morph_consts.capacity();
    std::size_t count = sel.nodes.size();
    selectNodes(t.tree, t.mapping, lod, v.position, f, sel);
    CHECK(sel.nodes.size() == count);
    CHECK(sel.nodes.data() == data);
    CHECK(sel.nodes.capacity() == capacity);
    CHECK(sel.ranges.capacity() == ranges);
    CHECK(sel.morph_consts.capacity() == consts);
    v.position.y = 2000.0;  // fewer nodes
    selectNodes(t.tree, t.mapping, lod, v.position, frustumFor(v), sel);
    CHECK(sel.nodes.data() == data);
}

TEST_CASE("cdlod: the top level reaches the whole map, however few levels the tree has") {
    // A 5x5 map 100 km across has one level: without this the map would end at base_range_m.
    TestTerrain t(5, 5, 4, 100000.0, 50.0, 9);
    LodSettings lod;
    Selection sel;
    ViewParams v;
    v.position = {0.0, 5000.0, 0.0};
    v.pitch_deg = -89.0;
    v.fov_deg = 170.0;
    selectNodes(t.tree, t.mapping, lod, v.position, frustumFor(v), sel);
    REQUIRE(sel.ranges.size() == 1);
    CHECK(sel.ranges[0] > 70000.0);  // the farthest corner is ~70.9 km away
    CHECK(sel.nodes.size() == 1);
}

TEST_CASE("cdlod: with an error-metric distance bias, neighbours stay within one level and edges coincide") {
    // Rough and smooth maps, so the bias varies from 0 to its ceiling across the map.
    std::mt19937 rng(17);
    int fine_coarse = 0, biased_nodes = 0;
    for (int mi = 0; mi < 2; ++mi) {
        TestTerrain t(257, 193, 8, 4096.0, 400.0, 30 + mi);
        if (mi == 1)  // white noise on one half: rough cells next to smooth ones
            for (int z = 0; z < 193; ++z)
                for (int x = 128; x < 257; ++x) t.map.samples[std::size_t(z) * 257 + std::size_t(x)] = float(uniform(rng, 0, 1));
        t.tree = MinMaxQuadtree(t.map, t.mapping, 8);
        GridErrors errors(t.map, t.mapping, 8, t.tree.levels());
        for (int i = 0; i < 40; ++i) {
            ViewParams v = randomView(rng, t.half());
            v.position.y = uniform(rng, 0, 400);
            LodSettings lod = randomLod(rng);
            lod.levels = 0;
            lod.bias_slope = i % 4 == 0 ? 0.25 : i % 4 == 1 ? 1.0 : i % 4 == 2 ? 2.0 : 4.0;
            const double scale = screenErrorScale(v.fov_deg, 36), max_px = uniform(rng, 0.5, 4.0);
            lod.base_range_m = calibratedBaseRange(t.tree, errors, t.mapping, lod, scale, max_px);
            DistanceBias bias;
            bias.build(t.tree, errors, t.mapping, lod, scale, max_px);
            biased_nodes += bias.highest() > 0.0f;
            CAPTURE(mi);
            CAPTURE(i);
            Report r = checkSelection(t, v, lod, i % 2 ? 8 : 16, nullptr, &bias);
            requireClean(r);
            fine_coarse += r.fine_coarse_pairs;
        }
    }
    CHECK(fine_coarse > 100);
    CHECK(biased_nodes > 40);
}

TEST_CASE("cdlod: a selection reused for a shadow frustum keeps exactly the nodes that touch it") {
    TestTerrain t(257, 257, 8, 4096.0, 400.0, 12);
    ViewParams v;
    v.position = {100.0, 150.0, 200.0};
    v.pitch_deg = -15.0;
    Selection main, shadow;
    selectNodes(t.tree, t.mapping, LodSettings{}, v.position, frustumFor(v), main);
    REQUIRE(main.nodes.size() > 10);
    // A narrower frustum looking the same way: a strict subset.
    ViewParams narrow = v;
    narrow.fov_deg = 20.0;
    Frustum f = frustumFor(narrow);
    cullSelection(main, f, shadow);
    CHECK(shadow.ranges == main.ranges);
    CHECK(shadow.morph_consts == main.morph_consts);
    CHECK(shadow.nodes.size() < main.nodes.size());
    CHECK(!shadow.nodes.empty());
    std::size_t kept = 0;
    for (const SelectedNode& n : main.nodes) {
        bool inside = true;
        for (const glm::dvec4& p : f) {
            glm::dvec3 c(p.x >= 0 ? n.max_rel.x : n.min_rel.x, p.y >= 0 ? n.max_rel.y : n.min_rel.y,
                         p.z >= 0 ? n.max_rel.z : n.min_rel.z);
            inside = inside && glm::dot(glm::dvec3(p), c) + p.w >= 0.0;
        }
        if (!inside) continue;
        REQUIRE(kept < shadow.nodes.size());
        CHECK(shadow.nodes[kept].x == n.x);
        CHECK(shadow.nodes[kept].z == n.z);
        CHECK(shadow.nodes[kept].level == n.level);
        ++kept;
    }
    CHECK(kept == shadow.nodes.size());
    // Reuse allocates nothing.
    const SelectedNode* data = shadow.nodes.data();
    cullSelection(main, f, shadow);
    CHECK(shadow.nodes.data() == data);
}

TEST_CASE("cdlod: shadow casters drawn coarser all reach one common step, which their neighbours share") {
    // Quadrants of 16 x 16 quads at steps 2, 4, 8, 16 and 64 m.
    const std::vector<float> steps{2.0f, 4.0f, 8.0f, 16.0f, 64.0f, 2.0f, 4.0f};
    // Off, or a texel finer than twice the finest step: every quadrant at full detail.
    CHECK(casterDecimation(steps, 16, 0.0) == std::vector<int>(steps.size(), 0));
    CHECK(casterDecimation(steps, 16, 3.9) == std::vector<int>(steps.size(), 0));
    // Up to 9 m: the common step is 8 m, so 2 m quadrants take every 4th vertex, 4 m every 2nd,
    // and 8 m and coarser draw as they are.
    CHECK(casterDecimation(steps, 16, 9.0) == std::vector<int>{2, 1, 0, 0, 0, 2, 1});
    CHECK(casterDecimation(steps, 16, 8.0) == std::vector<int>{2, 1, 0, 0, 0, 2, 1});
    // The common step cannot pass 16 quads of the finest (one quad per quadrant): 32 m here.
    CHECK(casterDecimation(steps, 16, 1000.0) == std::vector<int>{4, 3, 2, 1, 0, 4, 3});
    // Every 2^k must divide the quads per side: 12 quads allow k up to 2.
    CHECK(casterDecimation(steps, 12, 1000.0) == std::vector<int>{2, 1, 0, 0, 0, 2, 1});
    CHECK(casterDecimation(steps, 1, 1000.0) == std::vector<int>(steps.size(), 0));
    // Whatever the bound, each decimated quadrant lands on the common step and no coarser one
    // changes: neighbours at the common step share their edge vertices.
    for (double bound : {2.0, 5.0, 17.0, 40.0, 100.0}) {
        CAPTURE(bound);
        const std::vector<int> k = casterDecimation(steps, 16, bound);
        float common = 0.0f;
        for (std::size_t i = 0; i < steps.size(); ++i) {
            const float step = steps[i] * float(1 << k[i]);
            if (k[i] > 0) {
                if (common == 0.0f) common = step;
                CHECK(step == common);
                CHECK(step <= bound);
            }
        }
        for (std::size_t i = 0; i < steps.size(); ++i)
            if (common > 0.0f && steps[i] >= common) CHECK(k[i] == 0);
    }
    CHECK(casterDecimation({}, 16, 10.0).empty());
}
