// [debug]: the keys, units, ranges and help text.
#include "renderer/debug_settings.h"

#include <array>

namespace vista {

void describe(SettingsVisitor& v, DebugSettings& s) {
    static constexpr std::array<const char*, 10> views{"final", "depth", "albedo", "normals", "lights", "cascades", "shadow_map", "shadow", "spot_atlas", "point_shadows"};
    v.section("debug", "debug views and helpers");
    v.choice({"view", "", "what the screen shows: final image, depth, G-buffer albedo or normals, lights = heat map of local lights evaluated per pixel, cascades = sun shadow cascade colours, shadow_map = the cascades' depth maps, shadow = the sun's visibility (white lit, black shadowed or facing away), spot_atlas = the spot lights' shadow atlas, point_shadows = the point lights' depth cubes (a row of six faces per light)"},
             s.view, views);
    v.field({"heat_max", "lights", "light count shown red in the lights view"}, s.heat_max, 1.0f, 65536.0f);
    v.field({"grid", "", "reference grid on the y = 0 plane"}, s.grid);
    v.field({"grid_spacing", "m", "distance between minor grid lines"}, s.grid_spacing, 0.01f, 100000.0f);
}

}  // namespace vista
