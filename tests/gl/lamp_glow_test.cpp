// Lamp glow in fog ("lights.glow", renderer/lighting/lamp_glow.h) on the GPU: the light a lamp
// adds to each pixel must be the single-scattering integral the CPU marches for that pixel's
// ray, up to the ground or (over the sky) without end; clear air makes no pass and holds no memory.
#include "renderer/camera.h"
#include "renderer/lighting/lamp_glow.h"
#include "renderer/lighting/light_settings.h"
#include "renderer_fixture.h"

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>

#include <algorithm>
#include <cmath>

using namespace vista;

namespace {

constexpr double kEyeM = 3.0;  // camera and lamp height above the flat ground at y = 0
const ViewParams kView{{0.0, kEyeM, 0.0}, 0.0, 0.0, 60.0, 0.5, 96, 54};

Light lamp() {
    Light l;
    l.position = glm::dvec3(4.0, kEyeM, -25.0);
    l.radius_m = 20.0f;
    l.color = glm::vec3(1.0f, 0.8f, 0.6f);
    l.intensity = 1.0f;  // the peak glow stays far below the half-float target's 65,504
    return l;
}

// Night (the sun far down, no moon) over flat ground, dense fog, one lamp.
Settings foggyNight(bool fog, bool glow) {
    Settings s;
    test::terrainOnly(s);
    s.terrain.heightmap = "lamp-glow-test";
    s.terrain.size_m = 4000.0f;
    s.terrain.height_scale_m = 10.0f;
    s.terrain.height_offset_m = 0.0f;
    s.shadows.enabled = false;
    s.sky.sun_elevation_deg = -30.0f;
    s.sky.moon = false;
    s.sky.height_fog = fog;
    s.sky.fog_density_per_km = 20.0f;
    s.sky.fog_base_m = 0.0f;
    s.sky.fog_falloff_m = 1000.0f;
    s.lights.enabled = true;
    s.lights.glow = glow;
    s.lights.lights = {{"lamp", lamp()}};
    return s;
}

test::RenderedFrame render(const Settings& s) {
    FrameRenderer& r = test::fileRenderer();
    static bool adopted = false;
    if (!adopted) {
        test::adoptTerrain(r, s.terrain, 65, [](int, int) { return 0.0f; });
        adopted = true;
    }
    REQUIRE(r.prepare(s).empty());
    r.resetHistory();
    return test::renderFrame(r, s, kView);
}

}  // namespace

TEST_CASE("gl: a lamp's glow in fog is the single scattering the CPU integrates along each pixel's ray") {
    const test::RenderedFrame with = render(foggyNight(true, true));
    const test::RenderedFrame without = render(foggyNight(true, false));
    CHECK(with.report.counters.at("lights.glow") == 1.0);
    CHECK(std::find(with.report.executed.begin(), with.report.executed.end(), "lights.glow") != with.report.executed.end());
    CHECK(with.report.counters.count("lights.glow_memory_bytes") == 1);
    CHECK(without.report.counters.count("lights.glow") == 0);
    CHECK(without.report.counters.count("lights.glow_memory_bytes") == 0);

    const double pre_exposure = with.report.counters.at("sky.pre_exposure");
    const Settings s = foggyNight(true, true);
    const Light l = lamp();
    const GlowMedium medium = glowMedium(s.sky, l.position.y);
    const ViewMatrices m = viewMatrices(kView);
    const glm::dvec3 p = l.position - kView.position;
    // Expected glow per pixel (green), from the CPU integral with the light's real falloff.
    double peak = 0.0, worst = 0.0, ground_pixels = 0.0;
    std::vector<double> expected(std::size_t(kView.width) * kView.height);
    for (int row = 0; row < kView.height; ++row)
        for (int x = 0; x < kView.width; ++x) {
            const glm::vec4 ndc((float(x) + 0.5f) / float(kView.width) * 2.0f - 1.0f,
                                1.0f - (float(row) + 0.5f) / float(kView.height) * 2.0f, 0.5f, 1.0f);
            const glm::vec4 w = m.inv_view_proj * ndc;
            const glm::dvec3 dir = glm::normalize(glm::dvec3(w) / double(w.w));
            const double t_end = dir.y < 0.0 ? kEyeM / -dir.y : 1e30;  // the ground, or the sky
            const double e = medium.scattering.y * double(l.intensity) * double(l.color.y) * pre_exposure *
                             glowTransferReference(p, dir, t_end, l.radius_m, medium.extinction, true);
            expected[std::size_t(row) * kView.width + x] = e;
            peak = std::max(peak, e);
        }
    REQUIRE(peak > 0.0);
    for (int row = 0; row < kView.height; ++row)
        for (int x = 0; x < kView.width; ++x) {
            const std::size_t i = std::size_t(row) * kView.width + x;
            const double got = double(with.rgba[i * 4 + 1]) - double(without.rgba[i * 4 + 1]);
            const double e = expected[i];
            if (e < 0.02 * peak) continue;
            // The window's mean ignores the extinction's weighting (lamp_glow.h), the table is
            // read bilinearly and the half-float target rounds to 0.1 %.
            worst = std::max(worst, std::abs(got - e) / e);
            if (row > kView.height / 2 + 1) ground_pixels += 1.0;
        }
    MESSAGE("peak glow " << peak << " (HDR), largest relative error " << worst << ", ground pixels checked "
                         << ground_pixels);
    CHECK(worst < 0.03);
    CHECK(ground_pixels > 10.0);  // rays the ground stops inside the halo are checked too
}

TEST_CASE("gl: in clear air lamps do not glow: no lights.glow pass, no memory") {
    const test::RenderedFrame clear = render(foggyNight(false, true));
    CHECK(clear.report.counters.count("lights.glow") == 0);
    CHECK(clear.report.counters.count("lights.glow_memory_bytes") == 0);
    CHECK(std::find(clear.report.executed.begin(), clear.report.executed.end(), "lights.glow") == clear.report.executed.end());
}
