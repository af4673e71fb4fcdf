// [postfx.bloom] (postfx/bloom.h): the keys, units, ranges and help text.
#include "postfx/bloom_settings.h"

namespace vista {

void describe(SettingsVisitor& v, BloomSettings& s) {
    v.section("postfx.bloom", "bloom: 13-tap downsample chain and tent upsample (Jimenez 2014)");
    v.field({"enabled", "", "add bloom"}, s.enabled);
    v.field({"intensity", "", "share of the blurred image in the result"}, s.intensity, 0.0f, 1.0f);
    v.field({"radius", "", "weight of each coarser level while upsampling: 0 tight, 1 wide"}, s.radius, 0.0f, 1.0f);
    v.field({"levels", "", "downsample levels, each half the size of the one above"}, s.levels, 1, 10);
    v.field({"clamp", "", "highlights clamped to this before blurring (NaN and Inf count as 0)"}, s.clamp, 1.0f, 65504.0f);
}

}  // namespace vista
