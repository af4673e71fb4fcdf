// Camera-relative view matrices, built in double precision and then rounded.
#include "renderer/camera.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

namespace vista {

glm::dvec3 directionFromAngles(double yaw_deg, double pitch_deg) {
    double yaw = glm::radians(yaw_deg), pitch = glm::radians(std::clamp(pitch_deg, -90.0, 90.0));
    return {std::sin(yaw) * std::cos(pitch), std::sin(pitch), -std::cos(yaw) * std::cos(pitch)};
}

glm::dmat4 reversedInfinitePerspective(double fov_y_rad, double aspect, double near_m) {
    double f = 1.0 / std::tan(fov_y_rad * 0.5);
    glm::dmat4 p(0.0);
    p[0][0] = f / aspect;
    p[1][1] = f;
    p[2][3] = -1.0;   // w_clip = -z_view
    p[3][2] = near_m; // z_clip = near, so depth = near / -z_view
    return p;
}

ViewMatrices viewMatrices(const ViewParams& v) {
    ViewMatrices m;
    m.forward = directionFromAngles(v.yaw_deg, v.pitch_deg);
    double yaw = glm::radians(v.yaw_deg);
    m.right = {std::cos(yaw), 0.0, std::sin(yaw)};  // stays defined when looking straight up or down
    m.up = glm::cross(m.right, m.forward);
    glm::dmat4 view(1.0);
    for (int i = 0; i < 3; ++i) {  // rows: right, up, -forward
        view[i][0] = m.right[i];
        view[i][1] = m.up[i];
        view[i][2] = -m.forward[i];
    }
    double aspect = double(std::max(v.width, 1)) / double(std::max(v.height, 1));
    glm::dmat4 proj = reversedInfinitePerspective(glm::radians(std::clamp(v.fov_deg, 1.0, 179.0)), aspect,
                                                  std::max(v.near_m, 1e-6));
    glm::dmat4 view_proj = proj * view;
    m.view = glm::mat4(view);
    m.proj = glm::mat4(proj);
    m.view_proj = glm::mat4(view_proj);
    m.inv_view_proj = glm::mat4(glm::inverse(view_proj));
    return m;
}

}  // namespace vista
