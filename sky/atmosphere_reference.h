// Double-precision CPU reference of the atmosphere (sky/atmosphere_model.h): transmittance,
// single scattering (exact up to quadrature, with the planet's shadow), multiple scattering by
// Hillaire 2020's isotropic approximation (psi_ms with ground albedo), sky radiance, the sun's
// transmitted light and the sky irradiance on the ground. The GPU LUTs are tested against it.
//
// All radiances are per unit of AtmosphereParams::solar_irradiance components' units / sr
// (transfer factors when solar_irradiance is 1), per RGB sample at kAtmosphereWavelengthsNm.
// Cost grows with IntegrationSteps; see atmosphere_test.cpp for convergence.
#pragma once

#include "sky/atmosphere_model.h"

#include <glm/vec3.hpp>

#include <vector>

namespace vista {

// Quadrature sizes. Every integral along a ray is split where its integrand has a kink or a
// jump (the perigee, the ozone profile's corners, the edge of the planet's shadow); each piece
// uses composite Simpson in u with t = length * u^2 from the piece's lower-altitude end, so
// samples gather where the air is dense: near-horizon rays and a sun below the horizon stay
// accurate. psi_ms's sphere has three polar ranges (up, down to the sky, down to the ground).
// Measured against 16x the steps: view 64 / transmittance 32 are within ~1e-4 of converged
// radiance for noon, sunset, twilight, 100 km and orbit views (view 32: ~1e-3); the default
// psi_ms counts are within ~1e-3 with the sun up near the ground and ~1e-2 high up with the sun
// below the horizon (12 / 8 / 32 / 32 bring those to ~1e-3 and ~5e-3, at 3x the cost).
struct IntegrationSteps {
    int view = 64;              //!< intervals along a view ray (shared by its pieces, >= 4 each)
    int transmittance = 64;     //!< intervals of each optical-depth integral towards the sun
    int ms_polar = 8;           //!< Gauss-Legendre nodes in each of psi_ms's three polar ranges
    int ms_azimuth = 6;         //!< azimuth nodes over [0, pi] for psi_ms (the integrand is symmetric)
    int ms_ray = 24;            //!< intervals along each psi_ms ray
    int ms_transmittance = 24;  //!< intervals of the sun's optical depth inside psi_ms
};

// Optical depth (dimensionless, per RGB sample) from radius r along mu to the top of the
// atmosphere, or to the ground if the ray hits it.
glm::dvec3 opticalDepth(const AtmosphereParams& p, double r, double mu, int steps = 64);
// Transmittance from (r, mu) to the top of the atmosphere; 0 when the ray hits the ground.
glm::dvec3 transmittance(const AtmosphereParams& p, double r, double mu, int steps = 64);

// Hillaire 2020 multiple-scattering term psi_ms(r, mu_s) in 1/sr per unit solar irradiance:
// the radiance scattered (isotropically) towards any direction by second and higher orders,
// per unit scattering coefficient. Exact up to quadrature of its sphere and ray integrals.
glm::dvec3 multipleScattering(const AtmosphereParams& p, double r, double mu_s, const IntegrationSteps& steps = {});

// psi_ms tabulated over altitude (sqrt spacing, dense near the ground) and mu_s (uniform), with
// bilinear interpolation of its logarithm (psi_ms falls exponentially as the sun sets): the same
// term at a small fraction of the cost of evaluating it at every sample. Built on all cores.
class MultipleScatteringTable {
public:
    MultipleScatteringTable(const AtmosphereParams& p, const IntegrationSteps& steps = {}, int altitude_size = 32,
                            int mu_s_size = 128);
    glm::dvec3 operator()(double r, double mu_s) const;
    int altitudeSize() const { return altitude_size_; }
    int muSSize() const { return mu_s_size_; }

private:
    double bottom_radius_, top_radius_;
    int altitude_size_, mu_s_size_;
    std::vector<glm::dvec3> values_;  // log psi_ms, [altitude][mu_s]
};

// What a view ray accumulates up to the end of the atmosphere, the ground or max_distance.
struct ViewRayResult {
    glm::dvec3 radiance{0.0};       //!< in-scattered radiance (single + multiple), no ground or sun disk
    glm::dvec3 transmittance{1.0};  //!< from the camera to the end of the segment
    bool hits_ground = false;       //!< the segment ends on the ground (not cut by max_distance)
    double distance = 0.0;          //!< m from the camera to the end of the segment
};

// camera_pos and vectors in vista's world (planetFromWorld: y up, ground under the origin at
// y = 0); view_dir and sun_dir need not be normalised. A camera below the ground is lifted onto
// it; from above the atmosphere only the part of the ray inside it is integrated. ms = nullptr
// evaluates psi_ms directly at every sample (exact, slow); a table makes it cheap.
ViewRayResult integrateViewRay(const AtmosphereParams& p, glm::dvec3 camera_pos, glm::dvec3 view_dir,
                               glm::dvec3 sun_dir, double max_distance, const IntegrationSteps& steps = {},
                               const MultipleScatteringTable* ms = nullptr);
// Sky radiance towards view_dir (in-scattering only; the sun disk and the ground are not added).
glm::dvec3 skyRadiance(const AtmosphereParams& p, glm::dvec3 camera_pos, glm::dvec3 view_dir, glm::dvec3 sun_dir,
                       const IntegrationSteps& steps = {}, const MultipleScatteringTable* ms = nullptr);

// Transmittance of sunlight reaching pos (world), times the visible fraction of the sun's disk
// above the planet's horizon (so the sun fades over its 0.27 deg radius instead of popping).
glm::dvec3 sunTransmittance(const AtmosphereParams& p, glm::dvec3 pos, glm::dvec3 sun_dir, int steps = 64);
// Irradiance from the sun on a surface facing it at pos: solar_irradiance * sunTransmittance.
glm::dvec3 sunIrradiance(const AtmosphereParams& p, glm::dvec3 pos, glm::dvec3 sun_dir, int steps = 64);
// Irradiance of the sky (no sun disk) on an up-facing surface at pos: the cosine-weighted
// integral of skyRadiance over the upper hemisphere (Gauss-Legendre in cos theta, midpoint in
// azimuth about the sun's vertical plane, both doubled by symmetry).
glm::dvec3 skyIrradianceUp(const AtmosphereParams& p, glm::dvec3 pos, glm::dvec3 sun_dir, const IntegrationSteps& steps = {},
                           const MultipleScatteringTable* ms = nullptr, int polar_nodes = 8, int azimuth_nodes = 8);

// n Gauss-Legendre nodes x and weights w on [0, 1] (Newton on the Legendre recurrence); the
// quadrature the multiple-scattering integrals use, on the CPU and for the GPU LUT's directions.
void gaussLegendre01(int n, std::vector<double>& x, std::vector<double>& w);

}  // namespace vista
