// [postfx.tonemap]: the keys, units, ranges and help text.
#include "postfx/tonemap_settings.h"

#include <array>

namespace vista {

void describe(SettingsVisitor& v, TonemapSettings& s) {
    static constexpr std::array<const char*, 4> ops{"reinhard", "aces", "clamp", "agx"};
    v.section("postfx.tonemap", "tone mapping from HDR to display");
    v.field({"enabled", "", "tone map (off: clamp)"}, s.enabled);
    v.choice({"op", "", "operator: extended Reinhard on luminance, ACES fit (Narkowicz), clamp, AgX (Sobotka)"}, s.op, ops);
    v.field({"white", "", "linear value mapped to white (reinhard)"}, s.white, 0.01f, 1000.0f);
}

}  // namespace vista
