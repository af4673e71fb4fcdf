// [postfx.fxaa] (postfx/fxaa.h): the keys, units, ranges and help text.
#include "postfx/fxaa_settings.h"

namespace vista {

void describe(SettingsVisitor& v, FxaaSettings& s) {
    v.section("postfx.fxaa", "FXAA anti-aliasing on the display image");
    v.field({"enabled", "", "run FXAA"}, s.enabled);
    v.field({"edge_threshold", "", "smallest local luma contrast treated as an edge"}, s.edge_threshold, 0.01f, 1.0f);
    v.field({"edge_threshold_min", "", "luma contrast below this is never an edge (dark areas)"}, s.edge_threshold_min, 0.0f, 1.0f);
    v.field({"subpixel", "", "sub-pixel aliasing removal, 0 off, 1 softest"}, s.subpixel, 0.0f, 1.0f);
}

}  // namespace vista
