// The temporal techniques' CPU side: the Halton jitter and its projection shift, camera-cut
// detection, the reprojection of known points into the previous frame (also 10,000 km from the
// origin, where only the double-precision translation keeps it exact), and the void-and-cluster
// blue noise: a permutation whose spectrum has no low frequencies, unlike white noise.
#include "postfx/motion_blur.h"
#include "renderer/blue_noise.h"
#include "renderer/temporal.h"

#include <doctest/doctest.h>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>

using namespace vista;

namespace {

// Clip coordinates of a world point seen from camera v, all in double, written out by hand.
glm::dvec4 referenceClip(const ViewParams& v, const glm::dvec3& world) {
    const glm::dvec3 rel = world - v.position;
    const double yaw = glm::radians(v.yaw_deg);
    const glm::dvec3 forward = directionFromAngles(v.yaw_deg, v.pitch_deg);
    const glm::dvec3 right(std::cos(yaw), 0.0, std::sin(yaw));
    const glm::dvec3 up = glm::cross(right, forward);
    const glm::dvec3 eye(glm::dot(rel, right), glm::dot(rel, up), -glm::dot(rel, forward));
    const double f = 1.0 / std::tan(glm::radians(v.fov_deg) * 0.5), aspect = double(v.width) / double(v.height);
    return {eye.x * f / aspect, eye.y * f, v.near_m, -eye.z};
}

glm::dvec2 pixels(const glm::dvec4& clip, const ViewParams& v) {
    return {(clip.x / clip.w * 0.5 + 0.5) * double(v.width), (clip.y / clip.w * 0.5 + 0.5) * double(v.height)};
}

double lowToHighPower(const std::vector<double>& field, int size) {
    const std::vector<double> p = radialPowerSpectrum(field, size);
    double low = 0.0, high = 0.0;
    int nl = 0, nh = 0;
    for (int r = 1; r <= size / 8; ++r) low += p[std::size_t(r)], ++nl;
    for (int r = size / 4; r <= size / 2; ++r) high += p[std::size_t(r)], ++nh;
    return (low / nl) / (high / nh);
}

}  // namespace

TEST_CASE("temporal: Halton jitter terms, inside the pixel, and their projection shift") {
    CHECK(radicalInverse(1, 2) == doctest::Approx(0.5));
    CHECK(radicalInverse(2, 2) == doctest::Approx(0.25));
    CHECK(radicalInverse(3, 2) == doctest::Approx(0.75));
    CHECK(radicalInverse(1, 3) == doctest::Approx(1.0 / 3.0));
    CHECK(radicalInverse(5, 3) == doctest::Approx(7.0 / 9.0));
    std::set<std::pair<double, double>> seen;
    glm::dvec2 mean(0.0);
    for (std::uint64_t i = 0; i < 8; ++i) {
        const glm::dvec2 j = taaJitterPx(i);
        CHECK(std::abs(j.x) < 0.5);
        CHECK(std::abs(j.y) < 0.5);
        seen.insert({j.x, j.y});
        mean += j / 8.0;
        CHECK(taaJitterPx(i + 8) == j);  // period 8
    }
    CHECK(seen.size() == 8);
    CHECK(std::abs(mean.x) < 0.07);
    CHECK(std::abs(mean.y) < 0.07);

    // A point lands jitter pixels away from where the unjittered projection puts it.
    const ViewParams v{{0.0, 10.0, 0.0}, 30.0, -5.0, 60.0, 0.1, 320, 180};
    ViewMatrices m = viewMatrices(v);
    const glm::dvec2 jitter(0.25, -0.375);
    const glm::dvec3 rel(40.0, -3.0, -120.0);
    const glm::dvec4 a = glm::dmat4(m.view_proj) * glm::dvec4(rel, 1.0);
    applyJitter(m, jitter, v.width, v.height);
    const glm::dvec4 b = glm::dmat4(m.view_proj) * glm::dvec4(rel, 1.0);
    const glm::dvec2 shift = pixels(b, v) - pixels(a, v);
    CHECK(shift.x == doctest::Approx(jitter.x).epsilon(1e-3));
    CHECK(shift.y == doctest::Approx(jitter.y).epsilon(1e-3));
    CHECK(b.z / b.w == doctest::Approx(a.z / a.w));  // depth unchanged
}

TEST_CASE("temporal: camera cuts are jumps or turns beyond the thresholds") {
    const ViewParams a{{100.0, 50.0, 100.0}, 10.0, -5.0, 60.0, 0.1, 320, 180};
    ViewParams b = a;
    b.position.x += 5.0;
    b.yaw_deg += 2.0;
    CHECK_FALSE(cameraCut(a, b, 100.0, 30.0));
    b.position.x += 200.0;
    CHECK(cameraCut(a, b, 100.0, 30.0));
    b = a;
    b.yaw_deg += 45.0;
    CHECK(cameraCut(a, b, 100.0, 30.0));
    b = a;
    b.pitch_deg = 60.0;
    CHECK(cameraCut(a, b, 100.0, 30.0));
    b = a;
    b.width = 640;
    CHECK(cameraCut(a, b, 100.0, 30.0));
}

TEST_CASE("temporal: reprojection of known points matches the CPU reference, near and 10,000 km from the origin") {
    for (const glm::dvec3 origin : {glm::dvec3(0.0), glm::dvec3(1.0e7, 200.0, -1.0e7)}) {
        CAPTURE(origin.x);
        const ViewParams prev{origin + glm::dvec3(0.0, 120.0, 0.0), 20.0, -8.0, 55.0, 0.1, 1920, 1080};
        const ViewParams cur{origin + glm::dvec3(3.25, 120.5, -7.125), 21.5, -7.25, 55.0, 0.1, 1920, 1080};
        for (const glm::dvec3 offset : {glm::dvec3(50.0, -20.0, -400.0), glm::dvec3(-300.0, 5.0, -2000.0),
                                        glm::dvec3(2.0, -1.0, -15.0), glm::dvec3(4000.0, 900.0, -30000.0)}) {
            const glm::dvec3 world = cur.position + offset;
            const glm::dvec2 expected = pixels(referenceClip(prev, world), prev);
            // The point relative to this camera, as the shaders see it.
            const glm::dvec2 got = pixels(reprojectPoint(prev, cur, world - cur.position), prev);
            CHECK(glm::length(got - expected) < 0.01);
            // The float matrix the clouds' shader gets, applied in float.
            const glm::mat4 m(previousClipFromRelative(prev, cur));
            const glm::vec4 c = m * glm::vec4(glm::vec3(world - cur.position), 1.0f);
            CHECK(glm::length(pixels(glm::dvec4(c), prev) - expected) < 0.05);
            // TAA's and motion blur's clip-to-clip matrix from this frame's depth.
            const glm::dvec4 clip = referenceClip(cur, world);
            const glm::mat4 rp(reprojectionMatrix(prev, cur));
            const glm::vec4 ndc(float(clip.x / clip.w), float(clip.y / clip.w), float(clip.z / clip.w), 1.0f);
            const glm::vec4 p = rp * ndc;
            CHECK(glm::length(pixels(glm::dvec4(p), prev) - expected) < 0.05);
        }
    }
}

TEST_CASE("blue noise: void-and-cluster ranks are a permutation with no low frequencies, white noise has them") {
    const int n = kBlueNoiseSize;
    const std::vector<std::uint32_t> ranks = voidAndClusterRanks(n);
    REQUIRE(ranks.size() == std::size_t(n * n));
    std::vector<std::uint32_t> sorted = ranks;
    std::sort(sorted.begin(), sorted.end());
    for (std::size_t i = 0; i < sorted.size(); ++i) REQUIRE(sorted[i] == i);
    CHECK(voidAndClusterRanks(n) == ranks);  // deterministic

    std::vector<double> blue(ranks.size()), white(ranks.size());
    std::mt19937 rng(7);
    for (std::size_t i = 0; i < ranks.size(); ++i) {
        blue[i] = (double(ranks[i]) + 0.5) / double(ranks.size());
        white[i] = double(rng()) / 4294967296.0;
    }
    const double blue_ratio = lowToHighPower(blue, n), white_ratio = lowToHighPower(white, n);
    INFO("low/high frequency power: blue " << blue_ratio << ", white " << white_ratio);
    CHECK(blue_ratio < 0.1);
    CHECK(white_ratio > 0.5);

    // Every threshold set is evenly spread: the 10 % lowest ranks keep at least 2 texels apart
    // (toroidal), where a random 10 % has neighbours.
    auto minDistance = [n](const std::vector<double>& field) {
        std::vector<int> pts;
        for (int i = 0; i < n * n; ++i)
            if (field[std::size_t(i)] < 0.1) pts.push_back(i);
        double best = 1e30;
        for (std::size_t a = 0; a < pts.size(); ++a)
            for (std::size_t b = a + 1; b < pts.size(); ++b) {
                int dx = std::abs(pts[a] % n - pts[b] % n), dy = std::abs(pts[a] / n - pts[b] / n);
                dx = std::min(dx, n - dx);
                dy = std::min(dy, n - dy);
                best = std::min(best, std::sqrt(double(dx * dx + dy * dy)));
            }
        return best;
    };
    CHECK(minDistance(blue) >= 2.0);
    CHECK(minDistance(white) < 2.0);
}
