// `vista bench terrain`: CDLOD selection cost, triangle and node counts, screen-space error
// against the full-resolution heightmap, memory, and the GPU cost of the terrain pass, over
// random camera poses on a generated (or given) heightmap.
#pragma once

#include "app/bench_scene.h"
#include "app/gl_context.h"
#include "config/settings.h"

#include <cstdint>
#include <filesystem>
#include <string>

namespace vista {

struct BenchTerrainOptions {
    std::filesystem::path heightmap;  // empty: generate an island of `size`
    int size = 4097;                  // samples per side of the generated island
    int poses = 16;
    int width = 640, height = 360;    // frame size of the poses (the error is in its pixels)
    std::uint32_t seed = 1;           // island and poses
    Backend backend = Backend::OSMesa;
    std::filesystem::path json;       // empty: table only
    bool force = false;  // --force: replace an existing --json file
};

// Returns the exit code.
// scene: the isolated scene (app/bench_scene.h), stated in the output and the JSON.
int runBenchTerrain(const BenchScene& scene, const BenchTerrainOptions& options);

}  // namespace vista
