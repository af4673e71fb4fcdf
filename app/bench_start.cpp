// A bench's context and renderer (see bench_start.h).
#include "app/bench_start.h"

#include "app/scene.h"
#include "app/stats.h"

#include <cstdio>

namespace vista {

int startBench(const BenchScene& scene, Backend backend, int width, int height, BenchRenderer& out, bool compile_all) {
    std::printf("%s", scene.summary().c_str());
    std::string error;
    out.context = createContext(backend, ContextOptions{width, height, false, false, false, false, "bench"}, error);
    if (!out.context) return fail(1, error);
    out.renderer = std::make_unique<FrameRenderer>(vistaRoot());
    if (compile_all && !out.renderer->compilePrograms(error)) return fail(1, "shader compilation failed:\n" + error);
    return 0;
}

}  // namespace vista
