// Grass benchmark: one fixed meadow view, the grass passes' GPU time per density, in
// milliseconds and reference copies measured in the same run.
#include "app/bench_grass.h"

#include "app/bench_start.h"
#include "app/frame.h"
#include "app/scene.h"
#include "app/stats.h"

#include <nlohmann/json.hpp>

#include <cstdio>

namespace vista {

int runBenchGrass(const BenchScene& isolated, const BenchGrassOptions& o) {
    const Settings& scene = isolated.settings;
    BenchRenderer bench;
    if (const int failed = startBench(isolated, o.backend, o.width, o.height, bench)) return failed;
    FrameRenderer& renderer = *bench.renderer;
    const GlContext& context = *bench.context;

    Settings s = scene;
    s.terrain.enabled = true;
    s.grass.enabled = true;
    s.sky.enabled = false;  // the grass passes are measured; keep the rest of the frame small
    s.lights.enabled = false;
    InputErrors errors = renderer.prepare(s);
    if (!errors.empty() || !renderer.terrain()) {
        printErrors(errors);
        return 2;
    }
    // The default island's southern meadow (a gentle slope in the grass band), at eye height,
    // looking north along it; another scene uses the same spot on its own terrain.
    const double x = 0.0, z = 2530.0;
    ViewParams view{{x, renderer.terrain()->heightAt(x, z) + 1.7, z}, 0.0, -12.0, 60.0, 0.1, o.width, o.height};

    const double copy_ms = renderer.measureReferenceCopy(o.width, o.height);
    nlohmann::json rows = nlohmann::json::array();
    std::printf("%-10s %12s %10s %10s %12s %10s %10s %10s\n", "density", "considered", "blades", "cull_ms",
                "gbuffer_ms", "cull_cop", "draw_cop", "copies");
    for (float density : o.densities) {
        s.grass.density = density;
        std::vector<double> cull, draw, blades;
        FrameRequest request;
        std::vector<unsigned char> image;
        request.capture_ldr = &image;  // a sink, so the graph keeps the passes
        request.count_grass = true;
        for (int f = 0; f < o.frames + 2; ++f) {
            renderer.render(s, view, 10.0 + f / 30.0, request);
            FrameTiming t = renderer.timers().collect(true).back();
            std::uint64_t drawn = 0;
            for (const auto& c : renderer.counters().collect(true))
                if (c.name == "grass.blades") drawn = c.value;
            if (f < 2) continue;
            cull.push_back(passMs(t, "grass.cull"));
            draw.push_back(passMs(t, "grass.gbuffer"));
            blades.push_back(double(drawn));
        }
        const double c = median(cull), d = median(draw);
        const double considered = renderer.grass() ? double(renderer.grass()->considered()) : 0.0;
        std::printf("%-10.2f %12.0f %10.0f %10.3f %12.3f %10.2f %10.2f %10.2f\n", density, considered, median(blades), c, d,
                    c / copy_ms, d / copy_ms, (c + d) / copy_ms);
        rows.push_back({{"density", density},
                        {"considered", considered},
                        {"blades", median(blades)},
                        {"cull_gpu_ms", c},
                        {"gbuffer_gpu_ms", d},
                        {"gpu_ms", c + d},
                        {"copies", copy_ms > 0.0 ? (c + d) / copy_ms : 0.0},
                        {"memory_bytes", renderer.grass() ? renderer.grass()->memoryBytes() : 0}});
    }
    std::printf("reference_copy_ms %.4f\n", copy_ms);
    nlohmann::json out = {{"renderer", context.renderer()},
                          {"backend", backendName(o.backend)},
                          {"size", {o.width, o.height}},
                          {"radius_m", s.grass.radius_m},
                          {"reference_copy_ms", copy_ms},
                          {"rows", rows}};
    out["scene"] = isolated.json();
    return writeBenchJson(o.json, out.dump(2) + "\n", o.force);
}

}  // namespace vista
