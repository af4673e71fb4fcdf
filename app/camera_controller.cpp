// Free-fly camera maths.
#include "app/camera_controller.h"

#include "renderer/camera.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace vista {

void CameraController::reset(const CameraSettings& s) {
    position = s.position;
    yaw_deg = s.yaw_deg;
    pitch_deg = s.pitch_deg;
    fov_deg = s.fov_deg;
    velocity = glm::dvec3(0.0);
}

void CameraController::update(const CameraInput& in, double dt, const CameraSettings& s) {
    yaw_deg = std::remainder(yaw_deg + in.look_dx * s.mouse_sensitivity, 360.0);
    pitch_deg = std::clamp(pitch_deg - in.look_dy * s.mouse_sensitivity, -89.0, 89.0);
    fov_deg = std::clamp(fov_deg - in.scroll * s.zoom_sensitivity, 5.0, 120.0);

    glm::dvec3 forward = directionFromAngles(yaw_deg, pitch_deg);
    double yaw = yaw_deg * (3.14159265358979323846 / 180.0);
    glm::dvec3 right(std::cos(yaw), 0.0, std::sin(yaw));
    double speed = s.move_speed * (in.fast ? s.fast_multiplier : 1.0) * (in.slow ? s.slow_multiplier : 1.0);
    glm::dvec3 wish = forward * double(in.forward) + right * double(in.right) +
                      glm::dvec3(0.0, 1.0, 0.0) * double(in.up) * double(s.updown_speed);
    double len = glm::length(wish);
    glm::dvec3 target = len > 1e-9 ? wish / std::max(len, 1.0) * speed : glm::dvec3(0.0);
    // Exponential approach to the wished velocity (time constant tau): acceleration and
    // friction in one. Velocity and position use the exact solution over dt, so the glide
    // is the same at any frame rate.
    constexpr double tau = 0.1;  // s
    dt = std::max(dt, 0.0);
    double decay = std::exp(-dt / tau);
    glm::dvec3 excess = velocity - target;
    position += target * dt + excess * (tau * (1.0 - decay));
    velocity = target + excess * decay;
}

void keepAboveGround(CameraController& camera, double ground_m, const CameraSettings& s) {
    if (!std::isfinite(ground_m)) return;
    if (s.follow_terrain) {
        camera.position.y = ground_m + s.eye_height_m;
        camera.velocity.y = 0.0;
    } else if (!s.allow_below_ground && camera.position.y < ground_m + 2.0 * s.near_m) {
        camera.position.y = ground_m + 2.0 * s.near_m;  // the near plane stays above the surface
        camera.velocity.y = std::max(camera.velocity.y, 0.0);
    }
}

}  // namespace vista
