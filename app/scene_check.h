// What a capture validates before rendering, without a GL context: `vista check` runs it so
// it finds every problem a capture would (heightmap file and samples, terrain grid, LUT).
#pragma once

#include "config/input_error.h"
#include "config/settings.h"
#include "terrain/cdlod.h"
#include "terrain/heightmap.h"

namespace vista {

// A scene's heightmap or DEM as `vista check` loads it, with its placement (a DEM's extent comes
// from its geotransform, not from [terrain] size_m).
struct CheckedTerrain {
    Heightmap map;
    TerrainMapping mapping;
};

// terrain (optional) receives the checked heightmap when the terrain is on and valid.
InputErrors validateSceneInputs(const Settings& s, CheckedTerrain* terrain = nullptr);

}  // namespace vista
