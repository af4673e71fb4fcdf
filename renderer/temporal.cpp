// Jitter, cut detection and reprojection for the temporal passes (renderer/temporal.h).
#include "renderer/temporal.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

namespace vista {

double radicalInverse(std::uint64_t index, int base) {
    double result = 0.0, f = 1.0 / double(base);
    while (index > 0) {
        result += f * double(index % std::uint64_t(base));
        index /= std::uint64_t(base);
        f /= double(base);
    }
    return result;
}

glm::dvec2 taaJitterPx(std::uint64_t index) {
    const std::uint64_t i = index % 8 + 1;  // term 0 is (0, 0): start at 1
    return {radicalInverse(i, 2) - 0.5, radicalInverse(i, 3) - 0.5};
}

void applyJitter(ViewMatrices& m, glm::dvec2 jitter_px, int width, int height) {
    glm::dmat4 proj(m.proj);
    // clip.x += dx * w_clip with w_clip = -z_view: the z column gets -dx (NDC units).
    proj[2][0] -= 2.0 * jitter_px.x / double(std::max(width, 1));
    proj[2][1] -= 2.0 * jitter_px.y / double(std::max(height, 1));
    const glm::dmat4 view_proj = proj * glm::dmat4(m.view);
    m.proj = glm::mat4(proj);
    m.view_proj = glm::mat4(view_proj);
    m.inv_view_proj = glm::mat4(glm::inverse(view_proj));
}

bool cameraCut(const ViewParams& previous, const ViewParams& current, double distance_m, double angle_deg) {
    if (glm::length(current.position - previous.position) > distance_m) return true;
    const double c = glm::dot(directionFromAngles(previous.yaw_deg, previous.pitch_deg),
                              directionFromAngles(current.yaw_deg, current.pitch_deg));
    const double turn = glm::degrees(std::acos(std::clamp(c, -1.0, 1.0)));
    return turn > angle_deg || std::abs(current.fov_deg - previous.fov_deg) > angle_deg ||
           previous.width != current.width || previous.height != current.height;
}

glm::dmat4 previousClipFromRelative(const ViewParams& previous, const ViewParams& current) {
    ViewParams p = previous;
    p.width = current.width;  // the same image size (a change is a cut anyway)
    p.height = current.height;
    const glm::dmat4 prev_vp = glm::dmat4(viewMatrices(p).proj) * glm::dmat4(viewMatrices(p).view);
    return prev_vp * glm::translate(glm::dmat4(1.0), current.position - previous.position);
}

glm::dvec4 reprojectPoint(const ViewParams& previous, const ViewParams& current, const glm::dvec3& relative) {
    return previousClipFromRelative(previous, current) * glm::dvec4(relative, 1.0);
}

}  // namespace vista
