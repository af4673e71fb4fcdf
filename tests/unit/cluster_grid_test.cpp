// Clustered shading's grid: 002's exponential slices against a hand-computed example, slice
// lookup consistent with slice bounds, conservative CPU light assignment against brute force at
// random points, and projected sphere bounds that hold the projected sphere.
#include "renderer/lighting/cluster_grid.h"
#include "renderer/random.h"

#include <doctest/doctest.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

using namespace vista;

TEST_CASE("cluster grid: slices follow near_k = near_0 (1 + 2 tan(theta) / S_y)^k") {
    // 1280x720 with 16 px tiles: S_y = 45; fov 60 deg: tan 30 deg = 0.57735;
    // ratio = 1 + 2 * 0.57735 / 45 = 1.0256600; near_10 = 0.1 * 1.02566^10 = 0.1288351;
    // slices to reach 4000 m: ln(40000) / ln(1.02566) = 418.24 -> 419.
    CHECK(cubicSliceRatio(60.0, 45) == doctest::Approx(1.0256600119639834).epsilon(1e-12));
    CHECK(slicesToReach(0.1, 4000.0, 1.0256600119639834) == 419);
    ClusterGridParams p;
    p.width_px = 1280;
    p.height_px = 720;
    p.tile_px = 16;
    p.fov_y_deg = 60.0;
    p.near0_m = 0.1;
    p.far_m = 4000.0;
    p.max_slices = 1000;
    ClusterGrid g = makeClusterGrid(p);
    CHECK(g.tiles_x == 80);
    CHECK(g.tiles_y == 45);
    CHECK(g.slices == 419);
    CHECK(g.sliceNear(0) == doctest::Approx(0.1));
    CHECK(g.sliceNear(10) == doctest::Approx(0.1288351114268814).epsilon(1e-10));
    CHECK(g.sliceOf(0.1288) == 9);
    CHECK(g.sliceOf(0.1289) == 10);
    CHECK(g.sliceOf(0.05) == 0);  // in front of near_0: slice 0
    CHECK(g.sliceOf(1e9) == g.slices - 1);
    CHECK(g.sliceOf(std::nan("")) == 0);
    // Capped: the ratio grows so the same far distance is reached, (4000 / 0.1)^(1/64).
    p.max_slices = 64;
    ClusterGrid capped = makeClusterGrid(p);
    CHECK(capped.slices == 64);
    CHECK(capped.sliceNear(1) == doctest::Approx(0.11800684174712993).epsilon(1e-10));
    CHECK(capped.sliceNear(64) == doctest::Approx(4000.0).epsilon(1e-10));
    // A fixed count.
    p.slices = 16;
    CHECK(makeClusterGrid(p).slices == 16);
    // A partial last tile: 100 px with 32 px tiles is 4 tiles.
    p.width_px = 100;
    p.tile_px = 32;
    ClusterGrid partial = makeClusterGrid(p);
    CHECK(partial.tiles_x == 4);
    CHECK(partial.tileSlopes(3, 0).y == doctest::Approx(partial.tan_half_fov_y * partial.aspect));
}

TEST_CASE("cluster grid: slice lookup is monotone and agrees with the slice bounds") {
    ClusterGridParams p;
    p.width_px = 640;
    p.height_px = 360;
    p.near0_m = 0.5;
    p.far_m = 2000.0;
    ClusterGrid g = makeClusterGrid(p);
    int prev = 0;
    for (double depth = 0.0; depth < 5000.0; depth = depth * 1.01 + 0.001) {
        int k = g.sliceOf(depth);
        CHECK(k >= prev);
        prev = k;
        glm::dvec2 range = g.sliceRange(k);
        CHECK(depth >= range.x * (1.0 - 1e-12));
        CHECK(depth < range.y * (1.0 + 1e-12));
    }
    CHECK(prev == g.slices - 1);
}

namespace {

struct Camera {
    ClusterGrid grid;
    // A view-space point through pixel (px, py) at a view depth.
    glm::dvec3 point(double px, double py, double depth) const {
        double x = (2.0 * px / grid.width_px - 1.0) * grid.tan_half_fov_y * grid.aspect;
        double y = (2.0 * py / grid.height_px - 1.0) * grid.tan_half_fov_y;
        return {x * depth, y * depth, -depth};
    }
};

}  // namespace

TEST_CASE("cluster grid: light assignment is conservative against brute force at random points") {
    Rng rng(11);
    for (int view = 0; view < 6; ++view) {
        ClusterGridParams p;
        p.width_px = 200 + int(rng.below(400));
        p.height_px = 100 + int(rng.below(300));
        p.tile_px = view % 2 ? 32 : 16;
        p.fov_y_deg = rng.uniform(30.0, 100.0);
        p.near0_m = 0.1;
        p.far_m = 500.0;
        p.slices = view < 3 ? 0 : 24;
        Camera cam{makeClusterGrid(p)};
        std::vector<Sphere> lights(300);
        for (std::size_t i = 0; i < lights.size(); ++i) {
            double depth = rng.uniform(-20.0, 300.0);
            lights[i].center = cam.point(rng.uniform(-100.0, p.width_px + 100.0), rng.uniform(-100.0, p.height_px + 100.0), depth);
            if (depth < 0.0) lights[i].center.z = -depth;  // behind the camera
            lights[i].radius = i % 50 == 0 ? 0.0 : rng.uniform(0.2, 30.0);
        }
        lights[1].center = {0.0, 0.0, 0.0};  // at the camera
        ClusterLists lists;
        assignLights(cam.grid, lights, 100000, lists);
        CHECK(lists.overflow == 0);
        std::uint64_t listed = 0, needed = 0;
        for (int s = 0; s < 4000; ++s) {
            double px = rng.uniform(0.0, double(p.width_px)), py = rng.uniform(0.0, double(p.height_px));
            double depth = std::exp(rng.uniform(std::log(0.1), std::log(400.0)));
            glm::dvec3 q = cam.point(px, py, depth);
            int c = cam.grid.index(std::min(int(px) / p.tile_px, cam.grid.tiles_x - 1),
                                   std::min(int(py) / p.tile_px, cam.grid.tiles_y - 1), cam.grid.sliceOf(depth));
            auto begin = lists.indices.begin() + lists.offset[std::size_t(c)];
            auto end = begin + lists.count[std::size_t(c)];
            listed += lists.count[std::size_t(c)];
            for (std::size_t i = 0; i < lights.size(); ++i) {
                if (glm::length(q - lights[i].center) >= lights[i].radius) continue;
                ++needed;
                CHECK_MESSAGE(std::binary_search(begin, end, std::uint32_t(i)), "light ", i, " missing at depth ", depth);
            }
        }
        CHECK(needed > 0);
        CHECK(listed < std::uint64_t(4000) * lights.size() / 4);  // culling does cull
    }
}

TEST_CASE("cluster grid: a full list keeps the lowest light indices and counts the overflow") {
    ClusterGridParams p;
    p.width_px = p.height_px = 64;
    p.slices = 4;
    ClusterGrid g = makeClusterGrid(p);
    std::vector<Sphere> lights(10, Sphere{{0.0, 0.0, -5.0}, 1000.0});
    ClusterLists lists;
    assignLights(g, lights, 3, lists);
    CHECK(lists.pairs == std::uint64_t(g.clusterCount()) * 10);
    CHECK(lists.overflow == std::uint64_t(g.clusterCount()) * 7);
    CHECK(lists.count[0] == 3);
    CHECK(lists.indices[lists.offset[5]] == 0);
    CHECK(lists.indices[lists.offset[5] + 2] == 2);
}

TEST_CASE("cluster grid: the projected sphere rectangle bounds the projected sphere") {
    Rng rng(5);
    const double tan_half = std::tan(30.0 * 3.14159265358979 / 180.0), aspect = 16.0 / 9.0, near_m = 0.1;
    int bounded = 0;
    for (int i = 0; i < 2000; ++i) {
        Sphere s{{rng.uniform(-50, 50), rng.uniform(-50, 50), rng.uniform(-100, 20)}, rng.uniform(0.01, 30)};
        if (i % 100 == 0) s.center = {0.0, 0.0, -s.radius * 0.5};  // the eye inside
        glm::dvec4 b;
        bool visible = projectedSphereBounds(s, tan_half, aspect, near_m, b);
        if (visible && (b.x > -1.0 || b.y < 1.0)) ++bounded;
        for (int j = 0; j < 200; ++j) {
            glm::dvec3 dir = glm::normalize(glm::dvec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)) + 1e-9);
            glm::dvec3 q = s.center + dir * s.radius * rng.uniform(0.0, 1.0);
            double depth = -q.z;
            if (depth < near_m) continue;
            double x = q.x / (depth * tan_half * aspect), y = q.y / (depth * tan_half);
            if (std::abs(x) > 1.0 || std::abs(y) > 1.0) continue;  // off screen
            REQUIRE(visible);
            CHECK(x >= b.x - 1e-9);
            CHECK(x <= b.y + 1e-9);
            CHECK(y >= b.z - 1e-9);
            CHECK(y <= b.w + 1e-9);
        }
    }
    CHECK(bounded > 200);  // most rectangles are smaller than the screen
    glm::dvec4 b;
    CHECK(!projectedSphereBounds(Sphere{{0.0, 0.0, 10.0}, 1.0}, tan_half, aspect, near_m, b));  // behind
    // A small sphere straight ahead: a tight square around the centre.
    REQUIRE(projectedSphereBounds(Sphere{{0.0, 0.0, -10.0}, 1.0}, tan_half, aspect, near_m, b));
    double half = std::tan(std::asin(0.1)) / tan_half;
    CHECK(b.w == doctest::Approx(half));
    CHECK(b.z == doctest::Approx(-half));
}
