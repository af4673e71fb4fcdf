// [postfx.fxaa] (postfx/fxaa.h).
// describe() is the one description of the keys; config/settings.h gathers them into Settings.
#pragma once

#include "config/visitor.h"

namespace vista {

//! FXAA 3.11-style anti-aliasing on the display image (luma edges).
struct FxaaSettings {
    bool enabled = false;  //!< off by default: TAA ([postfx.taa]) anti-aliases; the low preset uses FXAA instead
    float edge_threshold = 0.125f;     //!< smallest local contrast treated as an edge, 0.01..1
    float edge_threshold_min = 0.0312f;//!< contrast below this (dark areas) is never an edge, 0..1
    float subpixel = 0.75f;            //!< sub-pixel aliasing removal (0 off, 1 soft), 0..1
};

// Lists the keys of FxaaSettings to v, in file order.
void describe(SettingsVisitor& v, FxaaSettings& s);

}  // namespace vista
