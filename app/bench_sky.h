// `vista bench sky`: for a few LUT sizes and step counts, the sky's error against the CPU
// reference (PSNR) beside the LUT build time and the per-frame sky cost in reference copies.
#pragma once

#include "app/gl_context.h"
#include "config/settings.h"

#include <filesystem>

namespace vista {

struct BenchSkyOptions {
    int width = 320, height = 180;  // frame size for the timings
    Backend backend = Backend::OSMesa;
    std::filesystem::path json;     // empty: table only
    bool force = false;  // --force: replace an existing --json file
};

// Returns the exit code.
int runBenchSky(const Settings& scene, const BenchSkyOptions& options);

}  // namespace vista
