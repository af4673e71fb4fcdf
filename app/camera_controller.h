// Free-fly camera: WASD moves in the view plane, Q/E down/up, the mouse looks around while
// the right button is held, the scroll wheel zooms (field of view); Shift and Ctrl scale
// the speed. Movement accelerates and glides to a stop rather than jumping. No GL or GLFW:
// the window code fills CameraInput.
#pragma once

#include "config/settings.h"

#include <glm/vec3.hpp>

namespace vista {

struct CameraInput {
    float forward = 0, right = 0, up = 0;  // -1..1 from W/S, D/A, E/Q
    bool fast = false, slow = false;       // Shift, Ctrl
    double look_dx = 0, look_dy = 0;       // mouse motion in pixels while looking
    double scroll = 0;                     // wheel steps, positive zooms in
};

class CameraController {
public:
    explicit CameraController(const CameraSettings& s) { reset(s); }
    void reset(const CameraSettings& s);
    void update(const CameraInput& in, double dt, const CameraSettings& s);

    glm::dvec3 position{0.0};
    double yaw_deg = 0.0, pitch_deg = 0.0, fov_deg = 60.0;
    glm::dvec3 velocity{0.0};  // m/s
};

// Terrain-following (000's first-person manipulator): with follow_terrain the eye stays at
// eye_height_m above ground_m (the ground height under the camera); otherwise the camera
// stops just above the surface unless allow_below_ground.
void keepAboveGround(CameraController& camera, double ground_m, const CameraSettings& s);

}  // namespace vista
