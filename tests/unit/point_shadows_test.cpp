// Shadowed point lights without GL: each cube face's reversed-Z view against GL's cube-map
// lookup (the face a direction picks, the texel it reads, and the depth pointFaceDepth says the
// face holds there), and which point lights get a cube (the spots' ranking, limit and count).
#include "renderer/camera.h"
#include "renderer/shadows/point_shadows.h"

#include <doctest/doctest.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <random>

using namespace vista;

namespace {

Light pointLight(glm::dvec3 position, float radius) {
    Light l;
    l.type = LightType::Point;
    l.position = position;
    l.radius_m = radius;
    return l;
}

// GL 4.5 table 8.19: the face a direction selects and its (s, t) in [0, 1] (t = 0 the first row).
glm::dvec2 cubeLookup(const glm::dvec3& r, int& face) {
    const glm::dvec3 a = glm::abs(r);
    double sc = 0.0, tc = 0.0, ma = 0.0;
    if (a.x >= a.y && a.x >= a.z) {
        face = r.x >= 0.0 ? 0 : 1;
        ma = a.x;
        sc = r.x >= 0.0 ? -r.z : r.z;
        tc = -r.y;
    } else if (a.y >= a.z) {
        face = r.y >= 0.0 ? 2 : 3;
        ma = a.y;
        sc = r.x;
        tc = r.y >= 0.0 ? r.z : -r.z;
    } else {
        face = r.z >= 0.0 ? 4 : 5;
        ma = a.z;
        sc = r.z >= 0.0 ? r.x : -r.x;
        tc = -r.y;
    }
    return {0.5 * (sc / ma + 1.0), 0.5 * (tc / ma + 1.0)};
}

}  // namespace

TEST_CASE("point shadows: each face draws a direction where GL's cube lookup reads it, at pointFaceDepth") {
    const glm::dvec3 camera(1.0e7, -3.0, 2.0e6);  // camera-relative views stay exact far out
    const Light l = pointLight(camera + glm::dvec3(10.0, 4.0, -6.0), 30.0f);
    const PointShadowView v = pointShadowView(l, camera);
    CHECK(v.far_m == 30.0);
    CHECK(v.near_m > 0.0);
    CHECK(v.near_m < 1.0);
    CHECK(glm::length(v.position - glm::dvec3(10.0, 4.0, -6.0)) < 1e-6);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1.0, 1.0), dist(0.1, 29.0);
    for (int i = 0; i < 500; ++i) {
        glm::dvec3 dir(u(rng), u(rng), u(rng));
        if (glm::length(dir) < 0.1) continue;
        dir = glm::normalize(dir) * dist(rng);
        int face = -1;
        const glm::dvec2 st = cubeLookup(dir, face);
        REQUIRE(face == pointCubeFace(dir));
        // The face draws the point (camera-relative) at the texel the lookup reads: window x = s,
        // window y = t (render targets put clip y = -1 in row 0).
        const glm::dvec4 clip = v.view_proj[std::size_t(face)] * glm::dvec4(v.position + dir, 1.0);
        REQUIRE(clip.w > 0.0);
        const glm::dvec3 ndc = glm::dvec3(clip) / clip.w;
        CHECK(ndc.x * 0.5 + 0.5 == doctest::Approx(st.x).epsilon(1e-9));
        CHECK(ndc.y * 0.5 + 0.5 == doctest::Approx(st.y).epsilon(1e-9));
        CHECK(ndc.z == doctest::Approx(pointFaceDepth(dir, v.near_m, v.far_m)).epsilon(1e-9));
    }
    // Reversed-Z: 1 at the near plane, 0 at the radius along every axis.
    CHECK(pointFaceDepth({0.0, -v.near_m, 0.0}, v.near_m, v.far_m) == doctest::Approx(1.0));
    CHECK(pointFaceDepth({0.0, 0.0, 30.0}, v.near_m, v.far_m) == doctest::Approx(0.0));
}

TEST_CASE("point shadows: the largest point lights on screen get cubes, up to point_max_lights, the rest are counted") {
    const ViewParams view{{0.0, 10.0, 0.0}, 0.0, 0.0, 60.0, 0.5, 320, 180};
    const ViewMatrices m = viewMatrices(view);
    const glm::dvec3 ahead = m.forward;
    std::vector<Light> lights;
    for (int i = 0; i < 6; ++i) lights.push_back(pointLight(view.position + ahead * (40.0 + 20.0 * i), 10.0f));
    lights.push_back(pointLight(view.position - ahead * 50.0, 10.0f));  // behind the camera
    Light spot = pointLight(view.position + ahead * 30.0, 10.0f);
    spot.type = LightType::Spot;  // the spots' own ranking takes it
    lights.push_back(spot);
    Light off = pointLight(view.position + ahead * 20.0, 10.0f);
    off.shadow = false;
    lights.push_back(off);
    ShadowSettings s;
    s.point_enabled = true;
    s.point_max_lights = 4;
    s.point_min_screen_px = 0.0f;
    PointShadows shadows;
    REQUIRE(shadows.prepare(s, lights, view, m));
    CHECK(shadows.stats().candidates == 6);
    CHECK(shadows.stats().unshadowed == 2);
    REQUIRE(shadows.picks().size() == 4);
    for (std::size_t k = 0; k < 4; ++k) CHECK(shadows.picks()[k].light == k);  // nearest (largest) first
    CHECK(shadows.frusta().size() == 4 * kCubeFaces);
    // Lights too small on screen cast no shadow: none left, no pass.
    s.point_min_screen_px = 10000.0f;
    CHECK_FALSE(shadows.prepare(s, lights, view, m));
    CHECK(shadows.stats().candidates == 0);
}
