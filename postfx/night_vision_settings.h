// [postfx.night_vision]: an image intensifier's look (postfx/grade.h).
// describe() is the one description of the keys; config/settings.h gathers them into Settings.
#pragma once

#include "config/visitor.h"

#include <glm/vec3.hpp>

namespace vista {

//! Night vision (as 000's): luminance amplified, noise, a green phosphor tint and a round
//! scope vignette; on the display image (place it after tonemap).
struct NightVisionSettings {
    bool enabled = false;
    float gain = 6.0f;        //!< luminance amplification, 1..1000
    float noise = 0.15f;      //!< noise amplitude, 0..1
    float noise_rate = 30.0f; //!< 1/s, new noise pattern this many times per second of scene time, 0..1000
    float vignette = 1.0f;    //!< darkening outside the scope circle (1 black), 0..1
    glm::vec3 tint{0.25f, 1.0f, 0.3f};  //!< phosphor colour, 0..1
};

// Lists the keys of NightVisionSettings to v, in file order.
void describe(SettingsVisitor& v, NightVisionSettings& s);

}  // namespace vista
