// Hemi-octahedral frame maps and the bake projection of the impostors (see impostor.h); the
// GLSL twins are in renderer/meshes/shaders/object_common.glsl.
#include "renderer/meshes/impostor.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace vista {

glm::vec2 hemiOctEncode(glm::vec3 d) {
    d.y = std::max(d.y, 0.0f);
    d /= std::max(std::abs(d.x) + std::abs(d.y) + std::abs(d.z), 1e-20f);
    return {d.x + d.z, d.x - d.z};
}

glm::vec3 hemiOctDecode(glm::vec2 e) {
    glm::vec3 d(0.5f * (e.x + e.y), 0.0f, 0.5f * (e.x - e.y));
    d.y = 1.0f - std::abs(d.x) - std::abs(d.z);
    return glm::normalize(d);
}

glm::vec3 impostorFrameDirection(int i, int j) {
    const float n1 = float(kImpostorFrames - 1);
    return hemiOctDecode(glm::vec2(float(i), float(j)) / n1 * 2.0f - 1.0f);
}

glm::ivec2 impostorFrameOf(glm::vec3 d) {
    const float n1 = float(kImpostorFrames - 1);
    const glm::vec2 cell = glm::clamp(glm::round((hemiOctEncode(glm::normalize(d)) * 0.5f + 0.5f) * n1), 0.0f, n1);
    return glm::ivec2(cell);
}

void impostorBasis(glm::vec3 d, glm::vec3& right, glm::vec3& up) {
    right = std::abs(d.y) < 0.999f ? glm::normalize(glm::cross(glm::vec3(0.0f, 1.0f, 0.0f), d)) : glm::vec3(1.0f, 0.0f, 0.0f);
    up = glm::cross(d, right);
}

glm::mat4 impostorBakeMatrix(glm::vec3 d, glm::vec3 centre, float radius) {
    glm::vec3 right, up;
    impostorBasis(d, right, up);
    const float k = 1.0f / std::max(radius, 1e-6f);
    glm::mat4 m(0.0f);  // column-major: m[column][row]
    for (int c = 0; c < 3; ++c) {
        m[c][0] = right[c] * k;
        m[c][1] = up[c] * k;
        m[c][2] = 0.5f * d[c] * k;
    }
    m[3][0] = -glm::dot(centre, right) * k;
    m[3][1] = -glm::dot(centre, up) * k;
    m[3][2] = 0.5f - 0.5f * glm::dot(centre, d) * k;
    m[3][3] = 1.0f;
    return m;
}

}  // namespace vista
