// Sun and sky light for the lighting passes, from the CPU reference at reduced quadrature:
// measured against the full-quality reference, the sun's transmittance is within ~1e-4 and
// the sky irradiance within ~1% from the ground to 100 km and the sun from zenith to twilight
// (tests/unit/sky_lighting_test.cpp).
#include "sky/sky_lighting.h"

#include "sky/atmosphere.h"
#include "sky/atmosphere_spectral.h"
#include "sky/night_light.h"

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
    const glm::dvec3 moon = moonDirection(sky);
    if (!(valid_ && sun == unit_.sun_direction && altitude == last_altitude_m_ && moon == last_moon_ &&
          sky.moon == last_moon_on_)) {
        const glm::dvec3 camera{0.0, altitude, 0.0};
        // Linear sRGB as the sky pass draws it: the direct sun (and the moon's sunlight) through
        // sunlightRgb(), the skylight through the sky's colour matrix at this sun.
        const SunlightConversion sunlight = sunlightConversion(p);
        unit_.sun_direction = sun;
        unit_.sun_illuminance = sunlightRgb(sunlight, sunIrradiance(p, camera, sun, kSteps.transmittance));
        unit_.sky_irradiance_up = skyColourMatrix(sun.y) * skyIrradianceUp(p, camera, sun, kSteps, table_.get(),
                                                                           kIrradiancePolar, kIrradianceAzimuth);
        // The moon: its phase from the elongation, through the atmosphere as the sun is (the
        // same transmittance and fraction of the disk above the horizon; the radii differ by 3%).
        unit_.moon_direction = moon;
        const double elongation = std::acos(std::clamp(glm::dot(sun, moon), -1.0, 1.0));
        unit_.moon_illuminance = sky.moon ? moonIlluminanceFraction(elongation) *
                                                sunlightRgb(sunlight, sunIrradiance(p, camera, moon, kSteps.transmittance))
                                          : glm::dvec3(0.0);
        unit_.night_irradiance_up = glm::dvec3(kNightFloorLux / kSolarIlluminanceLux);
        last_altitude_m_ = altitude;
        last_moon_ = moon;
        last_moon_on_ = sky.moon;
        valid_ = true;
        last_illuminance_ = -1.0f;
        ++evaluations_;
    }
    if (last_illuminance_ != sky.sun_illuminance) {
        last_ = unit_.scaled(sky.sun_illuminance);
        last_illuminance_ = sky.sun_illuminance;
    }
    return last_;
}

bool SkyLighting::moonIsKey() const {
    const glm::dvec3 w(0.2126, 0.7152, 0.0722);
    return glm::dot(moon_illuminance, w) > glm::dot(sun_illuminance, w);
}

double SkyLighting::upLux(double sun_illuminance_setting) const {
    const glm::dvec3 w(0.2126, 0.7152, 0.0722);
    const glm::dvec3 up = sun_illuminance * std::max(sun_direction.y, 0.0) +
                          moon_illuminance * std::max(moon_direction.y, 0.0) + sky_irradiance_up + night_irradiance_up;
    return glm::dot(up, w) * luxPerHdrUnit(sun_illuminance_setting);
}

SkyLighting SkyLighting::scaled(double f) const {
    SkyLighting out = *this;
    out.sun_illuminance *= f;
    out.sky_irradiance_up *= f;
    out.moon_illuminance *= f;
    out.night_irradiance_up *= f;
    return out;
}

}  // namespace vista
