// [postfx.exposure]: the keys, units, ranges and help text.
#include "postfx/exposure_settings.h"

#include <array>

namespace vista {

void describe(SettingsVisitor& v, ExposureSettings& s) {
    static constexpr std::array<const char*, 3> modes{"manual", "auto", "camera"};
    v.section("postfx.exposure", "exposure: manual, automatic from a log-luminance histogram, or a physical camera's");
    v.field({"enabled", "", "apply exposure"}, s.enabled);
    v.choice({"mode", "",
              "manual: scale 2^ev; auto: metered average to middle grey (0.18), times 2^ev; camera: EV100 from "
              "[postfx.dof] f_stop, [postfx.motion_blur] shutter_deg / 360 / frame_rate and iso, 1.2 * 2^EV100 cd/m^2 "
              "to 1, times 2^ev"},
             s.mode, modes);
    v.field({"ev", "stops", "exposure compensation, scale 2^ev"}, s.ev, -20.0f, 20.0f);
    v.field({"min_ev", "stops", "auto: lowest metered log2 luminance in [sky] sun_illuminance units (darker scenes stay dark)"}, s.min_ev, -40.0f, 20.0f);
    v.field({"max_ev", "stops", "auto: highest metered log2 luminance (brighter scenes stay bright)"}, s.max_ev, -40.0f, 20.0f);
    v.field({"night_ev", "stops", "auto: darker than middle grey by this at scotopic adaptation (< 0.005 cd/m^2), none above 5 cd/m^2"}, s.night_ev, 0.0f, 10.0f);
    v.field({"low_percent", "%", "auto: darkest share of pixels left out of the average"}, s.low_percent, 0.0f, 99.0f);
    v.field({"high_percent", "%", "auto: percentile above which pixels are left out of the average"}, s.high_percent, 1.0f, 100.0f);
    v.field({"speed_up", "1/s", "auto: adaptation rate towards brighter (difference falls by e in 1/rate s)"}, s.speed_up, 0.01f, 100.0f);
    v.field({"speed_down", "1/s", "auto: adaptation rate towards darker"}, s.speed_down, 0.01f, 100.0f);
    v.field({"iso", "", "camera: sensitivity (ISO arithmetic); sunny 16: f/16, 1/100 s, ISO 100"}, s.iso, 1.0f, 1.0e6f);
}

}  // namespace vista
