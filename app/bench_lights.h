// `vista bench lights`: the local-light culling methods compared on one fixed view of a
// generated scene (an island with a field of ground-level lights in front of the camera), for
// several light counts: GPU cost of culling + shading (also in reference copies), shading
// evaluations against the pairs that really need shading, CPU build cost and GPU memory.
#pragma once

#include "app/gl_context.h"
#include "config/settings.h"

#include <filesystem>
#include <vector>

namespace vista {

struct BenchLightsOptions {
    std::vector<int> lights = {0, 64, 256, 1024, 4096, 16384};
    std::vector<LightCulling> methods = {LightCulling::Naive, LightCulling::Tiled, LightCulling::Clustered,
                                         LightCulling::Hashed};
    int width = 320, height = 180;
    int frames = 3;                   // timed frames per (method, lights), after one warm-up
    float radius_m = 40.0f;           // every light's radius
    Backend backend = Backend::OSMesa;
    std::filesystem::path json;       // empty: table only
    bool force = false;  // --force: replace an existing --json file
};

// Returns the exit code.
int runBenchLights(const Settings& scene, const BenchLightsOptions& options);

}  // namespace vista
