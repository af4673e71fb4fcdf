// The sea's waves on the CPU (terrain/water/waves.h): the Pierson-Moskowitz integral against numerical
// quadrature and its closed-form wave height, the wave set carrying the spectrum's variance,
// Gerstner's closed form for one wave, normals and Jacobians against finite differences, crests
// that never fold, the footprint filter, phases packed for the GPU exact 10^7 s in and
// 10,000 km out, and the ring grid's reach.
#include "terrain/water/water.h"
#include "terrain/water/waves.h"

#include <doctest/doctest.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>
#include <random>

using namespace vista;

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// Composite Simpson on [a, b] with n (even) intervals.
template <class F>
double simpson(F f, double a, double b, int n) {
    const double h = (b - a) / n;
    double sum = f(a) + f(b);
    for (int i = 1; i < n; ++i) sum += f(a + i * h) * (i % 2 ? 4.0 : 2.0);
    return sum * h / 3.0;
}

glm::dvec3 surfacePoint(const WaveSet& set, glm::dvec2 x0, double t) {
    const WaveSample s = evaluateWaves(set, x0, t);
    return glm::dvec3(x0.x, 0.0, x0.y) + s.displacement;
}

double angleDiff(double a, double b) {
    double d = std::fmod(a - b, kTwoPi);
    if (d > std::numbers::pi) d -= kTwoPi;
    if (d < -std::numbers::pi) d += kTwoPi;
    return std::abs(d);
}

}  // namespace

TEST_CASE("water: the Pierson-Moskowitz integral matches quadrature and gives Hs = 0.22 U^2 / g") {
    for (double wind : {2.0, 6.0, 15.0}) {
        CAPTURE(wind);
        const double wp = peakAngularFrequency(wind);
        for (auto [lo, hi] : {std::pair{0.5 * wp, 1.5 * wp}, std::pair{wp, 4.0 * wp}, std::pair{0.2 * wp, 0.9 * wp}}) {
            const double numeric = simpson([wp](double w) { return piersonMoskowitz(w, wp); }, lo, hi, 4000);
            CHECK(piersonMoskowitzIntegral(lo, hi, wp) == doctest::Approx(numeric).epsilon(1e-7));
        }
        const double m0 = piersonMoskowitzIntegral(0.0, 1e9, wp);
        CHECK(4.0 * std::sqrt(m0) == doctest::Approx(0.2203 * wind * wind / kGravity).epsilon(2e-3));
    }
}

TEST_CASE("water: the wave set carries the spectrum's height variance over its band, longest wave first") {
    WaterSettings s;
    const WaveSet set = makeWaves(s);
    REQUIRE(set.waves.size() == std::size_t(s.waves));
    double variance = 0.0, max_height = 0.0;
    for (std::size_t i = 0; i < set.waves.size(); ++i) {
        const GerstnerWave& w = set.waves[i];
        variance += 0.5 * w.amplitude * w.amplitude;
        max_height += w.amplitude;
        CHECK(w.angular_frequency == doctest::Approx(std::sqrt(kGravity * w.wavenumber)));
        CHECK(glm::length(w.direction) == doctest::Approx(1.0));
        CHECK(w.phase >= 0.0);
        CHECK(w.phase < kTwoPi);
        if (i > 0) CHECK(w.wavenumber > set.waves[i - 1].wavenumber);
    }
    const double wp = set.peak_angular_frequency;
    CHECK(variance == doctest::Approx(piersonMoskowitzIntegral(set.band_low, set.band_high, wp)).epsilon(1e-9));
    // The band from 4 peak wavelengths to 0.25 m holds nearly all of the sea's variance.
    CHECK(variance > 0.97 * piersonMoskowitzIntegral(0.0, 1e9, wp));
    CHECK(set.max_height == doctest::Approx(max_height));
    CHECK(kTwoPi / set.waves.front().wavenumber == doctest::Approx(4.0 * kTwoPi * kGravity / (wp * wp)));
    CHECK(kTwoPi / set.waves.back().wavenumber == doctest::Approx(s.min_wavelength_m).epsilon(1e-6));
    // The longest wave goes with the wind: 60 deg clockwise from -z.
    const double a = 60.0 * std::numbers::pi / 180.0;
    CHECK(set.waves.front().direction.x == doctest::Approx(std::sin(a)));
    CHECK(set.waves.front().direction.y == doctest::Approx(-std::cos(a)));
    // Amplitudes scale linearly, deterministic.
    WaterSettings twice = s;
    twice.amplitude_scale = 2.0f;
    const WaveSet set2 = makeWaves(twice);
    for (std::size_t i = 0; i < set.waves.size(); ++i) {
        CHECK(set2.waves[i].amplitude == doctest::Approx(2.0 * set.waves[i].amplitude));
        CHECK(makeWaves(s).waves[i].phase == set.waves[i].phase);
    }
}

TEST_CASE("water: one Gerstner wave is the closed-form trochoid") {
    WaterSettings s;
    s.waves = 1;
    s.choppiness = 0.5f;
    const WaveSet set = makeWaves(s);
    REQUIRE(set.waves.size() == 1);
    const GerstnerWave& w = set.waves[0];
    CHECK(w.chop == doctest::Approx(0.5 * w.amplitude));
    for (double t : {0.0, 3.7, 1234.5}) {
        for (glm::dvec2 x0 : {glm::dvec2(0.0), glm::dvec2(12.0, -7.0), glm::dvec2(-300.0, 41.0)}) {
            const double theta = w.wavenumber * glm::dot(w.direction, x0) - w.angular_frequency * t + w.phase;
            const WaveSample ws = evaluateWaves(set, x0, t);
            CHECK(ws.displacement.x == doctest::Approx(-w.chop * w.direction.x * std::sin(theta)));
            CHECK(ws.displacement.y == doctest::Approx(w.amplitude * std::cos(theta)));
            CHECK(ws.displacement.z == doctest::Approx(-w.chop * w.direction.y * std::sin(theta)));
            // The squeeze along the wave: 1 - k c cos(theta).
            CHECK(ws.jacobian == doctest::Approx(1.0 - w.wavenumber * w.chop * std::cos(theta)));
        }
    }
    // Travels at the deep-water phase speed: the same crest a period later is one wavelength on.
    const double period = kTwoPi / w.angular_frequency, lambda = kTwoPi / w.wavenumber;
    const glm::dvec2 x0(5.0, 9.0);
    CHECK(evaluateWaves(set, x0 + w.direction * lambda, period).displacement.y ==
          doctest::Approx(evaluateWaves(set, x0, 0.0).displacement.y).epsilon(1e-9));
}

TEST_CASE("water: normals and Jacobians match finite differences, crests never fold") {
    WaterSettings s;
    s.choppiness = 2.0f;  // asks for more than the cap allows
    s.wind_speed_m_s = 12.0f;
    const WaveSet set = makeWaves(s);
    double squeeze = 0.0;
    for (const GerstnerWave& w : set.waves) squeeze += w.wavenumber * w.chop;
    CHECK(squeeze == doctest::Approx(kMaxSqueeze));
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> pos(-500.0, 500.0), time(0.0, 1000.0);
    double min_jacobian = 1e9;
    for (int i = 0; i < 200; ++i) {
        const glm::dvec2 x0(pos(rng), pos(rng));
        const double t = time(rng);
        const WaveSample ws = evaluateWaves(set, x0, t);
        const double h = 1e-4;
        const glm::dvec3 dx = (surfacePoint(set, x0 + glm::dvec2(h, 0), t) - surfacePoint(set, x0 - glm::dvec2(h, 0), t)) / (2 * h);
        const glm::dvec3 dz = (surfacePoint(set, x0 + glm::dvec2(0, h), t) - surfacePoint(set, x0 - glm::dvec2(0, h), t)) / (2 * h);
        const glm::dvec3 n = glm::normalize(glm::cross(dz, dx));
        CHECK(glm::length(ws.normal) == doctest::Approx(1.0));
        CHECK(glm::dot(n, ws.normal) > 1.0 - 1e-6);
        CHECK(ws.normal.y > 0.0);
        CHECK(ws.jacobian == doctest::Approx(dx.x * dz.z - dx.z * dz.x).epsilon(1e-5));
        CHECK(ws.jacobian >= 1.0 - kMaxSqueeze - 1e-9);
        CHECK(std::abs(ws.displacement.y) <= set.max_height);
        min_jacobian = std::min(min_jacobian, ws.jacobian);
    }
    CHECK(min_jacobian < 0.8);  // the test sees squeezed crests (all waves in phase would reach 1 - 0.9)
}

TEST_CASE("water: the footprint filter keeps long waves, removes short ones and keeps their slope variance") {
    CHECK(waveFootprintWeight(kTwoPi / 8.0, 1.0) == doctest::Approx(1.0));   // 8 footprints
    CHECK(waveFootprintWeight(kTwoPi / 100.0, 1.0) == doctest::Approx(1.0));
    CHECK(waveFootprintWeight(kTwoPi / 4.0, 1.0) == doctest::Approx(0.0));   // 4 footprints
    CHECK(waveFootprintWeight(kTwoPi / 6.0, 1.0) > 0.0);
    CHECK(waveFootprintWeight(kTwoPi / 6.0, 1.0) < 1.0);
    double previous = 1.0;
    for (double f = 0.0; f < 3.0; f += 0.01) {
        const double w = waveFootprintWeight(1.0, f);
        CHECK(w <= previous);
        previous = w;
    }
    const WaveSet set = makeWaves(WaterSettings{});
    double total = 0.0;
    for (const GerstnerWave& w : set.waves) total += 0.5 * (w.amplitude * w.wavenumber) * (w.amplitude * w.wavenumber);
    const WaveSample far = evaluateWaves(set, {10.0, 20.0}, 5.0, 1e6);
    CHECK(far.displacement == glm::dvec3(0.0));
    CHECK(far.normal.y == doctest::Approx(1.0));
    CHECK(far.lost_slope_variance == doctest::Approx(total));
    CHECK(evaluateWaves(set, {10.0, 20.0}, 5.0).lost_slope_variance == 0.0);
}

TEST_CASE("water: waves are finite 10^7 s in and 10,000 km out, and the GPU's packed phases stay exact there") {
    const WaveSet set = makeWaves(WaterSettings{});
    for (double t : {0.0, 10.0, 1e7}) {
        for (glm::dvec2 origin : {glm::dvec2(0.0), glm::dvec2(1e7, -1e7), glm::dvec2(-3.3e6, 8.1e6)}) {
            CAPTURE(t);
            CAPTURE(origin.x);
            std::vector<glm::vec4> a, b;
            packWaves(set, origin, t, a, b);
            REQUIRE(a.size() == set.waves.size());
            for (const glm::dvec2 offset : {glm::dvec2(0.0), glm::dvec2(3.5, -2.25), glm::dvec2(-120.0, 77.0)}) {
                const glm::dvec2 x0 = origin + offset;
                const WaveSample ws = evaluateWaves(set, x0, t);
                CHECK(std::isfinite(ws.displacement.x + ws.displacement.y + ws.displacement.z));
                CHECK(std::isfinite(ws.normal.x + ws.normal.y + ws.normal.z + ws.jacobian));
                CHECK(std::abs(ws.displacement.y) <= set.max_height);
                for (std::size_t i = 0; i < set.waves.size(); ++i) {
                    const GerstnerWave& w = set.waves[i];
                    // What the shader computes, in float: k d . (x0 - origin) + theta_0.
                    const float gpu = a[i].z * (a[i].x * float(offset.x) + a[i].y * float(offset.y)) + b[i].y;
                    const double exact = w.wavenumber * glm::dot(w.direction, x0) - w.angular_frequency * t + w.phase;
                    CHECK(b[i].y >= 0.0f);
                    CHECK(b[i].y < float(kTwoPi) + 1e-6f);
                    CHECK(angleDiff(double(gpu), exact) < 2e-3);
                }
            }
        }
    }
}

TEST_CASE("water: the ring grid reaches max_distance_m with cells growing with height and distance") {
    WaterSettings s;
    for (double h : {0.0, 2.0, 260.0, 5000.0}) {
        CAPTURE(h);
        const WaterGrid g = waterGrid(s, h);
        CHECK(g.segments == s.grid_segments);
        CHECK(g.angle == doctest::Approx(kTwoPi / s.grid_segments));
        const double cell = g.ring_constant * g.angle;  // radial step of the first ring
        CHECK(cell == doctest::Approx(std::max(double(s.grid_cell_m), 0.01 * h)));
        auto radius = [&](int j) { return g.ring_constant * std::expm1(g.angle * j); };
        CHECK(radius(g.rings) >= s.max_distance_m);
        CHECK(radius(g.rings - 1) < s.max_distance_m);
        // Cells about square: the radial step at a ring is its arc per segment (to the first order).
        const double r = radius(100), step = radius(101) - r;
        CHECK(step == doctest::Approx((r + g.ring_constant) * g.angle).epsilon(0.03));
    }
    CHECK(waterGrid(s, -40.0).ring_constant == waterGrid(s, 40.0).ring_constant);  // below the surface too
}
