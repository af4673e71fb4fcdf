// [postfx.scotopic]: night vision of the eye's rods (postfx/scotopic.h).
// describe() is the one description of the keys; config/settings.h gathers them into Settings.
#pragma once

#include "config/visitor.h"

namespace vista {

//! Scotopic vision (postfx/scotopic.h): below mesopic luminance the rods take over from the
//! cones: colour fades to the rods' luminance with a blue shift (Krawczyk et al. 2005) and
//! detail blurs (acuity). Per pixel, by its luminance in cd/m^2: none from 5 cd/m^2 up, all
//! at 0.005 and below (CIE mesopic range). Runs on linear HDR (before exposure) and only on
//! frames whose sky gives less than 400 lx (sky/night_light.h kPreExposureLux).
struct ScotopicSettings {
    bool enabled = true;
    float blue_shift = 1.0f;       //!< share of the rods' blue tint (0: grey), 0..1
    float acuity_arcmin = 10.0f;   //!< arcmin, detail lost at full scotopic vision (blur radius), 0..60
    bool show_rod_share = false;   //!< debug: the rods' share per pixel as grey, instead of the image
};

// Lists the keys of ScotopicSettings to v, in file order.
void describe(SettingsVisitor& v, ScotopicSettings& s);

}  // namespace vista
