// What the sky gives the lighting (CPU, no GL): the sun's direction, the sun's illuminance at
// the camera after the atmosphere, and the sky's ambient irradiance on an up-facing surface,
// from the double-precision reference model with reduced quadrature, cached.
//
// Units: HDR units, the scale of [sky] sun_illuminance (the solar irradiance at the top of the
// atmosphere, per RGB sample at 680/550/440 nm). A surface facing the sun outside the
// atmosphere receives sun_illuminance in every channel; its radiance as drawn by the sky pass
// is in the same units per steradian.
#pragma once

#include "config/settings.h"
#include "sky/atmosphere_reference.h"

#include <glm/vec3.hpp>

#include <memory>
#include <vector>

namespace vista {

struct SkyLighting {
    glm::dvec3 sun_direction{0.0, 1.0, 0.0};  //!< unit, towards the sun, world (y up, -z north)
    //! Irradiance on a surface facing the sun at the camera: sun_illuminance * atmospheric
    //! transmittance * the fraction of the sun's disk above the horizon (0 once it has set).
    glm::dvec3 sun_illuminance{0.0};
    //! Irradiance from the whole sky (no sun disk) on an up-facing surface at the camera,
    //! cosine-weighted; a Lambertian surface of albedo a reflects a * this / pi.
    glm::dvec3 sky_irradiance_up{0.0};
};

// The altitude the cache evaluates at: altitude_m snapped to whole metres up to 1 km and to steps
// of 0.1% above (a fixed grid, so the lighting never depends on earlier frames).
double snapSkyLightingAltitude(double altitude_m);

// Keeps what is expensive: a multiple-scattering table per atmosphere (~0.4 s to build on 2 cores, once
// per change of the atmosphere's settings) and the last result (recomputed, ~1 ms, when the sun,
// its illuminance or the snapped camera altitude change).
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
    SkyLighting last_;
    double last_altitude_m_ = -1.0;
    float last_illuminance_ = -1.0f;
    bool valid_ = false;
    int table_builds_ = 0, evaluations_ = 0;
};

}  // namespace vista
