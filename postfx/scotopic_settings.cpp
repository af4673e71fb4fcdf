// [postfx.scotopic]: the keys, units, ranges and help text.
#include "postfx/scotopic_settings.h"

namespace vista {

void describe(SettingsVisitor& v, ScotopicSettings& s) {
    v.section("postfx.scotopic", "scotopic vision at night: rods' luminance, blue shift, loss of acuity, below 5 cd/m^2");
    v.field({"enabled", "", "apply on frames whose sky gives less than 400 lx"}, s.enabled);
    v.field({"blue_shift", "", "share of the rods' blue tint (0: grey)"}, s.blue_shift, 0.0f, 1.0f);
    v.field({"acuity_arcmin", "arcmin", "blur radius at full scotopic vision"}, s.acuity_arcmin, 0.0f, 60.0f);
    v.field({"show_rod_share", "", "debug: show the rods' share per pixel as grey"}, s.show_rod_share);
}

}  // namespace vista
