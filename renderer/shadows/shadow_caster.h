// Geometry besides the terrain that casts into the sun cascades and the spot shadow atlas
// (grass): the buffer the shadow pass must read (so it runs after that buffer is written), how
// far from the camera the geometry can be, and a depth-only draw for one shadow view.
#pragma once

#include "renderer/frame_graph.h"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <cstddef>
#include <functional>
#include <span>

namespace vista {

struct ShadowCaster {
    BufferHandle reads;     // read by every shadow pass that draws it
    double reach_m = 0.0;   // m: nothing of it lies farther from the camera (cascades beyond skip it)
    std::function<void(const glm::mat4& camera_relative_to_clip)> draw;  // depth only, targets and tests set
    // Optional, for the point-light cubes: only what lies within radius_m of centre (world), into
    // several views; before(i) binds view i's target and depth state, matrices[i] is its matrix.
    // Without it the cubes call `draw` per view.
    std::function<void(const glm::dvec3& centre, double radius_m, std::span<const glm::mat4> matrices,
                       const std::function<void(std::size_t)>& before)>
        draw_near;
    bool valid() const { return bool(draw); }
};

}  // namespace vista
