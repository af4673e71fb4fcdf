// [postfx.lens_flare]: the keys, units, ranges and help text.
#include "postfx/lens_flare_settings.h"

namespace vista {

void describe(SettingsVisitor& v, LensFlareSettings& s) {
    v.section("postfx.lens_flare", "sun lens flare: ghosts, halo, chromatic aberration, starburst, faded by visibility");
    v.field({"enabled", "", "add a lens flare while the sun is on screen and above the horizon"}, s.enabled);
    v.field({"intensity", "", "flare radiance per unit sun illuminance"}, s.intensity, 0.0f, 1.0f);
    v.field({"ghosts", "", "ghost discs along the sun-to-centre axis"}, s.ghosts, 0, 16);
    v.field({"ghost_spacing", "", "ghost spacing along the axis (1 = sun to centre)"}, s.ghost_spacing, 0.01f, 2.0f);
    v.field({"halo_radius", "", "halo ring radius, share of the image height"}, s.halo_radius, 0.0f, 2.0f);
    v.field({"chromatic", "", "red/blue separation along the axis"}, s.chromatic, 0.0f, 0.5f);
    v.field({"starburst", "", "strength of the rays around the sun"}, s.starburst, 0.0f, 10.0f);
    v.field({"visibility_radius_deg", "deg", "radius of the 16 depth samples around the sun"}, s.visibility_radius_deg,
            0.01f, 10.0f);
    v.field({"visibility_rate", "1/s", "visibility follows the sky share of the samples by e in 1/rate s"},
            s.visibility_rate, 0.01f, 100.0f);
}

}  // namespace vista
