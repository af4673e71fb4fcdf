// Rain and snow placement, wind, splashes, wetness and ripples on the CPU: per-frame values for
// the weather shaders, and the mirror of what they compute, for the tests.
#include "sky/weather/weather_model.h"

#include "sky/clouds/cloud_model.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace vista {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

double positiveMod(double x, double m) {
    double r = std::fmod(x, m);
    if (r < 0.0) r += m;
    return r >= m ? 0.0 : r;
}

// Cell index and the position inside it, for a coordinate in cell units (floor in 64 bits).
std::int64_t cellOf(double v, double& frac) {
    double f = std::floor(v);
    frac = v - f;
    if (frac >= 1.0) frac = 0.0, f += 1.0;  // v just below an integer rounds up
    return std::int64_t(f);
}

}  // namespace

std::uint32_t weatherHash(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
    return cloudHash(a ^ cloudHash(b ^ cloudHash(c ^ cloudHash(d ^ 0x3c6ef372u))));
}

float weatherRandom(std::uint32_t h, std::uint32_t k) {
    return float(cloudHash(h ^ (k * 0x9e3779b9u + 0x7f4a7c15u)) >> 8) * (1.0f / 16777216.0f);
}

DropLayout dropLayout(const WeatherSettings& s) {
    DropLayout l;
    l.cell_m = s.cell_m;
    l.half = int(std::ceil(double(s.radius_m) / l.cell_m));
    l.cells = 2 * l.half + 1;
    const double per_cell = double(s.max_density) * l.cell_m * l.cell_m * l.cell_m;
    l.drops_per_cell = std::clamp(int(std::lround(per_cell)), 1, kMaxDropsPerCell);
    return l;
}

glm::dvec2 weatherWindVelocity(const WeatherSettings& s, const CloudsSettings& clouds, double t) {
    if (s.wind_from_clouds) return cloudWindVelocity(clouds.low, t) * double(s.wind_scale);
    const double az = glm::radians(double(s.wind_direction_deg));
    return glm::dvec2(std::sin(az), -std::cos(az)) * double(s.wind_speed_m_s);
}

glm::dvec2 weatherWindOffset(const WeatherSettings& s, const CloudsSettings& clouds, double t) {
    if (s.wind_from_clouds) return cloudWindOffset(clouds.low, t) * double(s.wind_scale);
    return weatherWindVelocity(s, clouds, t) * t;
}

glm::dvec3 dropFieldOffset(const WeatherSettings& s, const CloudsSettings& clouds, double t) {
    const glm::dvec2 wind = weatherWindOffset(s, clouds, t);
    return {wind.x, -double(s.drop_speed_m_s) * t, wind.y};
}

DropFrame dropFrame(const DropLayout& layout, const glm::dvec3& eye, const glm::dvec3& field_offset, double t) {
    DropFrame f;
    const glm::dvec3 q = (eye - field_offset) / layout.cell_m;
    double frac[3];
    const std::int64_t cell[3] = {cellOf(q.x, frac[0]), cellOf(q.y, frac[1]), cellOf(q.z, frac[2])};
    for (int a = 0; a < 3; ++a) {
        const std::int64_t min = cell[a] - layout.half;
        f.box_min[a] = int(std::uint32_t(std::uint64_t(min)));  // wraps: only the hash sees it
        f.frac[a] = float(frac[a]);
    }
    f.sway_phase = float(positiveMod(kTwoPi * kSnowSwayHz * t, kTwoPi));
    return f;
}

Drop dropAt(const DropLayout& layout, const DropFrame& frame, glm::ivec3 o, int j) {
    Drop d;
    d.cell = glm::ivec3(glm::uvec3(frame.box_min) + glm::uvec3(o));
    const std::uint32_t h = weatherHash(std::uint32_t(d.cell.x), std::uint32_t(d.cell.y), std::uint32_t(d.cell.z), std::uint32_t(j));
    const glm::dvec3 r(weatherRandom(h, 0), weatherRandom(h, 1), weatherRandom(h, 2));
    d.rel = (glm::dvec3(o - layout.half) + r - glm::dvec3(frame.frac)) * layout.cell_m;
    d.keep = weatherRandom(h, 3);
    d.size = 0.6f + 0.8f * weatherRandom(h, 4);
    d.phase = float(kTwoPi) * weatherRandom(h, 5);
    return d;
}

int dropsDrawnPerCell(const DropLayout& layout, float intensity) {
    return std::clamp(int(std::ceil(double(intensity) * layout.drops_per_cell)), 0, layout.drops_per_cell);
}

void visibleDropCells(const DropLayout& layout, const DropFrame& frame, const Frustum& planes, double radius_m,
                      double reach_m, std::vector<std::uint32_t>& out) {
    out.clear();
    const double c = layout.cell_m;
    for (int z = 0; z < layout.cells; ++z)
        for (int y = 0; y < layout.cells; ++y)
            for (int x = 0; x < layout.cells; ++x) {
                const glm::ivec3 o(x, y, z);
                const glm::dvec3 lo = (glm::dvec3(o - layout.half) - glm::dvec3(frame.frac)) * c - reach_m;
                const glm::dvec3 hi = lo + c + 2.0 * reach_m;
                // The box's nearest point to the camera (the origin).
                const glm::dvec3 nearest = glm::clamp(glm::dvec3(0.0), lo, hi);
                if (glm::dot(nearest, nearest) > radius_m * radius_m) continue;
                bool outside = false;
                for (const glm::dvec4& p : planes) {
                    // The corner farthest along the plane's normal.
                    const glm::dvec3 far(p.x >= 0.0 ? hi.x : lo.x, p.y >= 0.0 ? hi.y : lo.y, p.z >= 0.0 ? hi.z : lo.z);
                    if (p.x * far.x + p.y * far.y + p.z * far.z + p.w < 0.0) {
                        outside = true;
                        break;
                    }
                }
                if (!outside) out.push_back(packDropCell(o, layout.cells));
            }
}

SplashLayout splashLayout(const WeatherSettings& s) {
    SplashLayout l;
    l.half = int(std::ceil(double(s.splash_radius_m) / kSplashCellM));
    l.cells = 2 * l.half + 1;
    l.period_s = 4.0 * double(s.splash_life_s);
    const double per_cell = double(s.splash_rate) * kSplashCellM * kSplashCellM * l.period_s;
    l.slots = std::clamp(int(std::ceil(per_cell - 1e-6)), 1, kMaxSplashSlots);  // float settings: 16.0000002 is 16
    return l;
}

double splashFill(const SplashLayout& layout, const WeatherSettings& s) {
    const double per_cell = double(s.splash_rate) * kSplashCellM * kSplashCellM * layout.period_s;
    return std::min(1.0, per_cell / layout.slots);
}

SplashFrame splashFrame(const SplashLayout& layout, const glm::dvec2& eye_xz, double t) {
    SplashFrame f;
    for (int a = 0; a < 2; ++a) {
        double frac = 0.0;
        const std::int64_t min = cellOf(eye_xz[a] / kSplashCellM, frac) - layout.half;
        f.box_min[a] = int(std::uint32_t(std::uint64_t(min)));
        f.frac[a] = float(frac);
    }
    double frac = 0.0;
    f.cycle = std::uint32_t(std::uint64_t(cellOf(t / layout.period_s, frac)));
    f.cycle_frac = float(frac);
    return f;
}

double splashesKept(const SplashLayout& layout, const WeatherSettings& s) {
    return double(s.intensity) * splashFill(layout, s) * layout.slots;
}

Splash splashAt(const SplashLayout& layout, const SplashFrame& frame, glm::ivec2 o, int j) {
    const glm::uvec2 cell = glm::uvec2(frame.box_min) + glm::uvec2(o);
    const std::uint32_t h = weatherHash(cell.x, cell.y, std::uint32_t(j), 0x51ab5u);
    // The same float sum as the shader: cycle_frac + phase in [0, 2).
    const float u = frame.cycle_frac + weatherRandom(h, 0);
    const float whole = std::floor(u);
    Splash s;
    s.age = u - whole;
    s.cycle = frame.cycle + std::uint32_t(whole);
    const std::uint32_t hk = weatherHash(cell.x, cell.y, std::uint32_t(j), s.cycle);
    const glm::dvec2 r(weatherRandom(hk, 1), weatherRandom(hk, 2));
    s.rel_xz = (glm::dvec2(o - layout.half) + r - glm::dvec2(frame.frac)) * kSplashCellM;
    s.keep = weatherRandom(hk, 3);
    return s;
}

float weatherWetness(const WeatherSettings& s) {
    if (!s.enabled || s.kind != WeatherKind::Rain) return 0.0f;
    return s.wetness * std::min(1.0f, 2.0f * s.intensity);
}

RippleInput rainRippleWrap(const glm::dvec2& world_xz, double time_s) {
    return {glm::vec2(float(positiveMod(world_xz.x, kRippleWrapM)), float(positiveMod(world_xz.y, kRippleWrapM))),
            float(positiveMod(time_s, kRippleWrapS))};
}

glm::dvec3 rainRippleNormal(glm::dvec2 xz, double time, double intensity) {
    // As rain_ripples.glsl: 0.5 m cells (64 per wrap), each ring starts once a second at a
    // hashed place and phase (8 different places over the 8 s wrap), grows until its outer
    // edge is one cell from its centre, fading in and out; so the 3 x 3 cells around xz hold
    // every ring that reaches it.
    constexpr double cell_m = kRippleWrapM / 64.0, amplitude = 0.0035, wavelength = 0.06;
    glm::dvec2 slope(0.0);
    const glm::dvec2 c = glm::floor(xz / cell_m);
    for (int dz = -1; dz <= 1; ++dz)
        for (int dx = -1; dx <= 1; ++dx) {
            const glm::ivec2 cell = glm::ivec2(c) + glm::ivec2(dx, dz);
            const std::uint32_t wx = std::uint32_t(cell.x) & 63u, wz = std::uint32_t(cell.y) & 63u;
            const std::uint32_t h = weatherHash(wx, wz, 0x9127u, 0u);
            const double u = time + double(weatherRandom(h, 0));
            const double k = std::floor(u), age = u - k;
            const std::uint32_t hk = weatherHash(wx, wz, 0x9127u, std::uint32_t(int(k) & 7) + 1u);
            if (double(weatherRandom(hk, 1)) >= intensity) continue;
            const glm::dvec2 centre = (glm::dvec2(cell) + glm::dvec2(weatherRandom(hk, 2), weatherRandom(hk, 3))) * cell_m;
            const glm::dvec2 d = xz - centre;
            const double r = glm::length(d);
            const double x = (r - age * (cell_m - wavelength)) / wavelength;
            if (std::abs(x) >= 1.0 || r < 1e-6) continue;
            // Height a (1 - x^2)^2 sin(2 pi x) fade(age) around the front; its radial slope.
            const double b = (1.0 - x * x) * (1.0 - x * x), db = -4.0 * x * (1.0 - x * x);
            const double fade = (1.0 - age) * (1.0 - age) * std::min(1.0, 8.0 * age);
            const double dh = amplitude * fade / wavelength * (db * std::sin(kTwoPi * x) + b * kTwoPi * std::cos(kTwoPi * x));
            slope += dh * d / r;
        }
    return glm::normalize(glm::dvec3(-slope.x, 1.0, -slope.y));
}

}  // namespace vista
