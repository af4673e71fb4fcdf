// Where the scene's local lights stand: the surface a light's `ground H` offset is measured
// from (the terrain, or the sea's surface where the sea covers the terrain), and the
// warnings `vista check` gives for lights under water or inside the terrain.
#pragma once

#include "config/input_error.h"
#include "config/settings.h"
#include "renderer/lighting/local_lights.h"

#include <filesystem>
#include <string>
#include <vector>

namespace vista {

// The surface under a light at world x, z: the terrain height, raised to [water] level_m
// where the sea is on and covers it (a lamp `ground 2.5` on the shore stands 2.5 m above the
// water, not 2.5 m above the sea floor). Empty terrain: empty (volumes use their box's y).
GroundHeight lightGround(const GroundHeight& terrain, const WaterSettings& water);

// Warnings for lights whose centre is inside the terrain or under the water surface (explicit
// y, or volumes without `ground`), one per light or volume, located at the scene file's line
// that defines the key (the last of files that does; "--set" for overrides). terrain may be
// empty (then only the water is checked).
InputErrors checkLightPlacement(const Settings& s, const GroundHeight& terrain,
                                const std::vector<std::filesystem::path>& files,
                                const std::vector<std::string>& overrides);

}  // namespace vista
