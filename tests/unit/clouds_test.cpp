// Cloud maths on the CPU (sky/clouds/cloud_model.h): the noise's range and tiling, the shell
// intersection against brute-force marching, the wind at long run times, coverage over time,
// and which settings leave the clouds off.
#include "sky/clouds/cloud_model.h"

#include <doctest/doctest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <random>

using namespace vista;

TEST_CASE("clouds: value noise and fBm stay in [0, 1], reach most of it, and tile with the period") {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-300.0, 300.0);
    double lo = 1.0, hi = 0.0, fbm_lo = 1.0, fbm_hi = 0.0, worst_tile = 0.0;
    const double P = kCloudNoisePeriod;
    for (int i = 0; i < 20000; ++i) {
        const glm::dvec3 p(u(rng), u(rng) * 0.1, u(rng));
        const double n = cloudValueNoise(p, kCloudNoisePeriod, 7u);
        lo = std::min(lo, n), hi = std::max(hi, n);
        const double f = cloudFbm(p, 5, 7u);
        fbm_lo = std::min(fbm_lo, f), fbm_hi = std::max(fbm_hi, f);
        // Shifting by whole periods along any axis gives the same value (exactly: the lattice wraps).
        const glm::dvec3 shift(P * double(int(i % 3) - 1), P * double(i % 2), -P * double(i % 5));
        worst_tile = std::max(worst_tile, std::abs(cloudFbm(p + shift, 5, 7u) - f));
    }
    CHECK(lo >= 0.0);
    CHECK(hi <= 1.0);
    CHECK(lo < 0.05);  // the range is used, not a constant
    CHECK(hi > 0.95);
    CHECK(fbm_lo >= 0.0);
    CHECK(fbm_hi <= 1.0);
    CHECK(fbm_hi - fbm_lo > 0.5);
    CHECK(worst_tile < 1e-9);
    // Continuous across a lattice line, and different seeds give different patterns.
    const glm::dvec3 q(10.0, 3.0, 20.0);
    CHECK(std::abs(cloudValueNoise(q - glm::dvec3(1e-9, 0, 0), 64, 1u) - cloudValueNoise(q, 64, 1u)) < 1e-6);
    CHECK(cloudFbm(q + 0.37, 4, 1u) != cloudFbm(q + 0.37, 4, 2u));
    // At a lattice point the noise is the lattice value.
    CHECK(cloudValueNoise(q, 64, 3u) == doctest::Approx(cloudLattice(glm::ivec3(10, 3, 20), 64, 3u)).epsilon(1e-12));
}

namespace {

// The first stretch inside the shell by marching 1 m steps (ground included).
ShellSegment marched(double r, double mu, double ground, double rb, double rt, double t_max) {
    const glm::dvec3 o(0.0, r, 0.0), d(std::sqrt(std::max(1.0 - mu * mu, 0.0)), mu, 0.0);
    ShellSegment s;
    const double step = 1.0;
    for (double t = 0.0; t < t_max; t += step) {
        const double radius = glm::length(o + t * d);
        if (radius < ground) break;
        const bool inside = radius >= rb && radius <= rt;
        if (inside && !s.hit) {
            s.hit = true;
            s.t0 = t;
        }
        if (!inside && s.hit) {
            s.t1 = t;
            return s;
        }
        if (s.hit) s.t1 = t;
    }
    return s;
}

}  // namespace

TEST_CASE("clouds: shell intersection from below, inside, above and from orbit") {
    const double R = 6360e3, rb = R + 1500.0, rt = R + 2700.0;
    SUBCASE("below: straight up, at the horizon, down to the ground") {
        const double r = R + 100.0;
        ShellSegment s = cloudShellSegment(r, 1.0, R, rb, rt);
        REQUIRE(s.hit);
        CHECK(s.t0 == doctest::Approx(1400.0).epsilon(1e-9));
        CHECK(s.t1 == doctest::Approx(2600.0).epsilon(1e-9));
        s = cloudShellSegment(r, 0.0, R, rb, rt);
        REQUIRE(s.hit);
        CHECK(s.t0 == doctest::Approx(std::sqrt(rb * rb - r * r)).epsilon(1e-9));
        CHECK(s.t1 == doctest::Approx(std::sqrt(rt * rt - r * r)).epsilon(1e-9));
        CHECK_FALSE(cloudShellSegment(r, -0.5, R, rb, rt).hit);
    }
    SUBCASE("inside: up to the top, down to the bottom") {
        const double r = R + 2000.0;
        ShellSegment s = cloudShellSegment(r, 1.0, R, rb, rt);
        CHECK(s.t0 == 0.0);
        CHECK(s.t1 == doctest::Approx(700.0).epsilon(1e-9));
        s = cloudShellSegment(r, -1.0, R, rb, rt);
        CHECK(s.t0 == 0.0);
        CHECK(s.t1 == doctest::Approx(500.0).epsilon(1e-9));
    }
    SUBCASE("above: straight down, straight up (nothing)") {
        const double r = R + 10000.0;
        ShellSegment s = cloudShellSegment(r, -1.0, R, rb, rt);
        CHECK(s.t0 == doctest::Approx(7300.0).epsilon(1e-9));
        CHECK(s.t1 == doctest::Approx(8500.0).epsilon(1e-9));
        CHECK_FALSE(cloudShellSegment(r, 1.0, R, rb, rt).hit);
    }
    SUBCASE("from orbit: past the limb, grazing the shell only, and below the ground") {
        const double r = R + 400e3;
        const double mu_limb = -std::sqrt(1.0 - (rt / r) * (rt / r));
        CHECK_FALSE(cloudShellSegment(r, mu_limb + 1e-3, R, rb, rt).hit);
        // Between the tangents of the top and of the bottom the ray crosses the shell and leaves.
        const double mu_graze = -std::sqrt(1.0 - std::pow((rb + rt) / 2.0 / r, 2.0));
        ShellSegment s = cloudShellSegment(r, mu_graze, R, rb, rt);
        REQUIRE(s.hit);
        CHECK(s.t1 - s.t0 > 10000.0);  // a long chord through the shell
        CHECK_FALSE(cloudShellSegment(R - 50.0, 1.0, R, rb, rt).hit);  // under the ground
    }
    SUBCASE("random rays agree with marching to within the step") {
        std::mt19937 rng(11);
        std::uniform_real_distribution<double> mu_d(-1.0, 1.0), alt(-100.0, 5000.0);
        for (int i = 0; i < 200; ++i) {
            const double r = R + alt(rng), mu = mu_d(rng);
            const ShellSegment a = cloudShellSegment(r, mu, R, rb, rt);
            const ShellSegment b = marched(r, mu, R, rb, rt, 400e3);
            CAPTURE(r - R);
            CAPTURE(mu);
            REQUIRE(a.hit == b.hit);
            if (!a.hit) continue;
            CHECK(std::abs(a.t0 - b.t0) <= 1.01);
            CHECK(std::abs(a.t1 - b.t1) <= 1.01);
        }
    }
}

TEST_CASE("clouds: the wind at t = 1e7 s moves like at t = 10 s, and the noise origin stays exact") {
    CloudLayerSettings layer;
    layer.wind_speed = 12.0f;
    layer.wind_gust = 0.5f;
    layer.scale_m = 2500.0f;
    const double speed = layer.wind_speed, gust = layer.wind_gust;
    auto stats = [&](double t_start, double& mean, double& spread) {
        double sum = 0.0, sum2 = 0.0;
        const int n = 2000;
        for (int i = 0; i < n; ++i) {
            const double t = t_start + i * 0.5;
            const glm::dvec2 v = (cloudWindOffset(layer, t + 0.5) - cloudWindOffset(layer, t)) / 0.5;
            REQUIRE(std::isfinite(v.x));
            REQUIRE(std::isfinite(v.y));
            const double s = glm::length(v);
            // Never faster than the mean plus the largest gust (3 / 2 of the knots' spread of 2).
            CHECK(s <= speed * (1.0 + 3.0 * std::sqrt(2.0) * gust) + 1e-6);
            sum += s;
            sum2 += s * s;
        }
        mean = sum / n;
        spread = std::sqrt(std::max(sum2 / n - mean * mean, 0.0));
    };
    double m0 = 0, s0 = 0, m1 = 0, s1 = 0;
    stats(10.0, m0, s0);
    stats(1e7, m1, s1);
    CHECK(m0 > 0.3 * speed);
    CHECK(m1 > 0.3 * speed);
    CHECK(m1 == doctest::Approx(m0).epsilon(0.5));
    CHECK(s1 > 0.0);  // the wind wanders at long times too
    // The finite difference is the analytic velocity.
    for (double t : {10.0, 1e7 + 3.3}) {
        const glm::dvec2 fd = (cloudWindOffset(layer, t + 1e-3) - cloudWindOffset(layer, t - 1e-3)) / 2e-3;
        CHECK(glm::length(fd - cloudWindVelocity(layer, t)) < 1e-3 * speed);
    }
    // The wrapped origin is in [0, period) and moves by v dt / scale between frames at any time.
    for (double t : {10.0, 1e5, 1e7, 1e9}) {
        const glm::dvec2 cam(1.0e7, -3.0e6);
        const glm::dvec2 a = cloudNoiseOrigin(layer, cam, t), b = cloudNoiseOrigin(layer, cam, t + 1.0 / 60.0);
        CHECK(a.x >= 0.0);
        CHECK(a.x < kCloudNoisePeriod);
        CHECK(a.y >= 0.0);
        CHECK(a.y < kCloudNoisePeriod);
        glm::dvec2 d = b - a;
        for (double* c : {&d.x, &d.y}) *c -= kCloudNoisePeriod * std::round(*c / kCloudNoisePeriod);
        const glm::dvec2 expected = -(cloudWindOffset(layer, t + 1.0 / 60.0) - cloudWindOffset(layer, t)) / double(layer.scale_m);
        CAPTURE(t);
        CHECK(glm::length(d - expected) < 1e-6);
        CHECK(glm::length(d) > 0.0);
    }
}

TEST_CASE("clouds: coverage swings over its period and stays in [0, 1], and which settings draw clouds") {
    CloudsSettings c;
    c.coverage_variation = 0.2f;
    c.coverage_period_s = 100.0f;
    CloudLayerSettings l;
    l.coverage = 0.5f;
    CHECK(cloudCoverage(l, c, 0.0) == doctest::Approx(0.5));
    CHECK(cloudCoverage(l, c, 25.0) == doctest::Approx(0.7));
    CHECK(cloudCoverage(l, c, 75.0) == doctest::Approx(0.3));
    CHECK(cloudCoverage(l, c, 1e7 + 25.0) == doctest::Approx(0.7).epsilon(1e-6));
    l.coverage = 0.95f;
    CHECK(cloudCoverage(l, c, 25.0) == 1.0);
    CHECK(cloudsActive(c));
    c.low.coverage = 0.0f;
    CHECK(cloudsActive(c));  // the high layer still draws
    c.high.enabled = false;
    CHECK_FALSE(cloudsActive(c));
    c.high.enabled = true;
    c.high.density = 0.0f;
    CHECK_FALSE(cloudsActive(c));
    c.high.density = 0.01f;
    c.enabled = false;
    CHECK_FALSE(cloudsActive(c));
}
