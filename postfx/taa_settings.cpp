// [postfx.taa]: the keys, units, ranges and help text.
#include "postfx/taa_settings.h"

namespace vista {

void describe(SettingsVisitor& v, TaaSettings& s) {
    v.section("postfx.taa", "temporal anti-aliasing on the HDR image before the post chain (Karis 2014)");
    v.field({"enabled", "", "jitter the projection and resolve against the reprojected history"}, s.enabled);
    v.field({"blend", "", "share of the current frame in the result (1: history off)"}, s.blend, 0.02f, 1.0f);
    v.field({"clip_gamma", "", "history clipped to the neighbourhood mean +- this many standard deviations (YCoCg)"}, s.clip_gamma, 0.5f, 4.0f);
    v.field({"sharpen", "", "unsharp mask of the history against its bilinear fetch"}, s.sharpen, 0.0f, 1.0f);
    v.field({"disocclusion", "", "relative depth difference that rejects the history"}, s.disocclusion, 0.001f, 1.0f);
    v.field({"cut_distance_m", "m", "a camera jump beyond this between frames is a cut: TAA and cloud history dropped"}, s.cut_distance_m, 0.0f, 1.0e9f);
    v.field({"cut_angle_deg", "deg", "a camera turn beyond this between frames is a cut"}, s.cut_angle_deg, 0.0f, 180.0f);
}

}  // namespace vista
