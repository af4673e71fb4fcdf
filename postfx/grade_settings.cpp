// [postfx.grade]: the keys, units, ranges and help text.
#include "postfx/grade_settings.h"

namespace vista {

void describe(SettingsVisitor& v, GradeSettings& s) {
    v.section("postfx.grade", "colour grading on the display image: lift/gamma/gain, saturation, vignette");
    v.field({"enabled", "", "grade the image"}, s.enabled);
    v.field({"lift", "", "raises the blacks per channel: c + lift * (1 - c)"}, s.lift, -1.0f, 1.0f);
    v.field({"gamma", "", "mid-tones per channel: c^(1/gamma), above 1 brightens"}, s.gamma, 0.1f, 10.0f);
    v.field({"gain", "", "scales the whites per channel"}, s.gain, 0.0f, 10.0f);
    v.field({"saturation", "", "0 grey, 1 unchanged"}, s.saturation, 0.0f, 4.0f);
    v.field({"vignette", "", "darkening at the corners, 0 none, 1 black"}, s.vignette, 0.0f, 1.0f);
    v.field({"vignette_start", "", "share of the centre-to-corner distance where the darkening begins"}, s.vignette_start, 0.0f, 1.0f);
    v.field({"grain", "", "film grain amplitude at mid-grey (none at black and white)"}, s.grain, 0.0f, 1.0f);
    v.field({"grain_rate", "1/s", "new grain pattern this many times per second of scene time"}, s.grain_rate, 0.0f, 1000.0f);
    v.field({"lut", "", "optional 3D LUT (.cube file), applied after saturation; empty: none"}, s.lut);
}

}  // namespace vista
