// The cloud layers' maths on the CPU (no GL): the tileable value noise and fBm that
// sky/clouds/shaders/cloud_noise.glsl evaluates on the GPU (mirrored here in double for the tests),
// the first stretch of a view ray inside a spherical shell (mirrored by cloudShell() in
// sky/clouds/shaders/clouds_common.glsl), and the time-dependent parts computed in double on the CPU:
// the random-walk wind offset, the noise origin wrapped to the noise period (so a scene at
// time 1e7 s animates as smoothly as at 10 s) and the coverage swing.
#pragma once

#include "sky/clouds/cloud_settings.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>

namespace vista {

// Lattice cells of the coarsest octave in one period of the noise (octave k: kCloudNoisePeriod
// << k cells of half the size, the same period in space). Same as CLOUD_NOISE_PERIOD in GLSL.
inline constexpr int kCloudNoisePeriod = 64;
// Cloud layers the GPU block holds ([clouds.low], [clouds.high]).
inline constexpr int kMaxCloudLayers = 2;
// Seconds between the wind's random knots (its velocity wanders over about this time).
inline constexpr double kWindGustPeriodS = 90.0;

// 32-bit integer mix (an avalanche of xor-shifts and odd multiplies), as cloudHash() in GLSL.
std::uint32_t cloudHash(std::uint32_t x);
// The random value in [0, 1) at an integer lattice point, wrapped to period (a power of two).
double cloudLattice(glm::ivec3 cell, int period, std::uint32_t seed);
// Value noise in [0, 1]: quintic-faded trilinear interpolation of lattice values; periodic
// with `period` cells along every axis.
double cloudValueNoise(const glm::dvec3& p, int period, std::uint32_t seed);
// The seed of octave k of a layer's fBm.
std::uint32_t cloudOctaveSeed(std::uint32_t seed, int octave);
// fBm in [0, 1]: octaves of value noise, frequency x2 and amplitude x1/2 each, divided by the
// sum of the amplitudes; periodic with kCloudNoisePeriod cells of the first octave.
double cloudFbm(const glm::dvec3& p, int octaves, std::uint32_t seed);

// The first stretch [t0, t1] (m along the ray) of a ray inside the shell r_bottom <= |x| <=
// r_top around the planet's centre, starting at radius r with mu = cos(angle to the local
// vertical), cut where the ray meets the ground (radius ground_r). hit = false: none.
struct ShellSegment {
    double t0 = 0.0, t1 = 0.0;
    bool hit = false;
};
ShellSegment cloudShellSegment(double r, double mu, double ground_r, double r_bottom, double r_top);

// Whether a layer draws anything (enabled, coverage and density above 0).
bool cloudLayerActive(const CloudLayerSettings& layer);
// Whether [clouds] draws anything: enabled with at least one active layer.
bool cloudsActive(const CloudsSettings& clouds);
// The lowest altitude (m above sea level, y = 0) a cloud can be at: the base of the lowest active
// layer (+infinity: none, or [clouds] off).
double cloudsLowestBaseM(const CloudsSettings& clouds);

// How far (m, world x and z) the wind has carried a layer's pattern at time t (s): the mean
// drift wind_speed along wind_direction_deg times t, plus a bounded random walk whose velocity
// wanders by wind_gust * wind_speed (smooth random knots every kWindGustPeriodS). Not wrapped.
glm::dvec2 cloudWindOffset(const CloudLayerSettings& layer, double t);
// The wind velocity (m/s, world x and z) at time t: the derivative of cloudWindOffset().
glm::dvec2 cloudWindVelocity(const CloudLayerSettings& layer, double t);
// The noise coordinate (first-octave cells, x and z) of the world point camera_xz at time t,
// wrapped to [0, kCloudNoisePeriod): computed in double, so the GPU adds only small
// camera-relative offsets in float.
glm::dvec2 cloudNoiseOrigin(const CloudLayerSettings& layer, const glm::dvec2& camera_xz, double t);
// A layer's coverage at time t: coverage + coverage_variation * sin(2 pi t / coverage_period_s),
// clamped to [0, 1] (the phase is reduced in double first).
double cloudCoverage(const CloudLayerSettings& layer, const CloudsSettings& clouds, double t);

}  // namespace vista
