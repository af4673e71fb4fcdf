// [postfx.ssao]: the keys, units, ranges and help text.
#include "postfx/ssao_settings.h"

namespace vista {

void describe(SettingsVisitor& v, SsaoSettings& s) {
    v.section("postfx.ssao", "screen-space ambient occlusion (horizon based), multiplies the ambient light");
    v.field({"enabled", "", "compute ambient occlusion before the lighting"}, s.enabled);
    v.field({"radius_m", "m", "world-space reach of the horizon search"}, s.radius_m, 0.01f, 100.0f);
    v.field({"intensity", "", "strength: ao = 1 - intensity * occlusion"}, s.intensity, 0.0f, 4.0f);
    v.field({"bias", "", "sine of the horizon angle ignored (against self-occlusion)"}, s.bias, 0.0f, 0.9f);
    v.field({"directions", "", "horizon directions per pixel"}, s.directions, 1, 16);
    v.field({"steps", "", "depth samples along each direction"}, s.steps, 1, 32);
    v.field({"half_resolution", "", "compute at half size (the blur upsamples depth-aware)"}, s.half_resolution);
    v.field({"blur", "", "3x3 bilateral blur (off: nearest upsample only)"}, s.blur);
    v.field({"blur_depth_tolerance", "", "relative depth difference at which blur weights fall by e"}, s.blur_depth_tolerance, 0.001f, 1.0f);
}

}  // namespace vista
