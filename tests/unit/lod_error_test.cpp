// Screen-space error control (terrain/lod_error.h): grid errors against a brute-force
// triangle search, the bias field's slope and bound, and the distance-only calibration.
#include "terrain/lod_error.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>

using namespace vista;

namespace {

Heightmap noiseMap(int w, int h, std::uint32_t seed) {
    std::mt19937 rng(seed);
    Heightmap m{w, h, std::vector<float>(std::size_t(w) * std::size_t(h))};
    for (float& v : m.samples) v = float(std::uniform_real_distribution<double>(0.0, 1.0)(rng));
    return m;
}

// Height of the triangle mesh with vertices every `spacing` texels (last clamped to the edge)
// at texel (x, z): finds the triangle by barycentric coordinates, trying both of the quad's.
double meshHeight(const Heightmap& m, int spacing, int x, int z) {
    auto clampEdge = [](int v, int size) { return std::min(v, size - 1); };
    int x0 = std::min(x / spacing, (m.width - 2) / spacing) * spacing, z0 = std::min(z / spacing, (m.height - 2) / spacing) * spacing;
    int x1 = clampEdge(x0 + spacing, m.width), z1 = clampEdge(z0 + spacing, m.height);
    struct V {
        double x, z, h;
    };
    V a{double(x0), double(z0), m.at(x0, z0)}, b{double(x1), double(z0), m.at(x1, z0)}, c{double(x0), double(z1), m.at(x0, z1)},
        d{double(x1), double(z1), m.at(x1, z1)};
    for (const auto& tri : {std::array<V, 3>{a, c, b}, std::array<V, 3>{b, c, d}}) {
        double det = (tri[1].z - tri[2].z) * (tri[0].x - tri[2].x) + (tri[2].x - tri[1].x) * (tri[0].z - tri[2].z);
        double l0 = ((tri[1].z - tri[2].z) * (x - tri[2].x) + (tri[2].x - tri[1].x) * (z - tri[2].z)) / det;
        double l1 = ((tri[2].z - tri[0].z) * (x - tri[2].x) + (tri[0].x - tri[2].x) * (z - tri[2].z)) / det;
        double l2 = 1.0 - l0 - l1;
        if (l0 >= -1e-9 && l1 >= -1e-9 && l2 >= -1e-9) return l0 * tri[0].h + l1 * tri[1].h + l2 * tri[2].h;
    }
    FAIL("texel outside its quad");
    return 0.0;
}

}  // namespace

TEST_CASE("lod error: grid errors per leaf cell equal a brute-force triangle search") {
    for (auto [w, h] : {std::pair{33, 33}, std::pair{45, 29}, std::pair{2, 2}}) {
        Heightmap m = noiseMap(w, h, std::uint32_t(w * 7 + h));
        TerrainMapping mapping{100.0, 250.0, -3.0, w, h};
        const int leaf = 4;
        MinMaxQuadtree tree(m, mapping, leaf);
        GridErrors errors(m, mapping, leaf, tree.levels());
        REQUIRE(errors.levels() == tree.levels());
        REQUIRE(errors.cells() == tree.nodesPerSide(0));
        for (int level = 0; level < errors.levels(); ++level) {
            double worst = 0.0;
            for (int cz = 0; cz < errors.cells().y; ++cz)
                for (int cx = 0; cx < errors.cells().x; ++cx) {
                    double e = 0.0;
                    for (int z = cz * leaf; z <= std::min((cz + 1) * leaf, h - 1); ++z)
                        for (int x = cx * leaf; x <= std::min((cx + 1) * leaf, w - 1); ++x)
                            e = std::max(e, std::abs(double(m.at(x, z)) - meshHeight(m, 1 << level, x, z)) * 250.0);
                    CAPTURE(level);
                    CHECK(errors.at(level, cx, cz) == doctest::Approx(e).epsilon(1e-5));
                    worst = std::max(worst, e);
                }
            CHECK(errors.maxAt(level) == doctest::Approx(worst).epsilon(1e-5));
        }
        CHECK(errors.maxAt(0) == 0.0f);
    }
}

TEST_CASE("lod error: a flat map has no error and the bias reaches its ceiling") {
    Heightmap flat{65, 65, std::vector<float>(65 * 65, 0.3f)};
    TerrainMapping mapping{640.0, 100.0, 0.0, 65, 65};
    MinMaxQuadtree tree(flat, mapping, 8);
    GridErrors errors(flat, mapping, 8, tree.levels());
    for (int level = 0; level < errors.levels(); ++level) CHECK(errors.maxAt(level) == 0.0f);
    LodSettings lod;
    lod.bias_slope = 1.0;
    DistanceBias bias;
    bias.build(tree, errors, mapping, lod, 600.0, 1.0);
    CHECK(bias.lowest() > 0.0f);
    CHECK(bias.lowest() == bias.highest());
}

TEST_CASE("lod error: the bias stays under each cell's bound with its slope limited, and node minima hold") {
    Heightmap m = noiseMap(129, 97, 5);
    for (int z = 0; z < 97; ++z)  // smooth on the left, rough on the right
        for (int x = 0; x < 64; ++x) m.samples[std::size_t(z) * 129 + std::size_t(x)] = 0.5f + 0.001f * float(x % 3);
    TerrainMapping mapping{1280.0, 200.0, 0.0, 129, 97};
    MinMaxQuadtree tree(m, mapping, 8);
    GridErrors errors(m, mapping, 8, tree.levels());
    std::mt19937 rng(3);
    for (double slope : {0.25, 1.0, 3.0}) {
        LodSettings lod;
        lod.bias_slope = slope;
        const double scale = 300.0, max_px = 1.0;
        lod.base_range_m = calibratedBaseRange(tree, errors, mapping, lod, scale, max_px);
        DistanceBias bias;
        bias.build(tree, errors, mapping, lod, scale, max_px);
        CHECK(bias.lowest() >= 0.0f);
        CHECK(bias.highest() > bias.lowest());
        // Below G in every cell: at its corners (the bilinear maximum).
        std::vector<double> ends, starts;
        lodRanges(tree, mapping, lod, ends, starts);
        const glm::ivec2 cells = errors.cells();
        for (int cz = 0; cz < cells.y; ++cz)
            for (int cx = 0; cx < cells.x; ++cx) {
                double g = 1e300;
                for (int level = 0; level + 1 < int(ends.size()); ++level)
                    if (errors.at(level + 1, cx, cz) > 0)
                        g = std::min(g, starts[std::size_t(level)] - scale * errors.at(level + 1, cx, cz) / max_px);
                for (int dz = 0; dz <= 1; ++dz)
                    for (int dx = 0; dx <= 1; ++dx) {
                        double v = bias.corners()[std::size_t(cz + dz) * std::size_t(cells.x + 1) + std::size_t(cx + dx)];
                        CHECK(v <= std::max(g, 0.0) + 1e-3);
                    }
            }
        // Slope: random pairs of points (texel coordinates; texels 10 m in x, 13.3 m in z).
        std::uniform_real_distribution<double> tx(0.0, 128.0), tz(0.0, 96.0);
        double steepest = 0.0;
        for (int i = 0; i < 20000; ++i) {
            double ax = tx(rng), az = tz(rng), bx = ax + (tx(rng) - 64.0) * 0.05, bz = az + (tz(rng) - 48.0) * 0.05;
            bx = std::clamp(bx, 0.0, 128.0), bz = std::clamp(bz, 0.0, 96.0);
            double dist = std::hypot((bx - ax) * mapping.texelSizeX(), (bz - az) * mapping.texelSizeZ());
            if (dist < 1e-3) continue;
            steepest = std::max(steepest, std::abs(bias.at(ax, az) - bias.at(bx, bz)) / dist);
        }
        CAPTURE(slope);
        CHECK(steepest <= slope * (1.0 + 1e-4));
        CHECK(steepest > slope * 0.3);  // the limit is what shapes the field here
        // Node minima are lower bounds of the field over the node.
        for (int level = 0; level < tree.levels(); ++level) {
            glm::ivec2 count = tree.nodesPerSide(level);
            for (int i = 0; i < 200; ++i) {
                int x = int(rng() % std::uint32_t(count.x)), z = int(rng() % std::uint32_t(count.y));
                double n = double(8 << level);
                double px = std::min((x + std::uniform_real_distribution<double>(0, 1)(rng)) * n, 128.0);
                double pz = std::min((z + std::uniform_real_distribution<double>(0, 1)(rng)) * n, 96.0);
                CHECK(bias.minAt(level, x, z) <= bias.at(px, pz) + 1e-4);
            }
        }
    }
}

TEST_CASE("lod error: the calibrated base range is the smallest meeting the bound") {
    Heightmap m = noiseMap(129, 129, 8);
    TerrainMapping mapping{1280.0, 200.0, 0.0, 129, 129};
    MinMaxQuadtree tree(m, mapping, 8);
    GridErrors errors(m, mapping, 8, tree.levels());
    LodSettings lod;
    lod.base_range_m = 10.0;
    const double scale = 500.0, max_px = 2.0;
    double base = calibratedBaseRange(tree, errors, mapping, lod, scale, max_px);
    auto meets = [&](double b) {
        LodSettings l = lod;
        l.base_range_m = b;
        std::vector<double> ends, starts;
        lodRanges(tree, mapping, l, ends, starts);
        for (std::size_t k = 0; k + 1 < ends.size(); ++k)
            if (starts[k] < scale * errors.maxAt(int(k) + 1) / max_px * (1 - 1e-9)) return false;
        return true;
    };
    CHECK(meets(base));
    CHECK(!meets(base * 0.99));
    lod.base_range_m = base * 3.0;  // a larger setting is kept
    CHECK(calibratedBaseRange(tree, errors, mapping, lod, scale, max_px) == base * 3.0);
}

TEST_CASE("lod error: screen error scale is pixels per radian on the view axis") {
    CHECK(screenErrorScale(90.0, 720) == doctest::Approx(360.0));
    CHECK(screenErrorScale(60.0, 360) == doctest::Approx(180.0 / std::tan(30.0 * 3.14159265358979323846 / 180.0)));
}

TEST_CASE("lod error: the bias slope is lowered until the crack bounds fit in the calibrated ranges") {
    Heightmap m = noiseMap(129, 129, 9);
    TerrainMapping mapping{1280.0, 200.0, 0.0, 129, 129};
    MinMaxQuadtree tree(m, mapping, 8);
    LodSettings lod;
    auto crackBase = [&](double slope) {
        LodSettings l = lod;
        l.base_range_m = 1e-3;
        l.bias_slope = slope;
        std::vector<double> ends, starts;
        lodRanges(tree, mapping, l, ends, starts);
        return ends[0];
    };
    CHECK(usableBiasSlope(tree, mapping, lod, crackBase(2.0) * 1.01, 2.0) == 2.0);
    CHECK(usableBiasSlope(tree, mapping, lod, crackBase(0.0) * 0.99, 2.0) == 0.0);
    double slope = usableBiasSlope(tree, mapping, lod, crackBase(1.0), 2.0);
    CHECK(slope == doctest::Approx(1.0).epsilon(1e-3));
    CHECK(crackBase(slope) <= crackBase(1.0) * (1 + 1e-9));
}
