// What every bench (app/bench_*.cpp) starts with: the scene it measures stated, a hidden GL
// context of the bench's size and a renderer on it.
#pragma once

#include "app/bench_scene.h"
#include "app/frame.h"
#include "app/gl_context.h"

#include <memory>

namespace vista {

struct BenchRenderer {
    std::unique_ptr<GlContext> context;
    std::unique_ptr<FrameRenderer> renderer;  // destroyed before the context
};

// Prints scene's summary, creates the context (width x height on backend) and the renderer and,
// with compile_all, compiles every program up front so no timed frame waits for a compile. On
// failure prints why and returns the exit status (1); else 0.
int startBench(const BenchScene& scene, Backend backend, int width, int height, BenchRenderer& out,
               bool compile_all = true);

}  // namespace vista
