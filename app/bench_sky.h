// `vista bench sky`: for a few LUT sizes and step counts, the sky's error against the CPU
// reference (PSNR) beside the LUT build time and the per-frame sky cost in reference copies.
#pragma once

#include "app/bench_scene.h"
#include "app/gl_context.h"
#include "config/settings.h"

#include <filesystem>
#include <string>
#include <vector>

namespace vista {

struct BenchSkyOptions {
    int width = 320, height = 180;  // frame size for the timings
    Backend backend = Backend::OSMesa;
    std::filesystem::path json;     // empty: table only
    std::vector<std::string> presets;  // LUT presets to measure (low, medium, default, high); empty: all
    bool clouds = true;             // also the cloud octave/step sweep
    int psnr_width = 128, psnr_height = 72;  // views compared with the CPU reference (~0.1 ms a pixel on the CPU)
    bool force = false;  // --force: replace an existing --json file
};

// The LUT presets bench sky knows, in order.
std::vector<std::string> benchSkyPresetNames();

// Returns the exit code.
// scene: the isolated scene (app/bench_scene.h), stated in the output and the JSON.
int runBenchSky(const BenchScene& scene, const BenchSkyOptions& options);

}  // namespace vista
