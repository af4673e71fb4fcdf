// The interactive window: input, camera, time, frame, panel. Keys: F1 panel, F12
// screenshot, R reload shaders, Space pause time, Backspace restart time, F walk on the
// terrain (follow it at eye height) or fly, Esc quit.
#pragma once

#include "config/settings.h"

#include <filesystem>

namespace vista {

// Returns the process exit code.
int runWindow(Settings settings, const std::filesystem::path& scene_file);

}  // namespace vista
