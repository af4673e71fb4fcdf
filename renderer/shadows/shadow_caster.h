// Geometry besides the terrain that casts into the sun cascades and the spot shadow atlas
// (grass): the buffer the shadow pass must read (so it runs after that buffer is written), how
// far from the camera the geometry can be, and a depth-only draw for one shadow view.
#pragma once

#include "renderer/frame_graph.h"

#include <glm/mat4x4.hpp>

#include <functional>

namespace vista {

struct ShadowCaster {
    BufferHandle reads;     // read by every shadow pass that draws it
    double reach_m = 0.0;   // m: nothing of it lies farther from the camera (cascades beyond skip it)
    std::function<void(const glm::mat4& camera_relative_to_clip)> draw;  // depth only, targets and tests set
    bool valid() const { return bool(draw); }
};

}  // namespace vista
