// [postfx.night_vision]: the keys, units, ranges and help text.
#include "postfx/night_vision_settings.h"

namespace vista {

void describe(SettingsVisitor& v, NightVisionSettings& s) {
    v.section("postfx.night_vision", "night vision: amplified luminance, noise, green tint, scope vignette");
    v.field({"enabled", "", "night vision (place it after tonemap)"}, s.enabled);
    v.field({"gain", "", "luminance amplification"}, s.gain, 1.0f, 1000.0f);
    v.field({"noise", "", "noise amplitude"}, s.noise, 0.0f, 1.0f);
    v.field({"noise_rate", "1/s", "new noise pattern this many times per second of scene time"}, s.noise_rate, 0.0f, 1000.0f);
    v.field({"vignette", "", "darkening outside the scope circle, 1 black"}, s.vignette, 0.0f, 1.0f);
    v.field({"tint", "", "phosphor colour"}, s.tint, 0.0f, 1.0f);
}

}  // namespace vista
