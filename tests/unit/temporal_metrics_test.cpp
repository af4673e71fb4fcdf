// The temporal error measures of `vista quality` (app/temporal_metrics.h) on images made on the
// CPU: the converged image's linear-light box filter, flicker after reprojection (zero for a
// static textured wall seen by a moving camera, also 10,000 km from the origin; the change of
// an un-reprojected comparison is far larger), the flicker statistics and the frames a cut takes
// to converge.
#include "app/temporal_metrics.h"

#include <doctest/doctest.h>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <cmath>
#include <numeric>

using namespace vista;

namespace {

// A camera looking along -z at a wall z = wall_z whose grey level varies smoothly with the
// world position (a pattern of a few metres), sky (depth 0) above y = sky_y: the frame a perfect
// renderer makes, with its reversed-Z depth.
SequenceFrame wallFrame(const ViewParams& v, double wall_z, double sky_y) {
    SequenceFrame f;
    f.view = v;
    const int w = v.width, h = v.height;
    f.ldr.assign(std::size_t(w) * std::size_t(h) * 4, 255);
    f.depth.assign(std::size_t(w) * std::size_t(h), 0.0f);
    const ViewMatrices m = viewMatrices(v);
    const glm::dmat4 inv = glm::inverse(glm::dmat4(m.view_proj));
    for (int r = 0; r < h; ++r)
        for (int x = 0; x < w; ++x) {
            const glm::dvec4 p = inv * glm::dvec4(2.0 * (x + 0.5) / w - 1.0, 1.0 - 2.0 * (r + 0.5) / h, 0.5, 1.0);
            const glm::dvec3 dir = glm::normalize(glm::dvec3(p) / p.w);
            const std::size_t i = std::size_t(r) * std::size_t(w) + std::size_t(x);
            unsigned char grey = 200;  // sky
            if (dir.z < 0.0) {
                const double s = (wall_z - v.position.z) / dir.z;
                const glm::dvec3 world = v.position + dir * s;
                if (world.y < sky_y) {
                    const double distance = glm::dot(dir * s, m.forward);  // view-space depth
                    f.depth[i] = float(v.near_m / distance);
                    // Relative to a point on the wall: the pattern stays exact far from the origin.
                    const double u = world.x - std::floor(world.x / 1000.0) * 1000.0, vv = world.y;
                    grey = static_cast<unsigned char>(std::lround(128.0 + 60.0 * std::sin(u * 0.3) * std::cos(vv * 0.25)));
                }
            }
            for (int c = 0; c < 3; ++c) f.ldr[i * 4 + std::size_t(c)] = grey;
        }
    return f;
}

}  // namespace

TEST_CASE("temporal metrics: the converged image averages supersampled frames in linear light") {
    ConvergedImage image(1, 1, 2);
    CHECK(image.result().empty());
    // Two frames of 2x2: black and white texels average to linear 0.5 (sRGB 188), not 128.
    image.add({0, 0, 0, 255, 255, 255, 255, 255, 0, 0, 0, 255, 255, 255, 255, 255});
    image.add({0, 0, 0, 255, 255, 255, 255, 255, 0, 0, 0, 255, 255, 255, 255, 255});
    const std::vector<unsigned char> out = image.result();
    REQUIRE(out.size() == 4);
    CHECK(int(out[0]) == 188);
    CHECK(int(out[3]) == 255);
    CHECK(image.frames() == 2);
}

TEST_CASE("temporal metrics: flicker after reprojection of a static wall is near zero, also 10,000 km out") {
    for (const double origin : {0.0, 1.0e7}) {
        INFO("origin x = " << origin);
        ViewParams a;
        a.position = {origin + 3.0, 2.0, 0.0};
        a.fov_deg = 60.0;
        a.width = 96;
        a.height = 54;
        ViewParams b = a;
        b.position += glm::dvec3(0.6, 0.1, -1.5);  // one frame of a slow camera
        b.yaw_deg = 1.5;
        const SequenceFrame fa = wallFrame(a, -40.0, 12.0), fb = wallFrame(b, -40.0, 12.0);
        const FlickerStats moved = flickerStats(reprojectedLumaChange(fa, fb));
        CHECK(moved.samples > std::size_t(96 * 54 * 8 / 10));  // most pixels land in the previous frame
        CHECK(moved.mean < 1.0);                               // bilinear resampling of a smooth pattern
        // Without reprojection (the same camera twice) the same two images differ a lot.
        SequenceFrame fb_as_a = fb;
        fb_as_a.view = a;
        const FlickerStats unaligned = flickerStats(reprojectedLumaChange(fa, fb_as_a));
        CHECK(unaligned.mean > 10.0 * moved.mean + 2.0);
    }
}

TEST_CASE("temporal metrics: a surface the previous frame did not see is left out") {
    ViewParams a;
    a.width = 64;
    a.height = 36;
    SequenceFrame fa = wallFrame(a, -40.0, 1.0e9), fb = wallFrame(a, -40.0, 1.0e9);
    const std::size_t all = flickerStats(reprojectedLumaChange(fa, fb)).samples;
    CHECK(all == std::size_t(64 * 36));
    // The previous frame saw something 4x nearer in the left half: those pixels are occluded there.
    for (int r = 0; r < 36; ++r)
        for (int x = 0; x < 32; ++x) fa.depth[std::size_t(r) * 64 + std::size_t(x)] *= 4.0f;
    CHECK(flickerStats(reprojectedLumaChange(fa, fb)).samples == all / 2);
}

TEST_CASE("temporal metrics: flicker statistics and frames until converged") {
    std::vector<double> values(100);
    std::iota(values.begin(), values.end(), 1.0);
    const FlickerStats s = flickerStats(values);
    CHECK(s.mean == doctest::Approx(50.5));
    CHECK(s.p99 == doctest::Approx(99.0));
    CHECK(s.samples == 100);
    CHECK(flickerStats({}).samples == 0);

    CHECK(framesUntilConverged({}) == -1);
    CHECK(framesUntilConverged({30.0}) == 0);
    CHECK(framesUntilConverged({18.0, 25.0, 29.2, 29.5, 30.0}) == 2);
    CHECK(framesUntilConverged({18.0, 29.5, 27.0, 30.0, 30.0}) == 3);  // a dip after reaching it counts
    CHECK(framesUntilConverged({31.0, 32.0, 30.0}) == 0);              // better than converged is converged
}
