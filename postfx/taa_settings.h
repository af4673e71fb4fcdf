// [postfx.taa]: temporal anti-aliasing (postfx/taa.h).
// describe() is the one description of the keys; config/settings.h gathers them into Settings.
#pragma once

#include "config/visitor.h"

namespace vista {

//! Temporal anti-aliasing (postfx/taa.h, docs/temporal.md): a Halton sub-pixel jitter of the
//! projection and a resolve of the linear HDR image against its reprojected history, run on the
//! scene's HDR image before the post chain (so before tone mapping and in HDR captures).
//! cut_distance_m / cut_angle_deg also decide when the clouds' history is dropped.
struct TaaSettings {
    bool enabled = true;
    float blend = 0.1f;            //!< share of the current frame in the result, 0.02..1 (1: history off)
    float clip_gamma = 1.25f;      //!< neighbourhood box half-size in standard deviations, 0.5..4
    float sharpen = 0.25f;         //!< unsharp mask of the history against its bilinear fetch, 0..1
    float disocclusion = 0.05f;    //!< relative depth difference that rejects history, 0.001..1
    float cut_distance_m = 100.0f; //!< m, a camera jump beyond this between frames is a cut (history dropped)
    float cut_angle_deg = 30.0f;   //!< deg, a camera turn beyond this between frames is a cut
};

// Lists the keys of TaaSettings to v, in file order.
void describe(SettingsVisitor& v, TaaSettings& s);

}  // namespace vista
