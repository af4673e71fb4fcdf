// Grass placement and wind on the CPU: per-frame parameters for the shaders, and the mirror
// of what the shaders compute, for the tests.
#include "terrain/grass/grass_placement.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

namespace vista {
namespace {

constexpr double kTwoPi = 6.283185307179586;
// Candidates (blade slots) the cull pass may run over; beyond, fewer blades per cell.
constexpr std::int64_t kMaxCandidates = std::int64_t(1) << 24;

double smooth(double e0, double e1, double x) {
    double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

double positiveMod(double x, double m) {
    double r = std::fmod(x, m);
    return r < 0.0 ? r + m : r;
}

float lattice(int x, int z) {
    return float(grassHash(std::uint32_t(x & (kGustPeriod - 1)), std::uint32_t(z & (kGustPeriod - 1)), 7u) >> 8) *
           (1.0f / 16777216.0f);
}

float valueNoise(glm::vec2 q) {
    float fx = std::floor(q.x), fz = std::floor(q.y);
    int x = int(fx), z = int(fz);
    float u = q.x - fx, v = q.y - fz;
    u = u * u * (3.0f - 2.0f * u);
    v = v * v * (3.0f - 2.0f * v);
    float a = lattice(x, z), b = lattice(x + 1, z), c = lattice(x, z + 1), d = lattice(x + 1, z + 1);
    float top = a + (b - a) * u, bottom = c + (d - c) * u;
    return top + (bottom - top) * v;
}

}  // namespace

GrassLayout grassLayout(const GrassSettings& s) {
    GrassLayout l;
    l.cell_m = s.cell_m;
    const double half = 0.8 * s.radius_m;
    l.cells = int(std::ceil(2.0 * half / l.cell_m)) + 1;
    l.blades_per_cell = std::max(1, int(std::lround(double(s.density) * l.cell_m * l.cell_m)));
    const std::int64_t cells = std::int64_t(l.cells) * l.cells;
    if (cells * l.blades_per_cell > kMaxCandidates) l.blades_per_cell = int(std::max<std::int64_t>(1, kMaxCandidates / cells));
    l.shift_m = double(s.forward_shift) * s.radius_m;
    return l;
}

glm::ivec2 grassBoxMin(const GrassLayout& layout, glm::dvec2 eye_xz, glm::dvec3 forward) {
    // Along the view's heading (also when looking down: the frustum's upper edge still
    // reaches out ahead); straight up or down keeps the box centred.
    glm::dvec2 heading(forward.x, forward.z);
    double len = glm::length(heading);
    // Full shift for level views, less as the view turns down and sees around the camera.
    heading = len > 1e-9 ? heading / len * std::min(1.0, 1.5 * len) : glm::dvec2(0.0);
    glm::dvec2 centre = eye_xz + layout.shift_m * heading;
    glm::dvec2 c = centre / layout.cell_m - double(layout.cells) * 0.5;
    return {int(std::floor(c.x + 0.5)), int(std::floor(c.y + 0.5))};
}

glm::ivec2 grassWrapCell(glm::ivec2 slot, glm::ivec2 box_min, int cells) {
    glm::ivec2 r = (slot - box_min) % cells;
    r += glm::ivec2(r.x < 0 ? cells : 0, r.y < 0 ? cells : 0);
    return box_min + r;
}

double grassWrapSource(double p, double eye, double size) {
    return p + size * std::ceil((eye - p) / size - 0.5);
}

GrassCandidate grassCandidate(const GrassLayout& layout, glm::ivec2 cell, int blade, const GrassSettings& s) {
    const std::uint32_t h = grassHash(std::uint32_t(cell.x), std::uint32_t(cell.y), std::uint32_t(blade));
    GrassCandidate c;
    c.world_xz = (glm::dvec2(cell) + glm::dvec2(grassRandom(h, 0), grassRandom(h, 1))) * layout.cell_m;
    c.facing = float(kTwoPi) * grassRandom(h, 2);
    c.height_factor = 1.0f + s.height_variation * (grassRandom(h, 3) * 2.0f - 1.0f);
    c.thin = grassRandom(h, 4);
    c.density = grassRandom(h, 5);
    c.curvature = grassRandom(h, 6);
    c.phase = float(kTwoPi) * grassRandom(h, 7);
    c.frequency_step = 6 + std::min(int(grassRandom(h, 8) * 5.0f), 4);
    return c;
}

double grassKeep(const GrassSettings& s, double d) {
    const double r = s.radius_m, start = std::min(double(s.thin_start), 0.999) * r;
    return 1.0 - (1.0 - double(s.far_keep)) * smooth(start, r, d);
}

double grassFade(const GrassSettings& s, double d, double thin) {
    const double keep = grassKeep(s, d);
    const double shrink = std::clamp((keep - thin) / (0.2 * keep), 0.0, 1.0);
    return shrink * (1.0 - smooth(0.8 * s.radius_m, double(s.radius_m), d));
}

GrassWind grassWind(const GrassSettings& s, glm::dvec2 eye_xz, double time_s) {
    GrassWind w;
    const double az = glm::radians(double(s.wind_direction_deg));
    const glm::dvec2 dir{std::sin(az), -std::cos(az)};
    w.dir = glm::vec2(dir);
    const double inv_scale = 1.0 / double(s.gust_scale_m);
    w.inv_gust_scale = float(inv_scale);
    // The gust pattern moves with the wind: sample at (x - dir * speed * t) / scale.
    const glm::dvec2 origin = (eye_xz - dir * (double(s.gust_speed_m_s) * time_s)) * inv_scale;
    w.gust_origin = glm::vec2(float(positiveMod(origin.x, kGustPeriod)), float(positiveMod(origin.y, kGustPeriod)));
    w.sway_phase = float(positiveMod(kTwoPi * double(s.sway_frequency_hz) * time_s / 8.0, kTwoPi));
    w.strength = s.wind_strength;
    w.gust = s.gust_strength;
    w.sway = s.sway_strength;
    return w;
}

float grassGustNoise(glm::vec2 q) {
    return 0.65f * valueNoise(q) + 0.35f * valueNoise(q * 2.0f + 17.0f);
}

glm::vec2 grassWindTilt(const GrassWind& w, glm::vec2 rel_xz, float phase, int frequency_step) {
    glm::vec2 q = rel_xz * w.inv_gust_scale + w.gust_origin;
    float n = grassGustNoise(q);
    float t = std::clamp((n - 0.35f) / 0.5f, 0.0f, 1.0f);
    float gust = t * t * (3.0f - 2.0f * t);
    float angle = float(frequency_step) * w.sway_phase + phase;
    float along = w.strength + w.gust * gust + w.sway * std::sin(angle);
    float across = 0.35f * w.sway * std::cos(angle);
    return w.dir * along + glm::vec2(-w.dir.y, w.dir.x) * across;
}

glm::dvec3 grassBladePoint(double length, double tip_angle, glm::dvec2 bend_dir, int segments, int k) {
    glm::dvec3 p(0.0);
    const double step = length / segments;
    for (int j = 0; j < k; ++j) {
        double s = (j + 0.5) / segments;
        double theta = tip_angle * s * std::sqrt(s);
        p += step * glm::dvec3(std::sin(theta) * bend_dir.x, std::cos(theta), std::sin(theta) * bend_dir.y);
    }
    return p;
}

glm::vec3 grassMeanAlbedo(const GrassSettings& s) {
    // Dry share: dry_fraction * r^2 on average dry_fraction / 3; the albedo ramps from the
    // darkened root to the tip over a blade that tapers, so its mean weighs the tip more.
    glm::vec3 tip = s.color + (s.dry_color - s.color) * (s.dry_fraction / 3.0f);
    return tip * (1.0f - 0.6f * s.root_darkening);
}

}  // namespace vista
