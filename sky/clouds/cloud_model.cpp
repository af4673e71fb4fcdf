// Cloud noise, shell intersection, wind and coverage in double precision. The noise and the
// shell functions follow sky/clouds/shaders/cloud_noise.glsl and clouds_common.glsl line by line (the
// GL test compares them); wind and coverage exist only here and reach the GPU as uniforms.
#include "sky/clouds/cloud_model.h"

#include <glm/common.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace vista {

std::uint32_t cloudHash(std::uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}

double cloudLattice(glm::ivec3 cell, int period, std::uint32_t seed) {
    const std::uint32_t mask = std::uint32_t(period - 1);
    const std::uint32_t x = std::uint32_t(cell.x) & mask, y = std::uint32_t(cell.y) & mask, z = std::uint32_t(cell.z) & mask;
    const std::uint32_t h = cloudHash(x ^ cloudHash(y ^ cloudHash(z ^ seed)));
    return double(h >> 8) * (1.0 / 16777216.0);
}

namespace {
double fade(double t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); }
double lerp(double a, double b, double t) { return a + (b - a) * t; }
}  // namespace

double cloudValueNoise(const glm::dvec3& p, int period, std::uint32_t seed) {
    const glm::dvec3 i = glm::floor(p), f = p - i;
    const glm::ivec3 c(i);
    const glm::dvec3 u(fade(f.x), fade(f.y), fade(f.z));
    auto v = [&](int dx, int dy, int dz) { return cloudLattice(c + glm::ivec3(dx, dy, dz), period, seed); };
    const double x00 = lerp(v(0, 0, 0), v(1, 0, 0), u.x), x10 = lerp(v(0, 1, 0), v(1, 1, 0), u.x);
    const double x01 = lerp(v(0, 0, 1), v(1, 0, 1), u.x), x11 = lerp(v(0, 1, 1), v(1, 1, 1), u.x);
    return lerp(lerp(x00, x10, u.y), lerp(x01, x11, u.y), u.z);
}

std::uint32_t cloudOctaveSeed(std::uint32_t seed, int octave) { return seed + std::uint32_t(octave) * 0x9e3779b9u; }

double cloudFbm(const glm::dvec3& p, int octaves, std::uint32_t seed) {
    double sum = 0.0, amplitude = 1.0, norm = 0.0;
    glm::dvec3 q = p;
    int period = kCloudNoisePeriod;
    for (int k = 0; k < octaves; ++k) {
        sum += amplitude * cloudValueNoise(q, period, cloudOctaveSeed(seed, k));
        norm += amplitude;
        amplitude *= 0.5;
        q *= 2.0;
        period *= 2;
    }
    return norm > 0.0 ? sum / norm : 0.0;
}

namespace {

// Both distances where the ray (radius r, cosine mu) meets the sphere of radius s, nearer first;
// false when it misses. The roots come from q = -(b + sign(b) sqrt(disc)) and c / q, which keeps
// the small root accurate when r mu is large (Numerical Recipes' form of the quadratic).
bool sphereRoots(double r, double mu, double s, double& t_near, double& t_far) {
    const double b = r * mu, c = (r - s) * (r + s);
    const double disc = b * b - c;
    if (disc < 0.0) return false;
    const double q = -(b + std::copysign(std::sqrt(disc), b));
    const double a = q, d = q != 0.0 ? c / q : 0.0;
    t_near = std::min(a, d);
    t_far = std::max(a, d);
    return true;
}

}  // namespace

ShellSegment cloudShellSegment(double r, double mu, double ground_r, double r_bottom, double r_top) {
    ShellSegment s;
    double bn = 0.0, bf = 0.0, tn = 0.0, tf = 0.0;
    const bool hits_bottom = sphereRoots(r, mu, r_bottom, bn, bf);
    const bool hits_top = sphereRoots(r, mu, r_top, tn, tf);
    if (!hits_top || tf <= 0.0) return s;  // the shell is behind or beside the ray
    if (r < r_bottom) {
        s.t0 = bf;
        s.t1 = tf;
    } else {
        s.t0 = r > r_top ? std::max(tn, 0.0) : 0.0;
        s.t1 = hits_bottom && bn > 0.0 ? bn : tf;
    }
    double gn = 0.0, gf = 0.0;
    if (sphereRoots(r, mu, ground_r, gn, gf) && gf > 0.0) s.t1 = std::min(s.t1, std::max(gn, 0.0));
    s.hit = s.t1 > s.t0;
    return s;
}

bool cloudLayerActive(const CloudLayerSettings& layer) {
    return layer.enabled && layer.coverage > 0.0f && layer.density > 0.0f;
}

bool cloudsActive(const CloudsSettings& clouds) {
    return clouds.enabled && (cloudLayerActive(clouds.low) || cloudLayerActive(clouds.high));
}

double cloudsLowestBaseM(const CloudsSettings& clouds) {
    double base = std::numeric_limits<double>::infinity();
    if (!clouds.enabled) return base;
    for (const CloudLayerSettings* layer : {&clouds.low, &clouds.high})
        if (cloudLayerActive(*layer)) base = std::min(base, double(layer->base_m));
    return base;
}

namespace {

// The wind's random knots: one per kWindGustPeriodS, each component uniform in [-1, 1].
glm::dvec2 windKnot(std::int64_t k, std::uint32_t seed) {
    const std::uint32_t lo = std::uint32_t(std::uint64_t(k)), hi = std::uint32_t(std::uint64_t(k) >> 32);
    const std::uint32_t h = cloudHash(lo ^ cloudHash(hi ^ cloudHash(seed ^ 0x5bd1e995u)));
    const std::uint32_t h2 = cloudHash(h ^ 0x68e31da4u);
    return glm::dvec2(double(h >> 8), double(h2 >> 8)) * (2.0 / 16777216.0) - 1.0;
}

glm::dvec2 windDirection(const CloudLayerSettings& layer) {
    const double a = glm::radians(double(layer.wind_direction_deg));
    return {std::sin(a), -std::cos(a)};  // clockwise from -z
}

}  // namespace

// offset(t) = speed d t + speed gust T w(t/T), w smoothstep-interpolated between the knots, so
// the velocity speed (d + gust w'(t/T)) wanders smoothly (C1) by about gust * speed and the
// offset never accumulates error: it is a closed form of t, not a sum over frames.
glm::dvec2 cloudWindOffset(const CloudLayerSettings& layer, double t) {
    const double x = t / kWindGustPeriodS, k = std::floor(x), u = x - k;
    const std::uint32_t seed = std::uint32_t(layer.seed);
    const glm::dvec2 a = windKnot(std::int64_t(k), seed), b = windKnot(std::int64_t(k) + 1, seed);
    const double s = u * u * (3.0 - 2.0 * u);
    const glm::dvec2 w = a + (b - a) * s;
    const double speed = double(layer.wind_speed);
    return speed * (windDirection(layer) * t + double(layer.wind_gust) * kWindGustPeriodS * w);
}

glm::dvec2 cloudWindVelocity(const CloudLayerSettings& layer, double t) {
    const double x = t / kWindGustPeriodS, k = std::floor(x), u = x - k;
    const std::uint32_t seed = std::uint32_t(layer.seed);
    const glm::dvec2 a = windKnot(std::int64_t(k), seed), b = windKnot(std::int64_t(k) + 1, seed);
    const double ds = 6.0 * u * (1.0 - u);
    const double speed = double(layer.wind_speed);
    return speed * (windDirection(layer) + double(layer.wind_gust) * (b - a) * ds);
}

glm::dvec2 cloudNoiseOrigin(const CloudLayerSettings& layer, const glm::dvec2& camera_xz, double t) {
    const glm::dvec2 offset = cloudWindOffset(layer, t);
    const double period = double(kCloudNoisePeriod), scale = double(layer.scale_m);
    // Each term wrapped on its own first: (camera - offset) / scale loses nothing to a large
    // offset, and the sum is wrapped again.
    auto wrap = [period](double v) {
        double w = std::fmod(v, period);
        if (w < 0.0) w += period;
        return w >= period ? 0.0 : w;
    };
    const double x = wrap(wrap(camera_xz.x / scale) - wrap(offset.x / scale));
    const double z = wrap(wrap(camera_xz.y / scale) - wrap(offset.y / scale));
    return {x, z};
}

double cloudCoverage(const CloudLayerSettings& layer, const CloudsSettings& clouds, double t) {
    const double period = double(clouds.coverage_period_s);
    const double phase = 2.0 * std::numbers::pi * std::fmod(t, period) / period;
    return std::clamp(double(layer.coverage) + double(clouds.coverage_variation) * std::sin(phase), 0.0, 1.0);
}

}  // namespace vista
