// libFuzzer target: camera path files. Any text must parse without crashing; every key the
// parser keeps is finite and in range, and sampling the path anywhere (before, between and
// after the keys) gives a finite pose within the documented limits.
#include "app/camera_path.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

namespace {

// A key keeps its yaw as written; a sampled pose has it normalised to (-180, 180].
bool finitePose(const vista::CameraPose& p, bool sampled) {
    return std::isfinite(p.position.x) && std::isfinite(p.position.y) && std::isfinite(p.position.z) &&
           std::isfinite(p.yaw_deg) && std::isfinite(p.pitch_deg) && std::isfinite(p.fov_deg) &&
           p.pitch_deg >= -90.0 && p.pitch_deg <= 90.0 && p.fov_deg >= 1.0 && p.fov_deg <= 179.0 &&
           (!sampled || (p.yaw_deg > -180.0 && p.yaw_deg <= 180.0));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    vista::InputErrors errors;
    const vista::CameraPath path = vista::CameraPath::parse(text, "fuzz.path", errors);
    for (const vista::CameraKey& k : path.keys())
        if (!std::isfinite(k.t) || !finitePose(k.pose, false)) std::abort();
    if (path.empty()) return 0;
    const double t0 = path.startTime(), t1 = path.endTime();
    for (double f : {-1.0, 0.0, 0.125, 0.5, 0.875, 1.0, 2.0}) {
        const double t = t0 + (t1 - t0) * f;
        if (!std::isfinite(t)) continue;  // a span wider than a double holds
        if (!finitePose(path.sample(t), true)) std::abort();
    }
    for (const vista::CameraKey& k : path.keys())
        if (!finitePose(path.sample(k.t), true)) std::abort();
    return 0;
}
