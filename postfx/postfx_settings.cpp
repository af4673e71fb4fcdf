// [postfx]: the keys, units, ranges and help text.
#include "postfx/postfx_settings.h"

#include <array>

namespace vista {

void describe(SettingsVisitor& v, PostfxSettings& s) {
    static constexpr std::array<const char*, 10> effects{"bloom", "exposure", "tonemap", "fxaa", "grade", "dof",
                                                        "motion_blur", "lens_flare", "night_vision", "scotopic"};
    v.section("postfx", "post-processing chain");
    v.field({"enabled", "", "run the post chain (off: clamp and sRGB only)"}, s.enabled);
    v.sequence({"order", "", "effects in the order they run; before tonemap on linear HDR, after it on the display image"},
               s.order, effects);
}

}  // namespace vista
