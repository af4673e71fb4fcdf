// Frustum planes from a view-projection matrix (Gribb and Hartmann's row combinations).
#include "renderer/frustum.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace vista {

Frustum frustumFromViewProj(const glm::dmat4& m) {
    auto row = [&m](int i) { return glm::dvec4(m[0][i], m[1][i], m[2][i], m[3][i]); };
    glm::dvec4 r0 = row(0), r1 = row(1), r2 = row(2), r3 = row(3);
    // Zero-to-one clip depth, reversed: z <= w is the near plane, z >= 0 the far one (at
    // infinity for an infinite projection, where its normal vanishes).
    Frustum f{r3 + r0, r3 - r0, r3 + r1, r3 - r1, r3 - r2, r2};
    for (glm::dvec4& p : f) {
        double len = glm::length(glm::dvec3(p));
        p = len > 1e-9 * std::abs(p.w) ? p / len : glm::dvec4(0.0, 0.0, 0.0, 1.0);
    }
    return f;
}

}  // namespace vista
