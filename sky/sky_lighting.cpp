// Sun and sky light for the lighting passes, from the CPU reference at reduced quadrature:
// measured against the full-quality reference, the sun's transmittance is within ~1e-4 and
// the sky irradiance within ~1% from the ground to 100 km and the sun from zenith to twilight
// (tests/unit/sky_lighting_test.cpp).
#include "sky/sky_lighting.h"

#include "sky/atmosphere.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace vista {

namespace {

// Reduced quadrature: the table is built once per atmosphere, the rest per sun move.
const IntegrationSteps kSteps{16, 24, 6, 4, 12, 12};
constexpr int kTableAltitudes = 16, kTableMuS = 64;
constexpr int kIrradiancePolar = 6, kIrradianceAzimuth = 6;

std::vector<double> atmosphereKey(const AtmosphereParams& p) {
    std::vector<double> k = {p.bottom_radius, p.top_radius, p.rayleigh_scale_height, p.mie_scale_height, p.mie_g,
                             double(int(p.mie_phase)), p.ozone_center_altitude, p.ozone_half_width};
    for (const glm::dvec3& v : {p.rayleigh_scattering, p.mie_scattering, p.mie_extinction, p.ozone_absorption,
                                p.ground_albedo, p.solar_irradiance})
        k.insert(k.end(), {v.x, v.y, v.z});
    return k;
}

}  // namespace

double snapSkyLightingAltitude(double altitude_m) {
    if (altitude_m <= 1000.0) return std::round(altitude_m);
    const double step = std::log1p(1e-3);
    return 1000.0 * std::exp(std::round(std::log(altitude_m / 1000.0) / step) * step);
}

SkyLightingCache::SkyLightingCache() = default;
SkyLightingCache::~SkyLightingCache() = default;

const SkyLighting& SkyLightingCache::get(const SkySettings& sky, const glm::dvec3& camera_world_m) {
    const AtmosphereParams p = atmosphereParams(sky);
    const glm::dvec3 sun = sunDirection(sky);
    std::vector<double> key = atmosphereKey(p);
    if (!table_ || key != key_) {
        table_ = std::make_unique<MultipleScatteringTable>(p, kSteps, kTableAltitudes, kTableMuS);
        key_ = std::move(key);
        valid_ = false;
        ++table_builds_;
    }
    // The result is a function of the inputs alone, never of the calls before (a capture shard must
    // light frame k as a sequential run does): the altitude snaps to a fixed grid, steps of 1 m
    // up to 1 km and of 0.1% above, and the result is recomputed whenever the snapped altitude, the
    // sun or its illuminance differ at all. (A threshold against the last evaluation would keep a
    // slowly climbing camera's old lighting for a history-dependent number of frames.)
    const double altitude = snapSkyLightingAltitude(std::max(camera_world_m.y, 0.0));
    if (valid_ && sun == last_.sun_direction && altitude == last_altitude_m_ && last_illuminance_ == sky.sun_illuminance)
        return last_;
    const glm::dvec3 camera{0.0, altitude, 0.0};
    const double scale = sky.sun_illuminance;
    last_.sun_direction = sun;
    last_.sun_illuminance = scale * sunIrradiance(p, camera, sun, kSteps.transmittance);
    last_.sky_irradiance_up =
        scale * skyIrradianceUp(p, camera, sun, kSteps, table_.get(), kIrradiancePolar, kIrradianceAzimuth);
    last_altitude_m_ = altitude;
    last_illuminance_ = sky.sun_illuminance;
    valid_ = true;
    ++evaluations_;
    return last_;
}

}  // namespace vista
