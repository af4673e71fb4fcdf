// [postfx.grade]: colour grading (postfx/grade.h).
// describe() is the one description of the keys; config/settings.h gathers them into Settings.
#pragma once

#include "config/visitor.h"

#include <glm/vec3.hpp>

#include <string>

namespace vista {

//! Colour grading on the display image: lift/gamma/gain per channel, saturation, vignette.
struct GradeSettings {
    bool enabled = false;
    glm::vec3 lift{0.0f};          //!< raises the blacks: c + lift * (1 - c), -1..1
    glm::vec3 gamma{1.0f};         //!< mid-tones: c^(1/gamma) (above 1 brightens), 0.1..10
    glm::vec3 gain{1.0f};          //!< scales the whites, 0..10
    float saturation = 1.0f;       //!< 0 grey, 1 unchanged, 0..4
    float vignette = 0.0f;         //!< darkening at the corners (0 none, 1 black), 0..1
    float vignette_start = 0.5f;   //!< share of the centre-to-corner distance where the darkening begins, 0..1
    float grain = 0.0f;            //!< film grain amplitude at mid-grey (fades to 0 at black and white), 0..1
    float grain_rate = 24.0f;      //!< 1/s, new grain pattern this many times per second of scene time, 0..1000
    std::string lut;               //!< optional 3D LUT (.cube), relative to the vista root; applied after saturation
};

// Lists the keys of GradeSettings to v, in file order.
void describe(SettingsVisitor& v, GradeSettings& s);

}  // namespace vista
