// What a capture validates before rendering, without a GL context: `vista check` runs it so
// it finds every problem a capture would (heightmap file and samples, terrain grid, tile cache,
// LUT).
#pragma once

#include "config/input_error.h"
#include "config/settings.h"
#include "renderer/lighting/local_lights.h"  // GroundHeight
#include "terrain/cdlod.h"
#include "terrain/heightmap.h"

namespace vista {

// A scene's terrain as `vista check` finds it: the heightmap or DEM held whole, or for a streamed
// terrain with an up-to-date tile cache, that cache (read a tile at a time, the map never held).
struct CheckedTerrain {
    Heightmap map;           // not streamed: the map, with its placement (a DEM's extent comes
    TerrainMapping mapping;  // from its geotransform, not from [terrain] size_m)
    GroundHeight ground;     // world x/z to ground height (m), from either (it refers to map: keep
                             // this where it was filled); empty when neither
};

// terrain (optional) receives the checked terrain when the terrain is on and valid. A streamed
// terrain whose cache is missing or stale has its input read through and checked (as building
// the cache would), and no ground.
InputErrors validateSceneInputs(const Settings& s, CheckedTerrain* terrain = nullptr);

}  // namespace vista
