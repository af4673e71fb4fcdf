// Light at night, in the renderer's units: the moon's illuminance from its phase, the floor of
// starlight and airglow, the conversion between HDR units and lux, and the pre-exposure that
// keeps night radiances inside the half-float HDR target.
//
// Units. The HDR target holds radiance in "HDR units": [sky] sun_illuminance is the solar
// irradiance at the top of the atmosphere. That irradiance is kSolarIlluminanceLux, the
// luminous integral of the tabulated extraterrestrial solar spectrum (sky/atmosphere_spectral.h
// spectralSolarIlluminanceLux(1): 683 lm/W x sum of y-bar x E over 380..780 nm every 10 nm,
// ASTM G-173-03 ETR; a unit test checks the two agree), so one HDR unit of irradiance is kSolarIlluminanceLux / sun_illuminance lux and
// one HDR unit of radiance the same number of cd/m^2 (luxPerHdrUnit()).
//
// Pre-exposure. Noon terrain is ~0.1 HDR units and the sun's disk ~4e4; a moonless night's
// terrain ~1e-9, below half float's smallest subnormal (6e-8): no fixed scale spans 43 stops in
// a 30-stop format. So each frame multiplies every light (sun, sky, moon, stars, clouds,
// local lights) by preExposure(), a function of the sky's light at the camera alone (never of
// earlier frames: a shard renders frame k as a sequential run does); it is 1 whenever the sky
// gives more than kPreExposureLux, so day frames are unchanged. Auto exposure and the
// scotopic pass divide it back out; `vista capture --stats` reports it (sky.pre_exposure).
#pragma once

#include <glm/vec3.hpp>

namespace vista {

inline constexpr double kSolarIlluminanceLux = 132552.0;  // lx, top of the atmosphere (was 127,250 before issue 23)
inline constexpr double kMoonAngularRadiusDeg = 0.2587;   // mean, as seen from the earth
inline constexpr double kMoonAlbedo = 0.12;               // normal albedo of the lunar surface
// Starlight and airglow on a horizontal surface on a clear moonless night (~0.3 mlx of
// starlight and ~0.7 mlx of airglow; Leinert et al. 1998): the floor under the sky's light.
inline constexpr double kNightFloorLux = 1e-3;
// Above this much light from the sky at the camera the pre-exposure is 1 (day frames as before).
inline constexpr double kPreExposureLux = 400.0;
// The largest pre-exposure: a moonless night (kNightFloorLux) maps to kPreExposureLux.
inline constexpr double kMaxPreExposure = kPreExposureLux / kNightFloorLux;

// Lux per HDR unit of irradiance (and cd/m^2 per HDR unit of radiance) for a sun_illuminance.
double luxPerHdrUnit(double sun_illuminance);

// The moon's illuminance at the top of the atmosphere, as a fraction of the sun's, for the
// angle between the sun and the moon seen from the earth (elongation, rad; pi: full moon, 0:
// new): the Lommel-Seeliger disk the sky pass draws (sky/shaders/sky.glsl moonRadiance),
// integrated over its solid angle. Full moon: albedo / pi * solid angle = 2.45e-6 (~0.31 lx).
double moonIlluminanceFraction(double elongation_rad);

// The pre-exposure for a sky that gives sky_lux (sun, sky and moon on an up-facing surface,
// plus the floor) at the camera: min(max(kPreExposureLux / sky_lux, 1), kMaxPreExposure).
double preExposure(double sky_lux);

}  // namespace vista
