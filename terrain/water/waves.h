// The sea's waves: a sum of Gerstner (trochoidal) waves whose wavelengths, amplitudes and
// directions come from the wind through a Pierson-Moskowitz spectrum. The same function runs
// on the GPU (terrain/water/shaders/waves.glsl, float, camera-relative, phases wrapped here in double)
// and here in double as its reference.
//
// Wave i, at rest position x0 (world x, z) and time t, with phase
//   theta_i = k_i d_i . x0 - omega_i t + phi_i,   omega_i = sqrt(g k_i) (deep water)
// moves the surface point to
//   P = (x0.x - sum c_i d_i.x sin theta_i,  sum a_i cos theta_i,  x0.z - sum c_i d_i.z sin theta_i)
// (a_i: amplitude, c_i: horizontal amplitude = choppiness * a_i, capped so that
// sum k_i c_i <= kMaxSqueeze: the horizontal Jacobian stays >= 1 - kMaxSqueeze > 0, crests
// never fold). The normal is the cross product of dP/dz0 and dP/dx0.
//
// Footprint filtering: a wave much shorter than the sampling footprint f (grid cell or pixel,
// metres) cannot be drawn without aliasing, so each wave is weighted by
//   w(k, f) = 1 - smoothstep(1/8, 1/4, f k / 2 pi)
// (full while its wavelength is >= 8 f, gone at 4 f), and the slope variance it loses,
// (1 - w^2) (a k)^2 / 2, widens the specular lobe instead (water.surface's roughness).
#pragma once

#include "terrain/water/water_settings.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <vector>

namespace vista {

constexpr double kGravity = 9.81;        // m/s^2
constexpr double kMaxSqueeze = 0.9;      // largest sum of k c over the waves
constexpr double kPhillipsAlpha = 8.1e-3;  // Pierson-Moskowitz's Phillips constant

struct GerstnerWave {
    glm::dvec2 direction{1.0, 0.0};  // unit, world x/z, where the wave travels
    double wavenumber = 1.0;         // k = 2 pi / wavelength, 1/m
    double angular_frequency = 1.0;  // omega = sqrt(g k), rad/s
    double amplitude = 0.0;          // a, m (vertical)
    double chop = 0.0;               // c, m (horizontal)
    double phase = 0.0;              // phi, rad in [0, 2 pi)
};

struct WaveSet {
    std::vector<GerstnerWave> waves;   // longest first (increasing wavenumber)
    double peak_angular_frequency = 0.0;  // omega_p of the spectrum, rad/s
    double band_low = 0.0, band_high = 0.0;  // omega range the waves' bins cover, rad/s
    double max_height = 0.0;           // sum of amplitudes: |y| never exceeds it
    double max_chop = 0.0;             // sum of horizontal amplitudes: |x|, |z| shifts never exceed it
};

// Peak of the Pierson-Moskowitz spectrum for a wind speed (m/s): omega_p = 0.855 g / U.
double peakAngularFrequency(double wind_speed_m_s);
// The spectrum S(omega) = alpha g^2 omega^-5 exp(-5/4 (omega_p / omega)^4), m^2 s.
double piersonMoskowitz(double omega, double omega_p);
// Its integral from omega0 to omega1 (closed form), m^2: the surface's height variance there.
double piersonMoskowitzIntegral(double omega0, double omega1, double omega_p);

// The wave set of the settings: `waves` wavelengths geometric from 4 lambda_p (lambda_p = 2 pi g /
// omega_p^2) down to min_wavelength_m, each standing for its frequency bin (between the geometric
// means with its neighbours): a = amplitude_scale sqrt(2 S(omega) d omega); directions spread over
// +-direction_spread_deg around the wind by a golden-ratio sequence; phases likewise. Deterministic.
WaveSet makeWaves(const WaterSettings& s);

// w(k, f) above.
double waveFootprintWeight(double wavenumber, double footprint_m);

struct WaveSample {
    glm::dvec3 displacement{0.0};   // P - (x0.x, 0, x0.z), m (y: height above the still level)
    glm::dvec3 normal{0.0, 1.0, 0.0};  // unit
    double jacobian = 1.0;          // det of d(P.xz)/d(x0): < 1 where the surface is squeezed (crests)
    double lost_slope_variance = 0.0;  // slope variance of the waves the footprint removed
};

// The surface at rest position x0 (world x, z, m) and time t (s), in double; footprint_m = 0
// keeps every wave.
WaveSample evaluateWaves(const WaveSet& set, glm::dvec2 x0, double t, double footprint_m = 0.0);

// What the GPU gets per wave: (d.x, d.z, k, a) and (c, theta_0, slope variance of this wave and
// all shorter ones, omega dt mod 2 pi) where theta_0 = (k d . origin - omega t + phi) mod 2 pi in
// double, so that the shader's phase k d . (x0 - origin) + theta_0 stays exact for any time and
// origin (camera); adding omega dt gives the phase dt_s earlier (the previous frame's surface, for
// the motion vectors; dt_s 0: none).
void packWaves(const WaveSet& set, glm::dvec2 origin, double t, std::vector<glm::vec4>& a, std::vector<glm::vec4>& b,
               double dt_s = 0.0);

}  // namespace vista
