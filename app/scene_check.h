// What a capture validates before rendering, without a GL context: `vista check` runs it so
// it finds every problem a capture would (heightmap file and samples, terrain grid, LUT).
#pragma once

#include "config/input_error.h"
#include "config/settings.h"

namespace vista {

InputErrors validateSceneInputs(const Settings& s);

}  // namespace vista
