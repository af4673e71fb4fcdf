// Cloud layers under OSMesa: the GPU noise against its CPU mirror, finite images for extreme
// views with clouds on, no clouds.* pass when the clouds draw nothing, and cloud shadows that
// only ever take sunlight away from the terrain.
#include "app/frame.h"
#include "app/scene.h"
#include "renderer_fixture.h"
#include "sky/clouds/cloud_model.h"
#include "terrain/heightmap.h"

#include <glm/gtc/packing.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

using namespace vista;

namespace {

FrameRenderer& renderer() { return test::fileRenderer(); }

Settings skyWithClouds(float sun_elevation_deg) {
    Settings s;
    s.terrain.enabled = false;
    s.debug.grid = false;
    s.sky.sun_elevation_deg = sun_elevation_deg;
    s.sky.sun_azimuth_deg = 180.0f;
    s.clouds.low.coverage = 0.6f;
    return s;
}

struct Rendered {
    std::vector<float> hdr;
    std::uint64_t nonfinite = 0;
    std::vector<std::string> executed;
};

Rendered render(const Settings& s, const ViewParams& view, double t = 0.0) {
    FrameRenderer& r = renderer();
    REQUIRE(r.prepare(s).empty());
    r.resetHistory();  // each frame the first of a run: frames compare without history or jitter differences
    FrameRequest request;
    request.count_nonfinite = true;
    test::RenderedFrame f = test::renderFrame(r, s, view, t, request);
    return Rendered{std::move(f.rgba), f.counter("nonfinite_pixels"), std::move(f.report.executed)};
}

bool hasPrefix(const std::vector<std::string>& passes, const std::string& prefix) {
    return std::any_of(passes.begin(), passes.end(), [&](const std::string& p) { return p.rfind(prefix, 0) == 0; });
}
bool contains(const std::vector<std::string>& passes, const std::string& name) {
    return std::find(passes.begin(), passes.end(), name) != passes.end();
}

ViewParams view(double altitude_m, double yaw_deg, double pitch_deg, int width = 64, int height = 36) {
    return ViewParams{{0.0, altitude_m, 0.0}, yaw_deg, pitch_deg, 60.0, 0.5, width, height};
}

double meanAbsDiff(const Rendered& a, const Rendered& b) {
    double sum = 0.0;
    for (std::size_t i = 0; i < a.hdr.size(); ++i) sum += std::abs(double(a.hdr[i]) - double(b.hdr[i]));
    return sum / double(a.hdr.size());
}

}  // namespace

TEST_CASE("gl: cloud noise and fBm on the GPU match the double-precision CPU mirror") {
    FrameRenderer& r = renderer();
    const int w = 96, h = 64;
    const std::vector<float> texels = test::drawProbe(r.shaders(), "tests/gl/shaders/cloud_noise_probe.glsl", w, h);
    double worst_noise = 0.0, worst_fbm = 0.0, lo = 1.0, hi = 0.0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            // As the probe computes it, in float, then evaluated in double.
            const glm::dvec3 q(float(x) * 1.37f - 40.0f, float(y) * 0.29f + 0.11f, float(y) * 2.13f - float(x) * 0.71f);
            const float* t = &texels[(std::size_t(y) * std::size_t(w) + std::size_t(x)) * 4];
            const double n = cloudValueNoise(q, kCloudNoisePeriod, 12345u), f = cloudFbm(q, 5, 777u);
            worst_noise = std::max(worst_noise, std::abs(double(t[0]) - n));
            worst_fbm = std::max(worst_fbm, std::abs(double(t[1]) - f));
            lo = std::min(lo, n), hi = std::max(hi, n);
        }
    std::printf("cloud noise probe: worst |GPU - CPU| noise %.2e fbm %.2e\n", worst_noise, worst_fbm);
    CHECK(hi - lo > 0.8);  // the probe sees the noise's range
    CHECK(worst_noise < 2e-4);
    CHECK(worst_fbm < 2e-4);
}

TEST_CASE("gl: extreme views with clouds give finite images, and the clouds show") {
    struct Case {
        float sun_elevation;
        ViewParams view;
    } cases[] = {
        {35.0f, view(2.0, 0.0, 0.0)},           // the horizon
        {90.0f, view(2.0, 0.0, 89.9)},          // straight up at the sun
        {35.0f, view(2.0, 0.0, -89.9)},         // straight down
        {3.0f, view(2.0, 180.0, 10.0)},         // sunset, into the sun
        {-10.0f, view(2.0, 0.0, 30.0)},         // the sun below the horizon
        {30.0f, view(2000.0, 0.0, 0.0)},        // inside the low layer
        {30.0f, view(9000.0, 0.0, -30.0)},      // above both layers
        {10.0f, view(400000.0, 0.0, -89.0)},    // orbit, looking down
        {10.0f, view(400000.0, 180.0, -19.0)},  // orbit, the limb
        {-90.0f, view(-50.0, 0.0, 0.0)},        // below the ground
    };
    for (const Case& c : cases) {
        CAPTURE(c.sun_elevation);
        CAPTURE(c.view.position.y);
        CAPTURE(c.view.pitch_deg);
        Settings s = skyWithClouds(c.sun_elevation);
        Rendered r = render(s, c.view, 1e7);
        CHECK(r.nonfinite == 0);
        CHECK(contains(r.executed, "clouds.shell"));
    }
    // Looking up at noon: the clouds change the image.
    Settings s = skyWithClouds(60.0f);
    Settings clear = s;
    clear.clouds.enabled = false;
    const ViewParams up = view(2.0, 0.0, 60.0);
    CHECK(meanAbsDiff(render(s, up), render(clear, up)) > 1e-3);
    // Time 1e7 s draws clouds as well as time 10 s (the pattern has moved, the amount has not).
    Rendered a = render(s, up, 10.0), b = render(s, up, 1e7);
    CHECK(meanAbsDiff(a, render(clear, up)) > 0.2 * meanAbsDiff(b, render(clear, up)));
    CHECK(meanAbsDiff(b, render(clear, up)) > 0.2 * meanAbsDiff(a, render(clear, up)));
}

TEST_CASE("gl: clouds that draw nothing add no clouds.* pass") {
    Settings s = skyWithClouds(30.0f);
    const ViewParams v = view(2.0, 0.0, 20.0);
    CHECK(contains(render(s, v).executed, "clouds.shell"));
    CHECK(renderer().clouds() != nullptr);
    Settings off = s;
    off.clouds.enabled = false;
    Rendered r = render(off, v);
    CHECK_FALSE(hasPrefix(r.executed, "clouds."));
    CHECK(renderer().clouds() == nullptr);  // nothing kept allocated
    Settings none = s;
    none.clouds.low.coverage = 0.0f;
    none.clouds.high.coverage = 0.0f;
    CHECK_FALSE(hasPrefix(render(none, v).executed, "clouds."));
    Settings no_sky = s;
    no_sky.sky.enabled = false;
    CHECK_FALSE(hasPrefix(render(no_sky, v).executed, "clouds."));
}

TEST_CASE("gl: cloud shadows only take sunlight away, and a full overcast takes most of it") {
    Settings s;
    s.terrain.heightmap = "clouds-test";
    s.terrain.size_m = 4000.0f;
    s.terrain.height_scale_m = 200.0f;
    s.terrain.height_offset_m = 0.0f;
    s.debug.grid = false;
    s.lights.enabled = false;
    s.ssao.enabled = false;
    s.sky.sun_elevation_deg = 50.0f;
    s.sky.aerial_perspective = false;
    test::adoptTerrain(renderer(), s.terrain, 65, [](int x, int z) {
        return 0.5f + 0.3f * std::sin(float(x) * 0.2f) * std::cos(float(z) * 0.15f);
    });
    const ViewParams down{{0.0, 600.0, 0.0}, 0.0, -70.0, 50.0, 0.5, 96, 54};  // terrain in every pixel

    Settings clear = s;
    clear.clouds.enabled = false;
    Settings broken = s;  // the default layers
    Settings overcast = s;
    overcast.clouds.low.coverage = 1.0f;
    overcast.clouds.coverage_variation = 0.0f;
    const Rendered c = render(clear, down), b = render(broken, down), o = render(overcast, down);
    REQUIRE(contains(b.executed, "clouds.shadow"));
    CHECK_FALSE(contains(c.executed, "clouds.shadow"));
    CHECK(b.nonfinite == 0);
    CHECK(o.nonfinite == 0);
    double sum_c = 0.0, sum_b = 0.0, sum_o = 0.0, worst_brighter = 0.0;
    for (std::size_t i = 0; i < c.hdr.size(); i += 4)
        for (int k = 0; k < 3; ++k) {
            const double vc = c.hdr[i + std::size_t(k)], vb = b.hdr[i + std::size_t(k)], vo = o.hdr[i + std::size_t(k)];
            sum_c += vc, sum_b += vb, sum_o += vo;
            worst_brighter = std::max({worst_brighter, (vb - vc) / std::max(vc, 1e-3), (vo - vc) / std::max(vc, 1e-3)});
        }
    std::printf("cloud shadows: mean radiance clear %.4f broken %.4f overcast %.4f\n", sum_c, sum_b, sum_o);
    CHECK(worst_brighter < 2e-3);  // a shadow term above 1 would brighten some pixel
    CHECK(sum_b < sum_c);          // broken clouds shade part of the ground
    CHECK(sum_o < 0.6 * sum_c);    // an overcast takes most of the direct sun
    CHECK(sum_o > 0.0);            // the sky's ambient light remains
}
