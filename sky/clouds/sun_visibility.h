// How much of the sun reaches the camera (CPU, no GL): its transmittance through the atmosphere
// (SkyLighting::sun_illuminance over the top-of-atmosphere value, the disk's share above the
// horizon included) and through the cloud layers along the sun's direction (Beer's law over the
// same density field the clouds pass marches, mirrored here in double). The lens flare scales by
// their product: a red sun at the horizon or one behind clouds does not flare at full strength.
#pragma once

#include "sky/clouds/cloud_settings.h"
#include "sky/sky_lighting.h"
#include "sky/sky_settings.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace vista {

struct SunVisibility {
    double atmosphere = 1.0;  //!< photopic luminance of the sun at the camera over that above the atmosphere, 0..1
    double clouds = 1.0;      //!< transmittance of the cloud layers along the sun's direction, 0..1
    double share() const { return atmosphere * clouds; }
};

// Extinction (1/m) of a cloud layer at noise coordinate p_cells (first-octave cells, wrapped
// origin already added) and height h01 in [0, 1] across the layer, for its coverage now:
// cloudDensity() of sky/clouds/shaders/clouds_common.glsl in double.
double cloudExtinction(const CloudLayerSettings& layer, double coverage, const glm::dvec3& p_cells, double h01);

// Transmittance of every active layer of [clouds] from the camera (world metres; altitude its y)
// towards dir (unit), at scene time t, as the clouds pass sees that view ray: the same shell
// stretch, noise origin, coverage and fade with distance, integrated with `steps` midpoint
// intervals per layer. 1 when the clouds are off.
double cloudTransmittanceAlong(const CloudsSettings& clouds, const SkySettings& sky, const glm::dvec3& camera_world_m,
                               const glm::dvec3& dir, double time_s, int steps = 96);

// The sun's visibility for the lighting of a frame (`lighting` from SkyLightingCache::get for
// the same sky and camera).
SunVisibility sunVisibility(const SkyLighting& lighting, const SkySettings& sky, const CloudsSettings& clouds,
                            const glm::dvec3& camera_world_m, double time_s);

}  // namespace vista
