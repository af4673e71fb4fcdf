// Grass placement and wind on the CPU (terrain/grass/grass_placement.h, terrain/material_weights.h):
// the integer toroidal wrap against 001's formula, deterministic per-cell placement, the box
// covering the view, grass only where the terrain draws grass, length-keeping bends, and wind
// that stays finite and equally strong after 10^7 s.
#include "terrain/grass/grass_placement.h"
#include "terrain/material_weights.h"

#include <doctest/doctest.h>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>
#include <map>
#include <set>
#include <tuple>
#include <vector>

using namespace vista;

namespace {

struct Placed {
    glm::dvec2 xz;
    float facing;
    bool operator<(const Placed& o) const { return std::tie(xz.x, xz.y, facing) < std::tie(o.xz.x, o.xz.y, o.facing); }
};

// Every candidate the box shows for a camera, keyed by world cell and blade index.
std::map<std::tuple<int, int, int>, Placed> placeAll(const GrassSettings& s, glm::dvec2 eye, glm::dvec3 forward) {
    GrassLayout l = grassLayout(s);
    glm::ivec2 box = grassBoxMin(l, eye, forward);
    std::map<std::tuple<int, int, int>, Placed> out;
    for (int z = 0; z < l.cells; ++z)
        for (int x = 0; x < l.cells; ++x) {
            glm::ivec2 cell = grassWrapCell({x, z}, box, l.cells);
            for (int j = 0; j < l.blades_per_cell; ++j) {
                GrassCandidate c = grassCandidate(l, cell, j, s);
                out[{cell.x, cell.y, j}] = Placed{c.world_xz, c.facing};
            }
        }
    return out;
}

glm::dvec3 forwardOf(double yaw_deg, double pitch_deg) {
    double y = glm::radians(yaw_deg), p = glm::radians(pitch_deg);
    return {std::sin(y) * std::cos(p), std::sin(p), -std::cos(y) * std::cos(p)};
}

}  // namespace

TEST_CASE("grass: the integer wrap keeps every slot in the box, once each, as 001's formula does") {
    for (int cells : {1, 2, 7, 31, 64}) {
        for (glm::ivec2 box : {glm::ivec2(0, 0), glm::ivec2(-5, 3), glm::ivec2(-40000001, 39999990), glm::ivec2(123, -77)}) {
            std::set<std::pair<int, int>> seen;
            for (int z = 0; z < cells; ++z)
                for (int x = 0; x < cells; ++x) {
                    glm::ivec2 n = grassWrapCell({x, z}, box, cells);
                    REQUIRE(n.x >= box.x);
                    REQUIRE(n.x < box.x + cells);
                    REQUIRE(n.y >= box.y);
                    REQUIRE(n.y < box.y + cells);
                    CHECK(((n.x - x) % cells + cells) % cells == 0);  // same slot, shifted by whole boxes
                    seen.insert({n.x, n.y});
                    // 001: p' = p + size * ceil((eye - p) / size - 0.5) with the box centre as eye.
                    CHECK(grassWrapSource(double(x), box.x + cells * 0.5, cells) == doctest::Approx(n.x));
                    CHECK(grassWrapSource(double(z), box.y + cells * 0.5, cells) == doctest::Approx(n.y));
                }
            CHECK(seen.size() == std::size_t(cells) * std::size_t(cells));
        }
    }
}

TEST_CASE("grass: placement is deterministic and the same after moving away and back") {
    GrassSettings s;
    s.radius_m = 12.0f;
    s.density = 6.0f;
    const glm::dvec2 a{1234.5, -987.25}, b{1234.5 + 5000.0, -987.25 - 3000.0};
    auto first = placeAll(s, a, forwardOf(30, -5));
    auto away = placeAll(s, b, forwardOf(200, -5));
    auto back = placeAll(s, a, forwardOf(30, -5));
    CHECK(first.size() == back.size());
    bool same = first.size() == back.size();
    for (const auto& [key, p] : first) {
        auto it = back.find(key);
        same = same && it != back.end() && it->second.xz == p.xz && it->second.facing == p.facing;
    }
    CHECK(same);
    // Far away the box holds other cells.
    for (const auto& [key, p] : away) CHECK_FALSE(first.count(key));
    // A nearby camera (half a box over) sees the shared cells with the same blades.
    auto near = placeAll(s, a + glm::dvec2(7.3, -4.1), forwardOf(120, -5));
    int shared = 0;
    for (const auto& [key, p] : near) {
        auto it = first.find(key);
        if (it == first.end()) continue;
        ++shared;
        CHECK(it->second.xz == p.xz);
    }
    CHECK(shared > 0);
    // Blades sit inside their own cell.
    GrassLayout l = grassLayout(s);
    for (const auto& [key, p] : first) {
        auto [cx, cz, j] = key;
        CHECK(p.xz.x >= cx * l.cell_m);
        CHECK(p.xz.x < (cx + 1) * l.cell_m);
        CHECK(p.xz.y >= cz * l.cell_m);
        CHECK(p.xz.y < (cz + 1) * l.cell_m);
    }
}

TEST_CASE("grass: the box ahead of the camera holds every visible ground point within the radius") {
    // View rays through a grid of screen points (60 deg vertical field of view, 16:9) hit flat
    // ground; every hit within radius_m of the eye must lie in a cell of the box. Cameras at
    // several heights, pitches and every heading, near and far from the origin.
    GrassSettings s;
    const double tan_v = std::tan(glm::radians(30.0)), tan_h = tan_v * 16.0 / 9.0;
    long total_hits = 0;
    for (glm::dvec2 eye : {glm::dvec2(0.3, -0.7), glm::dvec2(1.0e7 + 0.37, -1.0e7 + 0.91)}) {
        for (double height : {1.7, 10.0, 30.0}) {
            for (double pitch : {0.0, -15.0, -30.0, -60.0, -85.0}) {
                for (double yaw = 0.0; yaw < 360.0; yaw += 5.0) {
                    GrassLayout l = grassLayout(s);
                    const glm::dvec3 f = forwardOf(yaw, pitch);
                    const double y = glm::radians(yaw);
                    const glm::dvec3 right{std::cos(y), 0.0, std::sin(y)};
                    const glm::dvec3 up = glm::cross(right, f);
                    glm::ivec2 box = grassBoxMin(l, eye, f);
                    int outside = 0, hits = 0;
                    for (int j = 0; j <= 32; ++j)
                        for (int i = 0; i <= 32; ++i) {
                            glm::dvec3 ray = f + right * (tan_h * (i / 16.0 - 1.0)) + up * (tan_v * (j / 16.0 - 1.0));
                            if (ray.y >= -1e-9) continue;
                            glm::dvec3 hit = ray * (height / -ray.y);
                            if (glm::length(hit) > s.radius_m) continue;
                            ++hits;
                            glm::dvec2 c = glm::floor((eye + glm::dvec2(hit.x, hit.z)) / l.cell_m);
                            outside += c.x < box.x || c.x >= box.x + l.cells || c.y < box.y || c.y >= box.y + l.cells;
                        }
                    CHECK_MESSAGE(outside == 0, "yaw " << yaw << " pitch " << pitch << " height " << height);
                    total_hits += hits;
                }
            }
        }
    }
    CHECK(total_hits > 100000);
}

TEST_CASE("grass: the grass weight is the terrain shader's grass layer share, none on sand, rock, snow, slopes") {
    material::Bands b;
    const double rock_slope = 0.75;
    // The terrain shader blends layer floor(L) into the next by fract(L), order sand, grass,
    // rock, snow: the grass layer's share computed that way must equal grassWeight's band term.
    for (double h = -0.1; h <= 1.1; h += 0.0007) {
        double l = material::bands(h, b);
        int lower = int(std::min(std::floor(l), 3.0));
        double t = l - lower;
        double share = lower == 0 ? t : lower == 1 ? 1.0 - t : 0.0;
        CHECK(material::grassWeight(l, 0.0, 0.0) == doctest::Approx(share).epsilon(1e-9));
    }
    CHECK(material::grassAt(0.05, 1.0, b, rock_slope) == 0.0);                   // beach
    CHECK(material::grassAt(b.sand_top, 1.0, b, rock_slope) == 0.0);             // beach edge
    CHECK(material::grassAt(0.3, 1.0, b, rock_slope) == doctest::Approx(1.0));   // meadow
    CHECK(material::grassAt(0.55, 1.0, b, rock_slope) == 0.0);                   // rock band
    CHECK(material::grassAt(0.9, 1.0, b, rock_slope) == 0.0);                    // snow
    CHECK(material::grassAt(0.3, rock_slope - 0.07, b, rock_slope) == 0.0);      // cliff
    CHECK(material::grassAt(0.3, rock_slope + 0.08, b, rock_slope) < 0.7);       // dirt on a moderate slope
    CHECK(material::grassAt(0.3, rock_slope + 0.13, b, rock_slope) == doctest::Approx(1.0));
}

TEST_CASE("grass: bending keeps the blade's length") {
    for (int segments : {1, 2, 4, 8})
        for (double tip : {0.0, 0.3, 0.9, 1.4}) {
            glm::dvec2 dir = glm::normalize(glm::dvec2(0.6, -0.8));
            double length = 0.0;
            glm::dvec3 prev(0.0);
            for (int k = 1; k <= segments; ++k) {
                glm::dvec3 p = grassBladePoint(0.5, tip, dir, segments, k);
                length += glm::length(p - prev);
                prev = p;
            }
            CHECK(length == doctest::Approx(0.5).epsilon(1e-12));
            if (tip > 0.0) {
                CHECK(prev.y < 0.5);                                   // the tip comes down as it bends
                CHECK(glm::dot(glm::dvec2(prev.x, prev.z), dir) > 0.0);  // toward the bend
            }
        }
}

TEST_CASE("grass: blades thin out and shrink to nothing at the radius, without jumps") {
    GrassSettings s;
    double prev_keep = 1.0, prev_fade = grassFade(s, 0.0, 0.5);
    for (double d = 0.0; d <= s.radius_m; d += s.radius_m / 2000.0) {
        double keep = grassKeep(s, d), fade = grassFade(s, d, 0.1);
        CHECK(keep <= prev_keep + 1e-12);
        CHECK(std::abs(fade - prev_fade) < 0.02);
        prev_keep = keep;
        prev_fade = fade;
    }
    CHECK(grassFade(s, s.radius_m, 0.0) == 0.0);
    CHECK(grassKeep(s, 0.0) == 1.0);
    CHECK(grassKeep(s, s.radius_m) == doctest::Approx(s.far_keep));
}

TEST_CASE("grass: wind after 10^7 s is finite and as strong as after 10 s") {
    GrassSettings s;
    // Amplitude statistics over one full period of the gust pattern (128 x 128 blades) and
    // one full sway cycle (steps of a sixteenth of the slowest period).
    auto stats = [&](double t0, glm::dvec2 eye) {
        double sum = 0.0, sum2 = 0.0, peak = 0.0;
        int n = 0;
        bool finite = true;
        const double span = kGustPeriod * double(s.gust_scale_m);
        const double period = 8.0 / (6.0 * s.sway_frequency_hz) * 6.0;  // common period of all steps
        for (int k = 0; k < 16; ++k) {
            GrassWind w = grassWind(s, eye, t0 + period * k / 16.0);
            for (int z = 0; z < 128; ++z)
                for (int x = 0; x < 128; ++x) {
                    glm::vec2 rel(float(x * span / 128.0), float(z * span / 128.0));
                    glm::vec2 tilt = grassWindTilt(w, rel, float(x * 0.37 + z * 0.11), 6 + (x + z) % 5);
                    finite = finite && std::isfinite(tilt.x) && std::isfinite(tilt.y);
                    double a = glm::length(glm::dvec2(tilt));
                    sum += a;
                    sum2 += a * a;
                    peak = std::max(peak, a);
                    ++n;
                }
        }
        double mean = sum / n;
        return std::tuple{finite, mean, std::sqrt(std::max(sum2 / n - mean * mean, 0.0)), peak};
    };
    auto [finite_a, mean_a, spread_a, peak_a] = stats(10.0, {0.0, 0.0});
    auto [finite_b, mean_b, spread_b, peak_b] = stats(1.0e7, {0.0, 0.0});
    auto [finite_c, mean_c, spread_c, peak_c] = stats(1.0e7 + 0.3, {9.9e6, -9.9e6});
    CHECK(finite_a);
    CHECK(finite_b);
    CHECK(finite_c);
    CHECK(spread_a > 0.02);  // the wind does move the blades
    CHECK(mean_b == doctest::Approx(mean_a).epsilon(0.03));
    CHECK(spread_b == doctest::Approx(spread_a).epsilon(0.05));
    CHECK(mean_c == doctest::Approx(mean_a).epsilon(0.03));
    CHECK(spread_c == doctest::Approx(spread_a).epsilon(0.05));
    CHECK(peak_b <= s.wind_strength + s.gust_strength + s.sway_strength * 1.07 + 1e-4);
    // The wrapped phases stay small; the motion between two close frames stays smooth.
    GrassWind w0 = grassWind(s, {0.0, 0.0}, 1.0e7), w1 = grassWind(s, {0.0, 0.0}, 1.0e7 + 1.0 / 60.0);
    CHECK(w0.sway_phase >= 0.0f);
    CHECK(w0.sway_phase < 6.2832f);
    CHECK(w0.gust_origin.x < float(kGustPeriod));
    glm::vec2 d = grassWindTilt(w1, {3.0f, 4.0f}, 1.0f, 7) - grassWindTilt(w0, {3.0f, 4.0f}, 1.0f, 7);
    CHECK(glm::length(d) < 0.05f);
}
