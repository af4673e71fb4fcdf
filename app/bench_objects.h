// `vista bench objects`: a forest of N procedural trees (data/props/tree.glb) scattered over the
// scene's terrain, N = 1k, 10k, 100k by default: instances placed and drawn, triangles drawn,
// the GPU cost of objects.cull + objects.gbuffer (ms and reference copies) beside the terrain's
// own G-buffer pass in the same frames, the instances' GPU memory and the frame's CPU time,
// from the meadow at eye height (the view of bench grass).
#pragma once

#include "app/bench_scene.h"
#include "app/gl_context.h"
#include "config/settings.h"

#include <filesystem>
#include <vector>

namespace vista {

struct BenchObjectsOptions {
    std::vector<int> trees{1000, 10000, 100000};
    int width = 640, height = 360;
    int frames = 3;                   // timed frames per count, after two warm-up frames
    Backend backend = Backend::OSMesa;
    std::filesystem::path json;       // empty: table only
    bool force = false;
};

int runBenchObjects(const BenchScene& scene, const BenchObjectsOptions& options);

}  // namespace vista
