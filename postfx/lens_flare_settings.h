// [postfx.lens_flare]: the sun's lens flare (postfx/lens_flare.h).
// describe() is the one description of the keys; config/settings.h gathers them into Settings.
#pragma once

#include "config/visitor.h"

namespace vista {

//! Lens flare from the sun (after Chapman 2013's parts, drawn from the sun's screen position):
//! ghosts along the sun-to-centre axis, a halo, chromatic aberration and a starburst, scaled by
//! the sun's visibility (the share of depth samples around it that see the sky, smoothed).
struct LensFlareSettings {
    bool enabled = false;
    float intensity = 0.002f;        //!< flare radiance per unit sun illuminance, 0..1
    int ghosts = 5;                  //!< ghost discs along the axis, 0..16
    float ghost_spacing = 0.45f;     //!< spacing of the ghosts along the sun-to-centre axis (1 = sun to centre), 0.01..2
    float halo_radius = 0.45f;       //!< halo ring radius, share of the image height, 0..2
    float chromatic = 0.03f;         //!< red/blue separation along the axis, 0..0.5
    float starburst = 1.0f;          //!< strength of the rays around the sun, 0..10
    float visibility_radius_deg = 0.5f;  //!< deg, radius of the depth samples around the sun, 0.01..10
    float visibility_rate = 8.0f;    //!< 1/s, visibility follows its target by e in 1/rate s, 0.01..100
};

// Lists the keys of LensFlareSettings to v, in file order.
void describe(SettingsVisitor& v, LensFlareSettings& s);

}  // namespace vista
