// [postfx.dof]: the keys, units, ranges and help text.
#include "postfx/dof_settings.h"

namespace vista {

void describe(SettingsVisitor& v, DofSettings& s) {
    v.section("postfx.dof", "depth of field: thin-lens circle of confusion, autofocus, near/far gather");
    v.field({"enabled", "", "blur what is out of focus (needs the scene depth)"}, s.enabled);
    v.field({"focus_distance_m", "m", "focus distance when autofocus is off"}, s.focus_distance_m, 0.1f, 1.0e6f);
    v.field({"focal_length_mm", "mm", "lens focal length"}, s.focal_length_mm, 1.0f, 2000.0f);
    v.field({"f_stop", "", "f-number N: aperture diameter = focal length / N"}, s.f_stop, 0.5f, 64.0f);
    v.field({"sensor_height_mm", "mm", "sensor height: CoC in pixels = CoC on the sensor / sensor height * image height"},
            s.sensor_height_mm, 1.0f, 100.0f);
    v.field({"autofocus", "", "focus on the screen centre (median of 5 depth samples)"}, s.autofocus);
    v.field({"autofocus_rate", "1/s", "autofocus speed: the gap (in diopters) falls by e in 1/rate s"}, s.autofocus_rate,
            0.01f, 100.0f);
    v.field({"max_coc_px", "px", "largest blur radius"}, s.max_coc_px, 1.0f, 64.0f);
    v.field({"samples", "", "gather taps per pixel (quality knob)"}, s.samples, 4, 256);
    v.field({"debug", "", "show the circle of confusion: red far, green near, blue in focus"}, s.debug);
}

}  // namespace vista
