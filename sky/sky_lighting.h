// What the sky gives the lighting (CPU, no GL): the sun's direction, the sun's illuminance at
// the camera after the atmosphere, and the sky's ambient irradiance on an up-facing surface,
// from the double-precision reference model with reduced quadrature, cached.
//
// At night the moon (its phase and the atmosphere's transmittance towards it) and a floor of
// starlight and airglow (sky/night_light.h) join them; the moon becomes the key light, the one
// directional light the lighting passes shade, once it gives more than the sun.
//
// Units: HDR linear sRGB, the scale of [sky] sun_illuminance (the solar illuminance at the top of
// the atmosphere). A surface facing the sun outside the atmosphere receives the solar spectrum's
// colour at luminance sun_illuminance (about 1.09, 0.98, 0.96 times it); the atmosphere's three
// samples become colour as in the sky pass (sky/atmosphere_spectral.h: sunlightRgb() for the
// direct sun and the moon's sunlight, skyColourMatrix() for the skylight).
#pragma once

#include "sky/atmosphere_reference.h"
#include "sky/sky_settings.h"

#include <glm/vec3.hpp>

#include <memory>
#include <vector>

namespace vista {

struct SkyLighting {
    glm::dvec3 sun_direction{0.0, 1.0, 0.0};  //!< unit, towards the sun, world (y up, -z north)
    //! Irradiance on a surface facing the sun at the camera: sun_illuminance * the colour of the
    //! sunlight after the atmosphere's transmittance * the fraction of the sun's disk above the horizon (0 once it has set).
    glm::dvec3 sun_illuminance{0.0};
    //! Irradiance from the whole sky (no sun disk) on an up-facing surface at the camera,
    //! cosine-weighted; a Lambertian surface of albedo a reflects a * this / pi.
    glm::dvec3 sky_irradiance_up{0.0};
    glm::dvec3 moon_direction{0.0, 1.0, 0.0};  //!< unit, towards the moon
    //! Irradiance on a surface facing the moon at the camera: the moon's phase-dependent share
    //! of sun_illuminance times the transmittance towards it (0 below the horizon or [sky] moon off).
    glm::dvec3 moon_illuminance{0.0};
    //! Starlight and airglow on an up-facing surface (kNightFloorLux, white): the night's floor.
    glm::dvec3 night_irradiance_up{0.0};

    //! The directional light the lighting shades: the moon when it gives more than the sun.
    bool moonIsKey() const;
    glm::dvec3 keyDirection() const { return moonIsKey() ? moon_direction : sun_direction; }
    glm::dvec3 keyIlluminance() const { return moonIsKey() ? moon_illuminance : sun_illuminance; }
    //! Photopic illuminance (lux) on an up-facing surface from all of the above.
    double upLux(double sun_illuminance_setting) const;
    //! Every irradiance times f (the pre-exposure).
    SkyLighting scaled(double f) const;
};

// The altitude the cache evaluates at: altitude_m snapped to whole metres up to 1 km and to steps
// of 0.1% above (a fixed grid, so the lighting never depends on earlier frames).
double snapSkyLightingAltitude(double altitude_m);

// Keeps what is expensive: a multiple-scattering table per atmosphere (~0.4 s to build on 2 cores, once
// per change of the atmosphere's settings) and the last result at unit sun_illuminance
// (recomputed, ~1 ms, when the sun, the moon or the snapped camera altitude change; a new
// sun_illuminance only rescales it).
class SkyLightingCache {
public:
    SkyLightingCache();
    ~SkyLightingCache();
    // The camera's altitude is its y (as for the sky pass: the planet's centre is below it).
    const SkyLighting& get(const SkySettings& sky, const glm::dvec3& camera_world_m);
    int tableBuilds() const { return table_builds_; }
    int evaluations() const { return evaluations_; }

private:
    std::unique_ptr<MultipleScatteringTable> table_;
    std::vector<double> key_;
    SkyLighting unit_, last_;  // at sun_illuminance 1, and scaled by the last call's
    double last_altitude_m_ = -1.0;
    float last_illuminance_ = -1.0f;
    glm::dvec3 last_moon_{0.0};
    bool last_moon_on_ = false;
    bool valid_ = false;
    int table_builds_ = 0, evaluations_ = 0;
};

}  // namespace vista
