// Weather maths on the CPU (sky/weather/weather_model.h): drops placed per field cell of the box around
// the camera, deterministic, falling with the wind, the same 10,000 km out at t = 10^7 s;
// visible-cell culling keeps every drop in view; splash cycles; wetness; the ripple normals.
#include "config/ini.h"
#include "renderer/camera.h"
#include "sky/clouds/cloud_model.h"
#include "sky/weather/weather_model.h"

#include <doctest/doctest.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <tuple>

using namespace vista;

namespace {

using CellKey = std::tuple<std::uint32_t, std::uint32_t, std::uint32_t, int>;

// World position of every drop of the box, keyed by (field cell, j).
std::map<CellKey, glm::dvec3> dropsOf(const WeatherSettings& s, const CloudsSettings& clouds, const glm::dvec3& eye, double t) {
    const DropLayout l = dropLayout(s);
    const DropFrame f = dropFrame(l, eye, dropFieldOffset(s, clouds, t), t);
    std::map<CellKey, glm::dvec3> out;
    for (int z = 0; z < l.cells; ++z)
        for (int y = 0; y < l.cells; ++y)
            for (int x = 0; x < l.cells; ++x)
                for (int j = 0; j < l.drops_per_cell; ++j) {
                    const Drop d = dropAt(l, f, {x, y, z}, j);
                    out[{std::uint32_t(d.cell.x), std::uint32_t(d.cell.y), std::uint32_t(d.cell.z), j}] = d.rel;
                }
    return out;
}

WeatherSettings rain() {
    WeatherSettings s;
    s.enabled = true;
    s.radius_m = 6.0f;
    s.cell_m = 2.0f;
    s.max_density = 1.0f;  // 8 per cell
    s.wind_from_clouds = false;
    s.wind_speed_m_s = 3.0f;
    s.wind_direction_deg = 90.0f;  // toward +x
    return s;
}

}  // namespace

TEST_CASE("weather: the box holds each cell once, covers the radius, and drops keep their world place as the camera moves") {
    const WeatherSettings s = rain();
    const CloudsSettings clouds;
    const DropLayout l = dropLayout(s);
    CHECK(l.cells == 7);
    CHECK(l.drops_per_cell == 8);
    for (const glm::dvec3 eye : {glm::dvec3(0.3, 10.0, -0.7), glm::dvec3(1.0e7 + 0.25, 120.0, -1.0e7 - 3.5)}) {
        const double t = 12.5;
        const auto a = dropsOf(s, clouds, eye, t);
        CHECK(a.size() == std::size_t(l.candidates()));  // every cell once
        // Every drop lies in the box, and every point within the radius is inside the box.
        for (const auto& [key, rel] : a) {
            CHECK(std::abs(rel.x) <= (l.half + 1) * l.cell_m);
            CHECK(std::abs(rel.y) <= (l.half + 1) * l.cell_m);
        }
        const DropFrame f = dropFrame(l, eye, dropFieldOffset(s, clouds, t), t);
        for (int a_ = 0; a_ < 3; ++a_) {
            const double lo = (-l.half - f.frac[a_]) * l.cell_m, hi = (l.half + 1 - f.frac[a_]) * l.cell_m;
            CHECK(lo <= -s.radius_m);
            CHECK(hi >= s.radius_m);
        }
        // Moving the camera by less than a cell and by several cells: the drops of the cells
        // both boxes hold stay where they were in the world.
        for (const glm::dvec3 step : {glm::dvec3(0.7, -0.2, 0.4), glm::dvec3(-5.1, 3.3, 4.9)}) {
            const auto b = dropsOf(s, clouds, eye + step, t);
            int shared = 0;
            double worst = 0.0;
            for (const auto& [key, rel] : a) {
                auto it = b.find(key);
                if (it == b.end()) continue;
                ++shared;
                worst = std::max(worst, glm::length((eye + rel) - (eye + step + it->second)));
            }
            CHECK(shared > l.candidates() / 10);
            CHECK(worst < 1e-5);  // float camera fraction: about 1e-7 of a cell
        }
    }
}

TEST_CASE("weather: drops fall with the wind, the same 10,000 km out and after 10^7 s") {
    const WeatherSettings s = rain();
    const CloudsSettings clouds;
    const double dt = 0.05;
    const glm::dvec3 expected(3.0 * dt, -s.drop_speed_m_s * dt, 0.0);
    for (const auto& [eye, t] : {std::pair{glm::dvec3(0.0, 5.0, 0.0), 3.0}, std::pair{glm::dvec3(1.0e7, 50.0, 1.0e7), 1.0e7}}) {
        const auto a = dropsOf(s, clouds, eye, t), b = dropsOf(s, clouds, eye, t + dt);
        int shared = 0;
        double worst = 0.0;
        for (const auto& [key, rel] : a) {
            auto it = b.find(key);
            if (it == b.end()) continue;
            ++shared;
            CHECK(std::isfinite(rel.x + rel.y + rel.z));
            worst = std::max(worst, glm::length((it->second - rel) - expected));
        }
        INFO("t = " << t);
        CHECK(shared > a.size() / 2);
        CHECK(worst < 1e-5);
    }
    // The same pattern at the origin and far out: the drops' spread and count within the radius.
    auto inside = [&](const glm::dvec3& eye, double t) {
        int n = 0;
        for (const auto& [key, rel] : dropsOf(s, clouds, eye, t)) n += glm::length(rel) < s.radius_m;
        return n;
    };
    const int near_origin = inside({0.0, 5.0, 0.0}, 0.0), far_out = inside({1.0e7, 5.0, -1.0e7}, 1.0e7);
    const double expected_count = 4.0 / 3.0 * 3.141592653589793 * 216.0 * s.max_density;  // 905
    CHECK(std::abs(near_origin - expected_count) < 0.15 * expected_count);
    CHECK(std::abs(far_out - expected_count) < 0.15 * expected_count);
}

TEST_CASE("weather: the same field cell always holds the same drops, and intensity only adds drops") {
    WeatherSettings s = rain();
    const DropLayout l = dropLayout(s);
    const DropFrame f{};
    const Drop a = dropAt(l, f, {2, 3, 4}, 5), b = dropAt(l, f, {2, 3, 4}, 5), c = dropAt(l, f, {2, 3, 4}, 6);
    CHECK(a.rel == b.rel);
    CHECK(a.keep == b.keep);
    CHECK(a.rel != c.rel);
    // Drop j is kept while j + keep < intensity x drops per cell: the kept set grows with it.
    int previous = 0;
    for (float intensity : {0.0f, 0.2f, 0.5f, 0.9f, 1.0f}) {
        int kept = 0;
        for (int j = 0; j < l.drops_per_cell; ++j) {
            const Drop d = dropAt(l, f, {1, 1, 1}, j);
            const bool k = float(j) + d.keep < intensity * float(l.drops_per_cell);
            kept += k;
            if (k) CHECK(j < dropsDrawnPerCell(l, intensity));
        }
        CHECK(kept >= previous);
        previous = kept;
    }
    CHECK(previous == l.drops_per_cell);
    CHECK(dropsDrawnPerCell(l, 0.0f) == 0);
    CHECK(dropsDrawnPerCell(l, 1.0f) == l.drops_per_cell);
    s.max_density = 50.0f;
    s.cell_m = 8.0f;
    CHECK(dropLayout(s).drops_per_cell == kMaxDropsPerCell);
}

TEST_CASE("weather: visible cells hold every drop within the radius that the view frustum sees") {
    const WeatherSettings s = rain();
    const CloudsSettings clouds;
    const DropLayout l = dropLayout(s);
    const glm::dvec3 eye(3.3, 20.0, -7.9);
    const DropFrame f = dropFrame(l, eye, dropFieldOffset(s, clouds, 4.0), 4.0);
    ViewParams v;
    v.yaw_deg = 20.0;
    v.pitch_deg = -15.0;
    v.width = 640;
    v.height = 360;
    const glm::dmat4 vp(viewMatrices(v).view_proj);
    const Frustum planes = frustumFromViewProj(vp);
    std::vector<std::uint32_t> cells;
    visibleDropCells(l, f, planes, s.radius_m, 0.0, cells);
    const std::set<std::uint32_t> listed(cells.begin(), cells.end());
    CHECK(listed.size() == cells.size());
    CHECK(cells.size() < std::size_t(l.cells * l.cells * l.cells) / 3);  // the view sees a part of the box
    int seen = 0;
    for (int z = 0; z < l.cells; ++z)
        for (int y = 0; y < l.cells; ++y)
            for (int x = 0; x < l.cells; ++x)
                for (int j = 0; j < l.drops_per_cell; ++j) {
                    const Drop d = dropAt(l, f, {x, y, z}, j);
                    const glm::dvec4 clip = vp * glm::dvec4(d.rel, 1.0);
                    const bool in_view = clip.w > 0.0 && std::abs(clip.x) < clip.w && std::abs(clip.y) < clip.w;
                    if (!in_view || glm::length(d.rel) >= s.radius_m) continue;
                    ++seen;
                    CHECK(listed.count(packDropCell({x, y, z}, l.cells)) == 1);
                }
    CHECK(seen > 50);
}

TEST_CASE("weather: wind from the clouds follows the low layer, and its offset is the integral of its velocity at 10^7 s") {
    WeatherSettings s = rain();
    s.wind_from_clouds = true;
    s.wind_scale = 0.5f;
    CloudsSettings clouds;
    for (double t : {10.0, 1.0e7}) {
        const glm::dvec2 v = weatherWindVelocity(s, clouds, t);
        CHECK(glm::length(v - 0.5 * cloudWindVelocity(clouds.low, t)) < 1e-12);
        const double h = 0.01;
        const glm::dvec2 numeric = (weatherWindOffset(s, clouds, t + h) - weatherWindOffset(s, clouds, t - h)) / (2.0 * h);
        CHECK(glm::length(numeric - v) < 1e-4);
    }
    s.wind_from_clouds = false;
    const glm::dvec2 fixed = weatherWindVelocity(s, clouds, 5.0);
    CHECK(fixed.x == doctest::Approx(3.0));
    CHECK(std::abs(fixed.y) < 1e-12);
}

TEST_CASE("weather: splashes cycle once per period at hashed places, with the rate asked for, also at 10^7 s") {
    WeatherSettings s = rain();
    s.splash_rate = 40.0f;
    s.splash_life_s = 0.1f;
    s.splash_radius_m = 5.0f;
    s.intensity = 0.5f;
    const SplashLayout l = splashLayout(s);
    CHECK(l.period_s == doctest::Approx(0.4));
    CHECK(l.slots == 16);
    CHECK(splashFill(l, s) == doctest::Approx(1.0));
    CHECK(splashesKept(l, s) == doctest::Approx(8.0));
    for (double t0 : {2.0, 1.0e7}) {
        const glm::dvec2 eye(1.0e7 + 0.3, -1.0e7 + 0.6);
        const SplashFrame a = splashFrame(l, eye, t0), b = splashFrame(l, eye, t0 + l.period_s);
        const SplashFrame c = splashFrame(l, eye, t0 + 0.01);
        int visible = 0, total = 0;
        for (int z = 0; z < l.cells; ++z)
            for (int x = 0; x < l.cells; ++x)
                for (int j = 0; j < l.slots; ++j) {
                    const Splash sa = splashAt(l, a, {x, z}, j), sb = splashAt(l, b, {x, z}, j), sc = splashAt(l, c, {x, z}, j);
                    CHECK(sb.cycle == sa.cycle + 1);  // one period later: the next splash of the slot
                    CHECK(std::abs(sb.age - sa.age) < 2e-4);
                    if (sa.cycle == sc.cycle) {
                        CHECK(sc.age - sa.age == doctest::Approx(0.01 / l.period_s).epsilon(0.01));
                        CHECK(glm::length(sc.rel_xz - sa.rel_xz) < 1e-6);  // a splash stays where it started
                    }
                    CHECK(std::abs(sa.rel_xz.x) <= (l.half + 1) * kSplashCellM);
                    ++total;
                    visible += sa.age < 0.25f && float(j) + sa.keep < splashesKept(l, s);
                }
        // A quarter of the period each, half the slots kept at intensity 0.5.
        const double share = double(visible) / total;
        INFO("t0 = " << t0);
        CHECK(share == doctest::Approx(0.125).epsilon(0.2));
    }
}

TEST_CASE("weather: the terrain is wet only while it rains, by intensity") {
    WeatherSettings s;
    CHECK(weatherWetness(s) == 0.0f);  // off by default
    s.enabled = true;
    s.wetness = 0.8f;
    s.intensity = 0.25f;
    CHECK(weatherWetness(s) == doctest::Approx(0.4f));
    s.intensity = 1.0f;
    CHECK(weatherWetness(s) == doctest::Approx(0.8f));
    s.kind = WeatherKind::Snow;
    CHECK(weatherWetness(s) == 0.0f);
}

TEST_CASE("weather: rain ripple normals are unit, flat without rain, periodic in the wrap, continuous in time") {
    for (double x = 0.013; x < 4.0; x += 0.0517)
        CHECK(rainRippleNormal({x, 1.7 * x}, 3.3, 0.0) == glm::dvec3(0.0, 1.0, 0.0));
    double tilted = 0.0, worst_jump = 0.0, worst_wrap = 0.0;
    int samples = 0;
    for (double z = 0.011; z < 3.0; z += 0.037)
        for (double x = 0.007; x < 3.0; x += 0.041) {
            for (double t : {0.2, 4.9, 7.95}) {
                const glm::dvec3 n = rainRippleNormal({x, z}, t, 1.0);
                CHECK(std::abs(glm::length(n) - 1.0) < 1e-12);
                CHECK(n.y > 0.0);
                tilted = std::max(tilted, std::sqrt(n.x * n.x + n.z * n.z));
                // Periodic: the same normal one wrap further in x/z, and in time.
                worst_wrap = std::max(worst_wrap, glm::length(n - rainRippleNormal({x + kRippleWrapM, z - kRippleWrapM}, t, 1.0)));
                const glm::dvec3 n_later = rainRippleNormal({x, z}, t + 1e-4, 1.0);
                worst_jump = std::max(worst_jump, glm::length(n_later - n));
                ++samples;
            }
            // Across the time wrap: t just below 8 s and just above 0 s meet.
            worst_wrap = std::max(worst_wrap, glm::length(rainRippleNormal({x, z}, kRippleWrapS - 1e-9, 1.0) -
                                                          rainRippleNormal({x, z}, 0.0, 1.0)));
        }
    CHECK(tilted > 0.1);         // the rings show
    CHECK(worst_wrap < 1e-6);
    CHECK(worst_jump < 0.05);    // no ring pops in or out
    const RippleInput w = rainRippleWrap({1.0e7 + 1.25, -1.0e7 - 0.5}, 1.0e7 + 0.75);
    CHECK(w.xz.x == doctest::Approx(std::fmod(1.0e7 + 1.25, 32.0)));
    CHECK(w.xz.y == doctest::Approx(32.0 - std::fmod(1.0e7 + 0.5, 32.0)));
    CHECK(w.time == doctest::Approx(std::fmod(1.0e7 + 0.75, 8.0)));
}

TEST_CASE("weather: [weather] is off by default and loads from a scene file") {
    Settings s;
    CHECK_FALSE(s.weather.enabled);
    const InputErrors errors = loadIniString("[weather]\nenabled = true\nkind = snow\nintensity = 0.3\n", "w.ini", s);
    CHECK(errors.empty());
    CHECK(s.weather.enabled);
    CHECK(s.weather.kind == WeatherKind::Snow);
    CHECK(s.weather.intensity == doctest::Approx(0.3f));
    Settings t;
    const InputErrors bad = loadIniString("[weather]\nintensity = 2\n", "w.ini", t);
    REQUIRE(bad.size() == 1);
    CHECK(bad[0].line == 2);
}
