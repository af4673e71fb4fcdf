// The wave set from the wind and its double-precision evaluation (formulas in waves.h).
#include "terrain/water/waves.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace vista {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

double smoothstep(double e0, double e1, double x) {
    const double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

double fract(double x) { return x - std::floor(x); }

}  // namespace

double peakAngularFrequency(double wind_speed_m_s) { return 0.855 * kGravity / std::max(wind_speed_m_s, 1e-3); }

double piersonMoskowitz(double omega, double omega_p) {
    if (!(omega > 0.0)) return 0.0;
    const double x = omega_p / omega;
    return kPhillipsAlpha * kGravity * kGravity * std::pow(omega, -5.0) * std::exp(-1.25 * x * x * x * x);
}

// d/d omega of exp(-5/4 omega_p^4 omega^-4) is 5 omega_p^4 omega^-5 exp(...), so
// S = alpha g^2 / (5 omega_p^4) d/d omega exp(-5/4 (omega_p / omega)^4).
double piersonMoskowitzIntegral(double omega0, double omega1, double omega_p) {
    auto primitive = [omega_p](double omega) {
        if (!(omega > 0.0)) return 0.0;
        const double x = omega_p / omega;
        return std::exp(-1.25 * x * x * x * x);
    };
    const double p4 = omega_p * omega_p * omega_p * omega_p;
    return kPhillipsAlpha * kGravity * kGravity / (5.0 * p4) * (primitive(omega1) - primitive(omega0));
}

WaveSet makeWaves(const WaterSettings& s) {
    WaveSet set;
    const double omega_p = peakAngularFrequency(s.wind_speed_m_s);
    set.peak_angular_frequency = omega_p;
    const double lambda_p = kTwoPi * kGravity / (omega_p * omega_p);
    const int n = std::clamp(s.waves, 1, 32);
    const double lambda_min = std::max(double(s.min_wavelength_m), 1e-3);
    const double lambda_max = std::max(4.0 * lambda_p, 2.0 * lambda_min);
    const double q = n > 1 ? std::pow(lambda_min / lambda_max, 1.0 / double(n - 1)) : 1.0;
    // Frequencies grow by r = q^(-1/2) per wave; each bin reaches half a step (geometric) either side.
    const double half_step = n > 1 ? std::pow(q, -0.25) : 1.0;
    const double wind = double(s.wind_direction_deg) * std::numbers::pi / 180.0;
    const double spread = double(s.direction_spread_deg) * std::numbers::pi / 180.0;
    double squeeze = 0.0;
    for (int i = 0; i < n; ++i) {
        const double lambda = n > 1 ? lambda_max * std::pow(q, double(i)) : lambda_p;
        GerstnerWave w;
        w.wavenumber = kTwoPi / lambda;
        w.angular_frequency = std::sqrt(kGravity * w.wavenumber);
        // One wave alone stands for the whole spectrum; otherwise the outer bins end at the last waves' edges.
        const double lo = n > 1 ? w.angular_frequency / half_step : 0.0;
        const double hi = n > 1 ? w.angular_frequency * half_step : 1e30;
        if (i == 0) set.band_low = lo;
        if (i == n - 1) set.band_high = hi;
        w.amplitude = double(s.amplitude_scale) * std::sqrt(2.0 * std::max(piersonMoskowitzIntegral(lo, hi, omega_p), 0.0));
        w.chop = double(s.choppiness) * w.amplitude;
        const double angle = wind + spread * (2.0 * fract(0.5 + double(i) * 0.6180339887498949) - 1.0);
        w.direction = {std::sin(angle), -std::cos(angle)};
        w.phase = kTwoPi * fract(double(i) * 0.7548776662466927);
        squeeze += w.wavenumber * w.chop;
        set.max_height += w.amplitude;
        set.waves.push_back(w);
    }
    if (squeeze > kMaxSqueeze)
        for (GerstnerWave& w : set.waves) w.chop *= kMaxSqueeze / squeeze;
    for (const GerstnerWave& w : set.waves) set.max_chop += w.chop;
    return set;
}

double waveFootprintWeight(double wavenumber, double footprint_m) {
    return 1.0 - smoothstep(0.125, 0.25, footprint_m * wavenumber / kTwoPi);
}

WaveSample evaluateWaves(const WaveSet& set, glm::dvec2 x0, double t, double footprint_m) {
    WaveSample out;
    glm::dvec3 tx(1.0, 0.0, 0.0), tz(0.0, 0.0, 1.0);  // dP/dx0, dP/dz0
    for (const GerstnerWave& w : set.waves) {
        const double weight = waveFootprintWeight(w.wavenumber, footprint_m);
        const double k = w.wavenumber, a = w.amplitude * weight, c = w.chop * weight;
        out.lost_slope_variance += 0.5 * (1.0 - weight * weight) * (w.amplitude * k) * (w.amplitude * k);
        if (weight <= 0.0) continue;
        const double theta = std::fmod(k * glm::dot(w.direction, x0) - w.angular_frequency * t + w.phase, kTwoPi);
        const double sn = std::sin(theta), cs = std::cos(theta);
        const double dx = w.direction.x, dz = w.direction.y;
        out.displacement += glm::dvec3(-c * dx * sn, a * cs, -c * dz * sn);
        tx += glm::dvec3(-c * k * dx * dx * cs, -a * k * dx * sn, -c * k * dx * dz * cs);
        tz += glm::dvec3(-c * k * dx * dz * cs, -a * k * dz * sn, -c * k * dz * dz * cs);
    }
    out.normal = glm::normalize(glm::cross(tz, tx));
    out.jacobian = tx.x * tz.z - tx.z * tz.x;
    return out;
}

void packWaves(const WaveSet& set, glm::dvec2 origin, double t, std::vector<glm::vec4>& a, std::vector<glm::vec4>& b,
               double dt_s) {
    a.clear();
    b.clear();
    const std::size_t n = set.waves.size();
    std::vector<double> tail(n + 1, 0.0);  // slope variance of wave i and every shorter one
    for (std::size_t i = n; i-- > 0;) {
        const GerstnerWave& w = set.waves[i];
        tail[i] = tail[i + 1] + 0.5 * (w.amplitude * w.wavenumber) * (w.amplitude * w.wavenumber);
    }
    for (std::size_t i = 0; i < n; ++i) {
        const GerstnerWave& w = set.waves[i];
        // Each term reduced separately first: k d . origin and omega t may be 1e9 rad or more.
        const double space = std::fmod(w.wavenumber * glm::dot(w.direction, origin), kTwoPi);
        const double time = std::fmod(w.angular_frequency * t, kTwoPi);
        double theta0 = std::fmod(space - time + w.phase, kTwoPi);
        if (theta0 < 0.0) theta0 += kTwoPi;
        a.emplace_back(float(w.direction.x), float(w.direction.y), float(w.wavenumber), float(w.amplitude));
        b.emplace_back(float(w.chop), float(theta0), float(tail[i]), float(std::fmod(w.angular_frequency * dt_s, kTwoPi)));
    }
}

}  // namespace vista
