// `vista bench grass`: blades drawn and the GPU cost of grass.cull + grass.gbuffer (ms and
// reference copies) at a few densities, from a meadow of the scene's terrain at eye height.
#pragma once

#include "app/bench_scene.h"
#include "app/gl_context.h"
#include "config/settings.h"

#include <filesystem>
#include <vector>

namespace vista {

struct BenchGrassOptions {
    std::vector<float> densities{4.0f, 8.0f, 16.0f, 24.0f, 48.0f};  // blades per m^2
    int width = 640, height = 360;
    int frames = 5;                   // timed frames per density, after two warm-up frames
    Backend backend = Backend::OSMesa;
    std::filesystem::path json;       // empty: table only
    bool force = false;  // --force: replace an existing --json file
};

// Returns the exit code.
// scene: the isolated scene (app/bench_scene.h), stated in the output and the JSON.
int runBenchGrass(const BenchScene& scene, const BenchGrassOptions& options);

}  // namespace vista
