// The motion vectors ("temporal.velocity", renderer/velocity.h) under OSMesa: for every pixel of
// a frame, the GPU's velocity matches the reprojection of that pixel's point (from its depth)
// into the previous camera, done here in double with the world positions written out: near the
// terrain, and 10,000 km from the origin at t = 10^7 s (sky only there: rotation alone moves it,
// and a float world position would have lost the translation's metres long before).
#include "app/frame.h"
#include "renderer/velocity.h"
#include "renderer_fixture.h"

#include <glm/matrix.hpp>

#include <cmath>
#include <vector>

using namespace vista;

namespace {

constexpr int kW = 96, kH = 54;

Settings velocityScene() {
    Settings s;
    s.debug.grid = false;
    s.taa.enabled = false;  // no jitter: the unjittered pixel centre is the pixel centre
    s.clouds.enabled = false;
    s.grass.enabled = false;
    s.objects.enabled = false;
    s.water.enabled = false;
    return s;
}

struct Check {
    double worst_px = 0.0, largest_motion_px = 0.0;
    int pixels = 0, terrain = 0;
};

// Renders `previous` then `current`; compares the second frame's velocity with the CPU.
Check compare(const Settings& s, const ViewParams& previous, const ViewParams& current, double t) {
    FrameRenderer& r = test::fileRenderer();
    REQUIRE(r.prepare(s).empty());
    r.resetHistory();
    FrameRequest first;
    r.render(s, previous, t, first);
    std::vector<float> depth, velocity;
    FrameRequest second;
    second.depth = &depth;
    second.velocity = &velocity;
    const FrameReport report = r.render(s, current, t + 1.0 / 24.0, second);
    CHECK(report.counters.at("temporal.cut") == 0.0);
    REQUIRE(depth.size() == std::size_t(kW * kH));
    REQUIRE(velocity.size() == std::size_t(kW * kH * 4));

    // Where the pixel's point is in world space (double), and where the previous camera saw it.
    const glm::dmat4 inv_current = glm::inverse(glm::dmat4(viewMatrices(current).view_proj));
    const glm::dmat4 previous_vp(viewMatrices(previous).view_proj);
    Check c;
    for (int row = 0; row < kH; ++row)
        for (int x = 0; x < kW; ++x) {
            const std::size_t i = std::size_t(row) * kW + std::size_t(x);
            const glm::dvec2 ndc(2.0 * (x + 0.5) / kW - 1.0, 1.0 - 2.0 * (row + 0.5) / kH);
            const glm::dvec4 h = inv_current * glm::dvec4(ndc, double(depth[i]), 1.0);  // camera-relative, homogeneous
            // World point = current camera + relative (w = 0: a direction, the sky).
            const glm::dvec4 world(glm::dvec3(h) + current.position * h.w, h.w);
            const glm::dvec4 clip = previous_vp * glm::dvec4(glm::dvec3(world) - previous.position * world.w, world.w);
            const float* v = &velocity[i * 4];
            if (!(clip.w > 1e-6)) {
                CHECK(v[3] == 0.0f);
                continue;
            }
            const glm::dvec2 expected = (ndc - glm::dvec2(clip) / clip.w) * 0.5 * glm::dvec2(kW, kH);  // px
            // The readback is top row first like the depth, but uv's y points up: flip nothing,
            // compare in the texture's own axes (uv y up, as ndc).
            const glm::dvec2 gpu = glm::dvec2(v[0], v[1]) * glm::dvec2(kW, kH);
            c.worst_px = std::max(c.worst_px, glm::length(gpu - expected));
            c.largest_motion_px = std::max(c.largest_motion_px, glm::length(expected));
            CHECK(v[3] == 1.0f);
            ++c.pixels;
            if (depth[i] > 0.0f) ++c.terrain;
        }
    return c;
}

}  // namespace

TEST_CASE("gl: motion vectors match the CPU reprojection of every pixel's point, also 10,000 km out at t = 1e7 s") {
    const Settings s = velocityScene();
    {
        INFO("near the terrain");
        const ViewParams previous{{-3600.0, 260.0, 3400.0}, 45.0, -6.0, 60.0, 0.5, kW, kH};
        ViewParams current = previous;
        current.position += glm::dvec3(6.0, -1.5, -4.0);  // a fast fly-through frame, well under a cut
        current.yaw_deg += 1.2;
        current.pitch_deg -= 0.5;
        const Check c = compare(s, previous, current, 600.0);
        CHECK(c.pixels == kW * kH);
        CHECK(c.terrain > kW * kH / 4);      // terrain, not just sky
        CHECK(c.largest_motion_px > 1.0);    // it moved
        CHECK(c.worst_px < 0.02);
    }
    {
        INFO("10,000 km from the origin, t = 1e7 s");
        const ViewParams previous{{1.0e7, 500.0, -2.5e6}, 200.0, 4.0, 60.0, 0.5, kW, kH};
        ViewParams current = previous;
        current.position += glm::dvec3(20.0, 0.5, 7.0);
        current.yaw_deg -= 2.0;
        current.pitch_deg += 1.0;
        const Check c = compare(s, previous, current, 1.0e7);
        CHECK(c.pixels == kW * kH);
        CHECK(c.largest_motion_px > 2.0);
        CHECK(c.worst_px < 0.02);
    }
}
