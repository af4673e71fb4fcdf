// View and projection for camera-relative rendering: the view matrix is a pure rotation
// (the camera sits at the origin), world positions are made camera-relative on the CPU in
// double precision, and the projection is reversed-Z with an infinite far plane for
// glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE): depth 1 at the near plane, 0 at infinity.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace vista {

struct ViewParams {
    glm::dvec3 position{0.0};  // m, world space
    double yaw_deg = 0.0;      // 0 looks along -z, positive turns right
    double pitch_deg = 0.0;    // positive looks up
    double fov_deg = 60.0;     // vertical
    double near_m = 0.1;
    int width = 1, height = 1;
};

struct ViewMatrices {
    glm::mat4 view{1.0f};  // rotation only
    glm::mat4 proj{1.0f};
    glm::mat4 view_proj{1.0f};
    glm::mat4 inv_view_proj{1.0f};
    glm::dvec3 forward{0.0, 0.0, -1.0};
    glm::dvec3 right{1.0, 0.0, 0.0};
    glm::dvec3 up{0.0, 1.0, 0.0};
};

// Unit vector for a heading (clockwise from -z) and an elevation, both in degrees.
glm::dvec3 directionFromAngles(double yaw_deg, double pitch_deg);
// Reversed-Z, infinite-far perspective (zero-to-one clip depth).
glm::dmat4 reversedInfinitePerspective(double fov_y_rad, double aspect, double near_m);
ViewMatrices viewMatrices(const ViewParams& v);

}  // namespace vista
