// Camera paths: timed key poses read from a text file, interpolated with centripetal
// Catmull-Rom (positions) and along the shortest arc (angles). Format, one key per line:
//   # t_seconds  x  y  z  yaw_deg  pitch_deg  [fov_deg]
//   0    1200  350  -800  45  -10
// Blank lines and '#' comments are ignored; times must increase strictly.
#pragma once

#include "config/input_error.h"

#include <glm/vec3.hpp>

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace vista {

struct CameraPose {
    glm::dvec3 position{0.0};  // m
    double yaw_deg = 0.0;      // 0 looks along -z, positive turns right
    double pitch_deg = 0.0;    // positive looks up
    double fov_deg = 60.0;     // vertical
};

struct CameraKey {
    double t = 0.0;  // s
    CameraPose pose;
};

class CameraPath {
public:
    CameraPath() = default;
    explicit CameraPath(std::vector<CameraKey> keys);

    // Parses text; name is the file name used in errors. A key without fov inherits the
    // previous key's (the first defaults to default_fov_deg).
    static CameraPath parse(std::string_view text, const std::string& name, InputErrors& errors,
                            double default_fov_deg = 60.0);
    static CameraPath load(const std::filesystem::path& file, InputErrors& errors,
                           double default_fov_deg = 60.0);

    // Pose at time t (s); t is clamped to [startTime(), endTime()]. Passes exactly
    // through every key, C1-continuous in position.
    CameraPose sample(double t) const;

    double startTime() const;
    double endTime() const;
    bool empty() const { return keys_.empty(); }
    const std::vector<CameraKey>& keys() const { return keys_; }

private:
    std::vector<CameraKey> keys_;
};

}  // namespace vista
