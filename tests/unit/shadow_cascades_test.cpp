// Sun shadow cascades without GL: PSSM splits against the closed form, slice spheres that
// hold their slice, cascades snapped to whole texels (also 10,000 km out), degenerate views
// and sun directions, and the caster selection that keeps the view's LOD.
#include "renderer/camera.h"
#include "renderer/shadows/cascades.h"
#include "renderer/shadows/sun_shadows.h"
#include "terrain/cdlod.h"
#include "terrain_helpers.h"

#include <doctest/doctest.h>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

using namespace vista;

namespace {

bool finite(const glm::dmat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

CascadeView viewOf(const ViewParams& v) {
    ViewMatrices m = viewMatrices(v);
    CascadeView cv;
    cv.position = v.position;
    cv.forward = m.forward;
    cv.up = m.up;
    cv.tan_half_fov_y = std::tan(glm::radians(v.fov_deg) * 0.5);
    cv.aspect = double(v.width) / double(v.height);
    return cv;
}

glm::dvec3 sunAt(double azimuth_deg, double elevation_deg) {
    double a = glm::radians(azimuth_deg), e = glm::radians(elevation_deg);
    return {std::sin(a) * std::cos(e), std::sin(e), -std::cos(a) * std::cos(e)};
}

}  // namespace

TEST_CASE("shadows: PSSM splits follow the closed form") {
    for (double lambda : {0.0, 0.5, 0.9, 1.0})
        for (int n : {1, 2, 3, 4, 5}) {
            const double near = 0.1, far = 500.0;
            auto d = pssmSplits(near, far, n, lambda);
            CHECK(d[0] == near);
            CHECK(d[std::size_t(n)] == far);
            for (int i = 1; i < n; ++i) {
                double t = double(i) / n;
                double expected = lambda * near * std::exp(t * std::log(far / near)) + (1 - lambda) * (near + (far - near) * t);
                CHECK(d[std::size_t(i)] == doctest::Approx(expected).epsilon(1e-12));
                CHECK(d[std::size_t(i)] > d[std::size_t(i - 1)]);
            }
        }
    // lambda = 1: each split is the geometric mean of its neighbours.
    auto d = pssmSplits(1.0, 10000.0, 4, 1.0);
    CHECK(d[2] == doctest::Approx(std::sqrt(d[1] * d[3])).epsilon(1e-12));
    CHECK(d[1] == doctest::Approx(10.0).epsilon(1e-12));
}

TEST_CASE("shadows: the slice sphere holds the slice's corners and touches the farthest") {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int k = 0; k < 200; ++k) {
        double near = 0.1 + u(rng) * 100, far = near * (1.01 + u(rng) * 50);
        double tan_y = std::tan(glm::radians(10.0 + u(rng) * 100)), aspect = 0.3 + u(rng) * 3;
        SliceSphere s = sliceSphere(near, far, tan_y, aspect);
        double worst = 0.0;
        for (double z : {near, far})
            for (double sx : {-1.0, 1.0})
                for (double sy : {-1.0, 1.0}) {
                    glm::dvec3 p(sx * z * tan_y * aspect, sy * z * tan_y, z);
                    worst = std::max(worst, glm::length(p - glm::dvec3(0, 0, s.center_depth)));
                }
        CHECK(worst <= s.radius * (1 + 1e-12));
        CHECK(worst >= s.radius * (1 - 1e-9));  // no larger than it must be for a centre on the axis
    }
}

TEST_CASE("shadows: stabilised cascades move by whole texels and keep their size while the camera moves and turns") {
    for (glm::dvec3 origin : {glm::dvec3(0.0), glm::dvec3(1e7, 300.0, -1e7)}) {  // and 10,000 km out
        const LightBasis light = lightBasis(sunAt(135.0, 25.0));
        ViewParams v{origin + glm::dvec3(0, 120, 0), 10.0, -15.0, 60.0, 0.1, 320, 180};
        ShadowCascade first = fitCascade(light, viewOf(v), 10.0, 60.0, 1024, true);
        std::mt19937 rng(3);
        std::uniform_real_distribution<double> step(-0.37, 0.37);
        for (int i = 0; i < 100; ++i) {
            v.position += glm::dvec3(step(rng), step(rng) * 0.2, step(rng));
            v.yaw_deg += step(rng) * 3.0;
            v.pitch_deg = std::clamp(v.pitch_deg + step(rng), -80.0, 80.0);
            ShadowCascade c = fitCascade(light, viewOf(v), 10.0, 60.0, 1024, true);
            CHECK(c.radius_m == first.radius_m);
            CHECK(c.texel_m == first.texel_m);
            // The centre's offset from the first one is a whole number of texels along each axis.
            glm::dvec3 delta = c.center_world - first.center_world;
            for (const glm::dvec3& axis : {light.right, light.up, light.dir}) {
                double texels = glm::dot(delta, axis) / c.texel_m;
                CHECK(std::abs(texels - std::round(texels)) < 1e-3);
            }
            // The matrix maps a fixed world point to the same texel fraction in every frame.
            glm::dvec3 world = origin + glm::dvec3(7.3, 2.1, -11.9);
            glm::dvec4 q = c.matrix * glm::dvec4(world - v.position, 1.0);
            glm::dvec4 q0 = first.matrix * glm::dvec4(world - (origin + glm::dvec3(0, 120, 0)), 1.0);
            double fx = (q.x - q0.x) * 0.5 * 1024, fy = (q.y - q0.y) * 0.5 * 1024;
            CHECK(std::abs(fx - std::round(fx)) < 1e-3);
            CHECK(std::abs(fy - std::round(fy)) < 1e-3);
        }
    }
}

TEST_CASE("shadows: unstabilised cascades change size with the view (what the bench compares against)") {
    const LightBasis light = lightBasis(sunAt(135.0, 25.0));
    ViewParams v{{0, 120, 0}, 10.0, -15.0, 60.0, 0.1, 320, 180};
    ShadowCascade a = fitCascade(light, viewOf(v), 10.0, 60.0, 1024, false);
    v.yaw_deg += 20.0;
    ShadowCascade b = fitCascade(light, viewOf(v), 10.0, 60.0, 1024, false);
    CHECK(a.radius_m != b.radius_m);
}

TEST_CASE("shadows: straight up and down views and any sun direction give finite, invertible cascades") {
    for (double pitch : {-90.0, -89.999, 0.0, 89.999, 90.0})
        for (double elevation : {90.0, 89.9999, 45.0, 2.0, 0.0001}) {
            const LightBasis light = lightBasis(sunAt(30.0, elevation));
            CHECK(glm::dot(light.right, light.up) == doctest::Approx(0.0).epsilon(1e-12));
            CHECK(glm::length(light.right) == doctest::Approx(1.0));
            CHECK(glm::dot(glm::cross(light.right, light.up), light.dir) == doctest::Approx(1.0));
            ViewParams v{{0, 50, 0}, 0.0, pitch, 60.0, 0.1, 64, 64};
            for (bool stable : {true, false}) {
                ShadowCascade c = fitCascade(light, viewOf(v), 0.1, 40.0, 512, stable);
                CHECK(finite(c.matrix));
                CHECK(c.radius_m > 0.0);
                CHECK(std::abs(glm::determinant(c.matrix)) > 1e-12);
            }
        }
}

TEST_CASE("shadows: the sun at or below the horizon casts no shadows") {
    ShadowSettings s;
    CHECK(sunCastsShadows(s, sunAt(0, 10)));
    CHECK_FALSE(sunCastsShadows(s, glm::dvec3(0, 0, -1)));  // exactly at the horizon
    CHECK_FALSE(sunCastsShadows(s, sunAt(0, -0.5)));
    CHECK_FALSE(sunCastsShadows(s, sunAt(0, -18)));
    s.min_sun_elevation_deg = 5.0f;
    CHECK_FALSE(sunCastsShadows(s, sunAt(0, 4)));
    CHECK(sunCastsShadows(s, sunAt(0, 6)));
    s.enabled = false;
    CHECK_FALSE(sunCastsShadows(s, sunAt(0, 60)));
}

TEST_CASE("shadows: cascade slices end at max_distance_m, then the far cascade") {
    ShadowSettings s;
    auto slices = cascadeSlices(s, 0.1);
    REQUIRE(slices.size() == 5);
    CHECK(slices[0].first == 0.1);
    CHECK(slices[3].second == doctest::Approx(500.0));
    CHECK(slices[4].first == slices[3].second);
    CHECK(slices[4].second == 5000.0);
    for (std::size_t i = 1; i < slices.size(); ++i) CHECK(slices[i].first == slices[i - 1].second);
    s.far_cascade = false;
    CHECK(cascadeSlices(s, 0.1).size() == 4);
}

TEST_CASE("shadows: caster planes keep a point above the box (towards the sun) and drop one below it") {
    const LightBasis light = lightBasis(sunAt(200.0, 30.0));
    ViewParams v{{5, 80, 9}, 0.0, -20.0, 60.0, 0.1, 160, 90};
    ShadowCascade c = fitCascade(light, viewOf(v), 1.0, 50.0, 512, true);
    auto planes = casterPlanes(light, c, v.position);
    auto inside = [&](const glm::dvec3& p) {
        for (const auto& pl : planes)
            if (glm::dot(glm::dvec3(pl), p) + pl.w < 0) return false;
        return true;
    };
    glm::dvec3 centre = c.center_world - v.position;
    CHECK(inside(centre));
    CHECK(inside(centre + light.dir * (c.radius_m * 100.0)));   // far towards the sun: may cast
    CHECK_FALSE(inside(centre - light.dir * (c.radius_m * 1.01)));  // below the box
    CHECK_FALSE(inside(centre + light.right * (c.radius_m * 1.01)));
    // With a reach towards the sun, casters beyond it are left out.
    planes = casterPlanes(light, c, v.position, 300.0);
    CHECK(inside(centre + light.dir * (c.radius_m + 299.0)));
    CHECK_FALSE(inside(centre + light.dir * (c.radius_m + 301.0)));
}

TEST_CASE("shadows: selecting with the caster frustum and culling by the view gives the view's own selection") {
    // A bumpy 257x257 map, random views and suns: same nodes, same levels.
    const test::BumpyQuadtree terrain(0.11, 0.07);
    const auto& [mapping, tree, lod] = terrain;
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int k = 0; k < 40; ++k) {
        const ViewParams v = test::randomView(rng, 4000, 300, 500);
        glm::dmat4 vp(viewMatrices(v).view_proj);
        Frustum view = frustumFromViewProj(vp);
        Selection own, wide, culled;
        selectNodes(tree, mapping, lod, v.position, view, own);
        selectNodes(tree, mapping, lod, v.position, extrudeTowardsSun(view, sunAt(u(rng) * 360, 3 + u(rng) * 80)), wide);
        cullSelection(wide, view, culled);
        CHECK(wide.nodes.size() >= own.nodes.size());
        REQUIRE(culled.nodes.size() == own.nodes.size());
        for (std::size_t i = 0; i < own.nodes.size(); ++i) {
            CHECK(culled.nodes[i].level == own.nodes[i].level);
            CHECK(culled.nodes[i].node_level == own.nodes[i].node_level);
            CHECK(culled.nodes[i].x == own.nodes[i].x);
            CHECK(culled.nodes[i].z == own.nodes[i].z);
        }
    }
}

TEST_CASE("shadows: a caster reaches a cascade's receivers exactly when its box swept away from the sun does") {
    // Brute force: the box's points (a 5^3 lattice, corners included) moved along -sun down to
    // the floor (9 steps, both ends included); the deepest view depth any of them reaches.
    std::mt19937 rng(21);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    int kept = 0, dropped = 0;
    for (int n = 0; n < 400; ++n) {
        const glm::dvec3 forward = glm::normalize(glm::dvec3(u(rng), 0.4 * u(rng), u(rng)));
        const glm::dvec3 sun = glm::normalize(glm::dvec3(u(rng), 0.1 + std::abs(u(rng)), u(rng)));
        const glm::dvec3 lo(400.0 * u(rng), -200.0 + 100.0 * u(rng), 400.0 * u(rng));
        const glm::dvec3 hi = lo + glm::dvec3(10.0 + 90.0 * std::abs(u(rng)), 150.0 * std::abs(u(rng)), 10.0 + 90.0 * std::abs(u(rng)));
        const double floor = lo.y - 100.0 * std::abs(u(rng)), min_depth = 500.0 * u(rng);
        double deepest = -1e300;
        for (int i = 0; i <= 4; ++i)
            for (int j = 0; j <= 4; ++j)
                for (int k = 0; k <= 4; ++k) {
                    const glm::dvec3 p = lo + (hi - lo) * glm::dvec3(i, j, k) / 4.0;
                    const double t_max = std::max(p.y - floor, 0.0) / sun.y;
                    for (int s = 0; s <= 8; ++s) deepest = std::max(deepest, glm::dot(forward, p - sun * (t_max * s / 8.0)));
                }
        CAPTURE(n);
        if (std::abs(deepest - min_depth) < 1e-6) continue;  // on the edge either answer is right
        const bool reaches = casterReachesDepth(lo, hi, forward, sun, floor, min_depth);
        CHECK(reaches == (deepest >= min_depth));
        (reaches ? kept : dropped) += 1;
    }
    CHECK(kept > 50);
    CHECK(dropped > 50);
    // No floor known: a shadow pointing away along the view may reach any depth.
    const glm::dvec3 forward(0.0, 0.0, -1.0), behind = glm::normalize(glm::dvec3(0.0, 1.0, 1.0));
    const double none = -std::numeric_limits<double>::infinity();
    CHECK(casterReachesDepth({-5, 0, -15}, {5, 10, -5}, forward, behind, none, 1e6));
    // The sun ahead: the shadow points back towards the camera, the box alone decides.
    const glm::dvec3 ahead = glm::normalize(glm::dvec3(0.0, 1.0, -1.0));
    CHECK_FALSE(casterReachesDepth({-5, 0, -15}, {5, 10, -5}, forward, ahead, none, 15.5));
    CHECK(casterReachesDepth({-5, 0, -15}, {5, 10, -5}, forward, ahead, none, 14.5));
}
