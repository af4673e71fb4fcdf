// What a capture validates before rendering, without a GL context: `vista check` runs it so
// it finds every problem a capture would (heightmap file and samples, terrain grid, LUT).
#pragma once

#include "config/input_error.h"
#include "config/settings.h"
#include "terrain/heightmap.h"

namespace vista {

// map (optional) receives the checked heightmap when the terrain is on and valid.
InputErrors validateSceneInputs(const Settings& s, Heightmap* map = nullptr);

}  // namespace vista
