// Shadowed spot lights without GL: the tile's reversed-Z perspective against its closed form
// (depth of a distance, back again, the cone inside the frustum, any axis, 10,000 km out),
// which lights get a tile (priority by screen size, the atlas limit and its count), the atlas
// grid, the `shadow` key, and a terrain selection that covers the spot views while the view's
// part stays the view's own selection.
#include "renderer/lighting/light_settings.h"
#include "renderer/lighting/local_lights.h"
#include "renderer/camera.h"
#include "renderer/shadows/spot_shadows.h"
#include "terrain/cdlod.h"
#include "terrain_helpers.h"

#include <doctest/doctest.h>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <random>

using namespace vista;

namespace {

Light spot(glm::dvec3 position, glm::vec3 direction, float radius, float outer_deg) {
    Light l;
    l.type = LightType::Spot;
    l.position = position;
    l.direction = direction;
    l.radius_m = radius;
    l.inner_deg = outer_deg * 0.5f;
    l.outer_deg = outer_deg;
    return l;
}

glm::dvec3 project(const glm::dmat4& m, const glm::dvec3& p) {
    glm::dvec4 q = m * glm::dvec4(p, 1.0);
    return glm::dvec3(q) / q.w;
}

// A unit vector at `angle` from axis, turned by `turn` around it.
glm::dvec3 coneDirection(const glm::dvec3& axis, double angle, double turn) {
    glm::dvec3 a = glm::normalize(axis);
    glm::dvec3 t = glm::normalize(glm::cross(a, std::abs(a.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0)));
    glm::dvec3 b = glm::cross(a, t);
    return std::cos(angle) * a + std::sin(angle) * (std::cos(turn) * t + std::sin(turn) * b);
}

}  // namespace

TEST_CASE("spot shadows: depth along the axis follows n (f - z) / (z (f - n)) and spotLinearDepth inverts it") {
    const Light l = spot({10.0, 20.0, -5.0}, {0.3f, -1.0f, 0.2f}, 40.0f, 35.0f);
    const SpotShadowView v = spotShadowView(l, glm::dvec3(0.0));
    CHECK(v.far_m == 40.0);
    CHECK(v.near_m > 0.0);
    CHECK(v.near_m < v.far_m);
    const glm::dvec3 axis = glm::normalize(glm::dvec3(l.direction));
    for (double z : {v.near_m, 0.5, 1.0, 3.0, 10.0, 25.0, 40.0}) {
        CAPTURE(z);
        const glm::dvec3 ndc = project(v.view_proj, l.position + axis * z);
        CHECK(std::abs(ndc.x) < 1e-9);
        CHECK(std::abs(ndc.y) < 1e-9);
        const double expected = v.near_m * (v.far_m - z) / (z * (v.far_m - v.near_m));
        CHECK(ndc.z == doctest::Approx(expected).epsilon(1e-12));
        CHECK(spotLinearDepth(ndc.z, v.near_m, v.far_m) == doctest::Approx(z).epsilon(1e-12));
    }
    CHECK(project(v.view_proj, l.position + axis * v.near_m).z == doctest::Approx(1.0));  // reversed-Z: near is 1
    CHECK(std::abs(project(v.view_proj, l.position + axis * v.far_m).z) < 1e-12);        // the radius is 0
}

TEST_CASE("spot shadows: everything the cone reaches lies inside the tile, for any axis and far from the origin") {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const std::vector<glm::vec3> axes = {{0, -1, 0}, {0, 1, 0}, {1, 0, 0}, {0, 0, -1}, {0.577f, -0.577f, 0.577f},
                                         {1e-4f, -1.0f, 0.0f}, {0.2f, 0.1f, -0.9f}};
    for (const glm::dvec3 camera : {glm::dvec3(0.0), glm::dvec3(1e7, 300.0, -1e7)}) {
        for (const glm::vec3& axis : axes) {
            for (float outer : {1.0f, 30.0f, 60.0f, 84.0f}) {
                CAPTURE(outer);
                const Light l = spot(camera + glm::dvec3(12.0, 8.0, -3.0), axis, 30.0f, outer);
                const SpotShadowView v = spotShadowView(l, camera);
                for (int c = 0; c < 4; ++c)
                    for (int r = 0; r < 4; ++r) REQUIRE(std::isfinite(v.view_proj[c][r]));
                REQUIRE(std::abs(glm::determinant(v.view_proj)) > 0.0);
                for (int i = 0; i < 200; ++i) {
                    // A point the light reaches: inside the cone and the radius (beyond the near plane).
                    const double angle = glm::radians(double(outer)) * std::sqrt(u(rng)) * 0.999;
                    const glm::dvec3 dir = coneDirection(glm::dvec3(axis), angle, u(rng) * 6.283185307);
                    const double dist = v.near_m / std::cos(angle) + u(rng) * (29.9 - v.near_m / std::cos(angle));
                    if (dist * std::cos(angle) >= 30.0) continue;
                    const glm::dvec3 ndc = project(v.view_proj, l.position - camera + dir * dist);
                    CHECK(std::abs(ndc.x) <= 1.0 + 1e-9);
                    CHECK(std::abs(ndc.y) <= 1.0 + 1e-9);
                    CHECK(ndc.z >= -1e-9);
                    CHECK(ndc.z <= 1.0 + 1e-9);
                }
            }
        }
    }
}

TEST_CASE("spot shadows: the tile's matrix is the same 10,000 km out as at the origin (camera-relative in double)") {
    const glm::dvec3 far(1e7, 0.0, -1e7);
    const Light near_light = spot({5.0, 6.0, 7.0}, {0.0f, -1.0f, 0.3f}, 25.0f, 40.0f);
    Light far_light = near_light;
    far_light.position += far;
    const SpotShadowView a = spotShadowView(near_light, glm::dvec3(0.0));
    const SpotShadowView b = spotShadowView(far_light, far);
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) CHECK(b.view_proj[c][r] == doctest::Approx(a.view_proj[c][r]).epsilon(1e-9));
}

TEST_CASE("spot shadows: the largest lights on screen get the tiles, the rest are counted as unshadowed") {
    const ViewParams view{{0.0, 10.0, 0.0}, 0.0, 0.0, 60.0, 0.1, 320, 180};  // looks along -z
    const ViewMatrices m = viewMatrices(view);
    std::vector<Light> lights;
    for (int i = 0; i < 10; ++i)  // along the view axis, farther and farther: smaller on screen
        lights.push_back(spot({0.0, 10.0, -20.0 - 30.0 * i}, {0, -1, 0}, 10.0f, 30.0f));
    Light point = lights[0];
    point.type = LightType::Point;
    lights.push_back(point);                                                  // 10: point lights cast none
    lights.push_back(spot({0.0, 10.0, 60.0}, {0, -1, 0}, 10.0f, 30.0f));      // 11: behind the camera
    Light off = lights[0];
    off.shadow = false;
    lights.push_back(off);                                                    // 12: shadow off
    lights.push_back(spot({0.0, 10.0, -15.0}, {0, -1, 0}, 10.0f, 89.0f));     // 13: too wide a cone
    lights.push_back(spot({0.0, 10.0, -15.0}, {0, -1, 0}, 0.0f, 30.0f));      // 14: radius 0
    lights.push_back(spot({0.5, 12.0, 0.5}, {0, -1, 0}, 10.0f, 30.0f));       // 15: the camera is inside its sphere

    std::uint64_t candidates = 0;
    std::vector<SpotShadowPick> picks = pickShadowedSpots(lights, view, m, 4, 0.0f, candidates);
    CHECK(candidates == 11);  // lights 0..9 and 15
    REQUIRE(picks.size() == 4);
    CHECK(picks[0].light == 15);
    CHECK(std::isinf(picks[0].screen_px));
    CHECK(picks[1].light == 0);
    CHECK(picks[2].light == 1);
    CHECK(picks[3].light == 2);
    CHECK(picks[1].screen_px > picks[2].screen_px);
    // The closed form for light 0's sphere: r / sqrt(d^2 - r^2) * (h / 2) / tan(fov / 2).
    const Sphere s0 = boundingSphere(lights[0]);
    const double d0 = glm::length(s0.center - view.position);
    const double expected = s0.radius / std::sqrt(d0 * d0 - s0.radius * s0.radius) * 90.0 / std::tan(glm::radians(30.0));
    CHECK(picks[1].screen_px == doctest::Approx(expected));

    picks = pickShadowedSpots(lights, view, m, 64, 0.0f, candidates);
    CHECK(picks.size() == 11);
    picks = pickShadowedSpots(lights, view, m, 64, float(expected) * 0.5f, candidates);  // small ones drop out
    CHECK(candidates < 11);
    CHECK(candidates >= 2);
    for (const SpotShadowPick& p : picks) CHECK(p.screen_px >= expected * 0.5);
}

TEST_CASE("spot shadows: atlas tiles per side") {
    CHECK(spotAtlasTilesPerSide(1) == 1);
    CHECK(spotAtlasTilesPerSide(2) == 2);
    CHECK(spotAtlasTilesPerSide(4) == 2);
    CHECK(spotAtlasTilesPerSide(5) == 3);
    CHECK(spotAtlasTilesPerSide(16) == 4);
    CHECK(spotAtlasTilesPerSide(17) == 5);
    CHECK(spotAtlasTilesPerSide(64) == 8);
}

TEST_CASE("spot shadows: `shadow on|off` in a light entry, round trip and errors") {
    Light l;
    REQUIRE(parseLightSpec("spot 1 2 3  radius 20  cone 10 30  shadow off", l).empty());
    CHECK(l.type == LightType::Spot);
    CHECK_FALSE(l.shadow);
    Light back;
    REQUIRE(parseLightSpec(formatLightSpec(l), back).empty());
    CHECK(back == l);
    Light fresh;
    REQUIRE(parseLightSpec("spot 1 2 3", fresh).empty());
    CHECK(fresh.shadow);  // the default
    CHECK(formatLightSpec(fresh).find("shadow") == std::string::npos);
    const std::string error = parseLightSpec("spot 1 2 3  shadow maybe", l);
    CHECK(error.find("shadow") != std::string::npos);
    CHECK(error.find("'on' or 'off'") != std::string::npos);
}

TEST_CASE("spot shadows: a selection widened by spot views keeps the view's own nodes and covers the spots") {
    const test::BumpyQuadtree terrain(0.13, 0.05);
    const auto& [mapping, tree, lod] = terrain;
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int k = 0; k < 30; ++k) {
        const ViewParams v = test::randomView(rng, 3000, 350, 300);
        const Frustum view = frustumFromViewProj(glm::dmat4(viewMatrices(v).view_proj));
        // Two street lights, one of them behind the camera (outside the view).
        std::vector<Frustum> spots;
        for (int i = 0; i < 2; ++i) {
            const glm::dvec3 at = v.position + glm::dvec3((u(rng) - 0.5) * 400, -50 - u(rng) * 200, (u(rng) - 0.5) * 400);
            spots.push_back(frustumFromViewProj(spotShadowView(spot(at, {0, -1, 0}, 300.0f, 50.0f), v.position).view_proj));
        }
        std::vector<Frustum> all = {view};
        all.insert(all.end(), spots.begin(), spots.end());
        Selection own, wide, culled, spot_own, spot_culled;
        selectNodes(tree, mapping, lod, v.position, view, own);
        selectNodes(tree, mapping, lod, v.position, all, wide);
        cullSelection(wide, view, culled);
        REQUIRE(culled.nodes.size() == own.nodes.size());
        for (std::size_t i = 0; i < own.nodes.size(); ++i) {
            CHECK(culled.nodes[i].level == own.nodes[i].level);
            CHECK(culled.nodes[i].x == own.nodes[i].x);
            CHECK(culled.nodes[i].z == own.nodes[i].z);
        }
        for (const Frustum& f : spots) {  // each spot view sees what it would see alone
            selectNodes(tree, mapping, lod, v.position, f, spot_own);
            cullSelection(wide, f, spot_culled);
            CHECK(spot_culled.nodes.size() == spot_own.nodes.size());
        }
    }
}

TEST_CASE("spot shadows: street lights with `ground H` stand H above the terrain, and round-trip") {
    LightsSettings s;
    Light l;
    REQUIRE(parseLightSpec("spot 10 999 -20  direction 0 -1 0  ground 6", l).empty());
    CHECK(l.ground_m == 6.0f);
    Light back;
    REQUIRE(parseLightSpec(formatLightSpec(l), back).empty());
    CHECK(back == l);
    s.lights = {{"a", l}, {"b", spot({1.0, 2.0, 3.0}, {0, -1, 0}, 10.0f, 30.0f)}};
    const std::vector<Light> on = collectSceneLights(s, [](double x, double z) { return 0.5 * x - z; }, 1.0);
    REQUIRE(on.size() == 2);
    CHECK(on[0].position.y == doctest::Approx(0.5 * 10.0 + 20.0 + 6.0));
    CHECK(on[1].position.y == 2.0);  // no `ground`: its own y
    CHECK(collectSceneLights(s, {}, 1.0)[0].position.y == 999.0);  // no terrain: its own y
    CHECK_FALSE(parseLightSpec("spot 1 2 3  ground -2", l).empty());
}
