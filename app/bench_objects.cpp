// Objects benchmark: one fixed meadow view, a forest of growing size scattered over the whole
// terrain (every ground accepted, so the count is density x area), the object passes' GPU time
// in ms and reference copies beside terrain.gbuffer, measured in the same run.
#include "app/bench_objects.h"

#include "app/bench_start.h"
#include "app/frame.h"
#include "app/scene.h"
#include "app/stats.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>

namespace vista {

int runBenchObjects(const BenchScene& isolated, const BenchObjectsOptions& o) {
    BenchRenderer bench;
    if (const int failed = startBench(isolated, o.backend, o.width, o.height, bench)) return failed;
    FrameRenderer& renderer = *bench.renderer;
    const GlContext& context = *bench.context;

    Settings s = isolated.settings;
    s.terrain.enabled = true;
    s.sky.enabled = false;
    s.lights.enabled = false;
    s.objects.enabled = true;
    s.objects.objects.clear();
    s.objects.scatters.clear();
    InputErrors errors = renderer.prepare(s);
    if (!errors.empty() || !renderer.terrain()) {
        printErrors(errors);
        return 2;
    }
    const double x = 0.0, z = 2530.0;
    const ViewParams view{{x, renderer.terrain()->heightAt(x, z) + 1.7, z}, 0.0, -12.0, 60.0, 0.1, o.width, o.height};
    const double area = double(s.terrain.size_m) * double(s.terrain.size_m);

    const double copy_ms = renderer.measureReferenceCopy(o.width, o.height);
    nlohmann::json rows = nlohmann::json::array();
    std::printf("%-8s %9s %9s %9s %11s %9s %10s %10s %10s %9s %10s %9s\n", "trees", "placed", "drawn", "impostors", "triangles",
                "cull_ms", "gbuffer_ms", "terrain_ms", "copies", "terr_cop", "memory_MB", "cpu_ms");
    for (int trees : o.trees) {
        ScatterRule rule;
        rule.files = {"data/props/tree.glb"};
        rule.density = double(trees) / area;
        rule.cell_m = 64.0f;
        rule.scale_min = 0.8f;
        rule.scale_max = 1.3f;
        rule.seed = 5;
        s.objects.scatters = {{"bench", rule}};
        errors = renderer.prepare(s);
        if (!errors.empty()) {
            printErrors(errors);
            return 2;
        }
        std::vector<double> cull, draw, terrain, drawn, impostors, tris, cpu;
        FrameRequest request;
        std::vector<unsigned char> image;
        request.capture_ldr = &image;
        request.count_objects = true;
        for (int f = 0; f < o.frames + 2; ++f) {
            const auto start = std::chrono::steady_clock::now();
            renderer.render(s, view, 10.0, request);
            const double cpu_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
            FrameTiming t = renderer.timers().collect(true).back();
            std::uint64_t n = 0, tri = 0, imp = 0;
            for (const auto& c : renderer.counters().collect(true)) {
                if (c.name == "objects.instances") n = c.value;
                if (c.name == "objects.triangles") tri = c.value;
                if (c.name == "objects.impostors") imp = c.value;
            }
            if (f < 2) continue;
            cull.push_back(passMs(t, "objects.cull"));
            draw.push_back(passMs(t, "objects.gbuffer"));
            terrain.push_back(passMs(t, "terrain.gbuffer"));
            drawn.push_back(double(n));
            impostors.push_back(double(imp));
            tris.push_back(double(tri));
            cpu.push_back(cpu_ms);
        }
        const Objects* objects = renderer.objects();
        const double placed = objects ? double(objects->stats().instances) : 0.0;
        const double memory = objects ? double(objects->memoryBytes()) : 0.0;
        const double c = median(cull), d = median(draw), te = median(terrain);
        std::printf("%-8d %9.0f %9.0f %9.0f %11.0f %9.3f %10.3f %10.3f %10.2f %9.2f %10.2f %9.2f\n", trees, placed, median(drawn),
                    median(impostors), median(tris), c, d, te, (c + d) / copy_ms, te / copy_ms, memory / 1048576.0, median(cpu));
        rows.push_back({{"trees", trees},
                        {"placed", placed},
                        {"drawn", median(drawn)},
                        {"impostors", median(impostors)},
                        {"triangles", median(tris)},
                        {"cull_gpu_ms", c},
                        {"gbuffer_gpu_ms", d},
                        {"terrain_gbuffer_gpu_ms", te},
                        {"copies", copy_ms > 0.0 ? (c + d) / copy_ms : 0.0},
                        {"terrain_copies", copy_ms > 0.0 ? te / copy_ms : 0.0},
                        {"instance_bytes", placed * double(kObjectInstanceBytes + kObjectSlotBytes)},
                        {"memory_bytes", memory},
                        {"cpu_ms", median(cpu)}});
    }
    std::printf("reference_copy_ms %.4f\n", copy_ms);
    nlohmann::json out = {{"renderer", context.renderer()},
                          {"backend", backendName(o.backend)},
                          {"size", {o.width, o.height}},
                          {"reference_copy_ms", copy_ms},
                          {"rows", rows}};
    out["scene"] = isolated.json();
    return writeBenchJson(o.json, out.dump(2) + "\n", o.force);
}

}  // namespace vista
