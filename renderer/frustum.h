// View frusta as planes, for culling on the CPU (terrain selection, shadow casters, objects).
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include <array>

namespace vista {

// A frustum as 6 inward-facing planes (a, b, c, d) in camera-relative world space:
// a point p is inside when dot(abc, p) + d >= 0 for every plane. Order: left, right,
// bottom, top, near, far; planes are normalised (|abc| = 1) or (0, 0, 0, 1) (always passes).
using Frustum = std::array<glm::dvec4, 6>;
// Planes of a view-projection matrix (camera-relative, reversed-Z infinite: the far plane is
// degenerate and always passes).
Frustum frustumFromViewProj(const glm::dmat4& view_proj);

}  // namespace vista
