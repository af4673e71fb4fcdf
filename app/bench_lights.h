// `vista bench lights`: the local-light culling methods compared on a generated scene (an island
// with a field of ground-level lights in front of the camera): GPU cost of culling + shading
// (also in reference copies), shading evaluations against the pairs that really need shading,
// CPU build cost and GPU memory. Sweeps reproduce the KU Leuven (002) experiment: light counts,
// resolution, tile size, hash node size, deferred against forward lists, a camera path (median
// and p95 per frame) and evaluations per pixel class (distance band) -- docs/lights-experiment.md.
#pragma once

#include "app/bench_scene.h"
#include "app/gl_context.h"
#include "config/settings.h"

#include <filesystem>
#include <string>
#include <utility>
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
    // Sweeps: counts (the methods over `lights`), resolution, tiles, nodes, forward, path, classes.
    std::vector<std::string> sweeps = {"counts"};
    bool methods_given = false;       // else the other sweeps leave naive out (its cost grows as lights x pixels)
    std::vector<std::pair<int, int>> resolutions = {{320, 180}, {640, 360}};  // the resolution sweep
    int sweep_lights = 1024;          // light count of every sweep but counts
    int path_frames = 16;             // frames of the path sweep
    std::filesystem::path charts;     // PNG charts go here (one per sweep); empty: beside --json, or none
    bool force = false;  // --force: replace an existing --json file
};

// The sweep names bench lights accepts, in the order it runs them.
std::vector<std::string> benchLightsSweeps();

// Returns the exit code.
// scene: the isolated scene (app/bench_scene.h), stated in the output and the JSON.
int runBenchLights(const BenchScene& scene, const BenchLightsOptions& options);

}  // namespace vista
