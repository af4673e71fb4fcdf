// Light culling benchmark: every (method, light count) on the same view in one run.
#include "app/bench_lights.h"

#include "app/frame.h"
#include "app/scene.h"
#include "app/stats.h"
#include "lighting/light_settings.h"
#include "lighting/local_lights.h"
#include "terrain/heightmap.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <map>
#include <string>

namespace vista {
namespace {

const char* methodName(LightCulling m) {
    switch (m) {
        case LightCulling::Naive: return "naive";
        case LightCulling::Tiled: return "tiled";
        case LightCulling::Clustered: return "clustered";
        case LightCulling::Hashed: return "hashed";
    }
    return "?";
}

// The light field: a square of side 1600 m in front of the camera, n lights on a jittered grid
// (nx * nz >= n, as square as possible; the listed defaults are squares), 3 m above the ground,
// warm random hues.
std::string fieldSpec(int n, float radius_m) {
    const int nx = std::max(1, int(std::lround(std::sqrt(double(n)))));
    const int nz = (n + nx - 1) / nx;
    char spec[256];
    std::snprintf(spec, sizeof spec,
                  "box -800 0 -1700 800 0 -100  count %d 1 %d  radius %g  intensity 400  saturation 0.6  "
                  "jitter 0.9  seed 5  ground 3",
                  nx, nz, double(radius_m));
    return spec;
}

struct Result {
    double gpu_ms = 0.0, copies = 0.0, build_ms = 0.0, frame_cpu_ms = 0.0;
    std::uint64_t count = 0, evaluations = 0, exact = 0, overflow = 0;
    std::size_t memory_bytes = 0;
};

}  // namespace

int runBenchLights(const Settings& scene, const BenchLightsOptions& o) {
    std::string error;
    auto context = createContext(o.backend, ContextOptions{o.width, o.height, false, false, false, false, "bench"}, error);
    if (!context) return fail(1, error);
    FrameRenderer renderer(vistaRoot());
    if (!renderer.compilePrograms(error)) return fail(1, "shader compilation failed:\n" + error);

    // A generated island (4 m texels) seen from its south, 150 m up, looking north and down.
    Settings s = scene;
    s.terrain.enabled = true;
    s.terrain.heightmap = "generated island 1025^2 seed 3 (bench lights)";
    s.terrain.size_m = 4096.0f;
    s.terrain.height_scale_m = 300.0f;
    s.terrain.height_offset_m = -30.0f;
    s.terrain.origin = glm::dvec3(0.0);
    s.sky.enabled = false;
    s.sky.sun_mode = SunMode::Angles;
    s.sky.sun_elevation_deg = -10.0f;  // night: the local lights carry the image
    s.debug.grid = false;
    s.debug.view = DebugView::Final;
    s.lights.enabled = true;
    s.lights.animation = LightAnimation{};
    InputErrors errors;
    std::fprintf(stderr, "bench lights: generating the island...\n");
    auto terrain = Terrain::create(generateIsland(IslandParams{1025, 3}), s.terrain, renderer.shaders(), errors);
    if (!terrain) {
        printErrors(errors);
        return 2;
    }
    const double ground = terrain->heightAt(0.0, 0.0);
    renderer.adoptTerrain(std::move(terrain));
    ViewParams view{{0.0, std::max(ground, 0.0) + 150.0, 0.0}, 0.0, -12.0, 60.0, 0.5, o.width, o.height};

    const double copy_ms = renderer.measureReferenceCopy(o.width, o.height);
    std::map<std::pair<int, int>, Result> results;  // (method, lights)
    nlohmann::json rows = nlohmann::json::array();
    std::printf("%-10s %7s %10s %8s %13s %11s %10s %9s %9s %12s %8s\n", "method", "lights", "gpu_ms", "copies",
                "evaluations", "exact", "efficiency", "build_ms", "frame_ms", "memory_bytes", "overflow");
    for (int n : o.lights) {
        s.lights.lights.clear();
        s.lights.volumes.clear();
        if (n > 0) {
            NamedLightVolume v{"field", {}};
            std::string problem = parseVolumeSpec(fieldSpec(n, o.radius_m), v.volume);
            if (!problem.empty()) return fail(2, "--lights " + std::to_string(n) + ": " + problem);
            s.lights.volumes.push_back(v);
        }
        for (LightCulling m : o.methods) {
            s.lights.culling = m;
            Result r;
            FrameRequest request;
            request.count_lights = true;
            std::vector<unsigned char> image;
            request.capture_ldr = &image;  // a sink, so the graph keeps the passes
            // Warm-up: the first frame compiles variants and builds the hashed octree (its cost is
            // build_ms); the next ones let the list pool grow to what the view needs.
            for (int w = 0; w < 3; ++w) {
                renderer.render(s, view, 0.0, request);
                renderer.timers().collect(true);
                renderer.counters().collect(true);
                if (w == 0)
                    if (const LocalLights* l = renderer.localLights()) r.build_ms = l->stats().build_ms;
            }
            std::vector<double> gpu, cpu;
            for (int f = 0; f < o.frames; ++f) {
                renderer.render(s, view, 0.0, request);
                FrameTiming t = renderer.timers().collect(true).back();
                double ms = 0.0;
                for (const auto& p : t.passes)
                    if (p.name == "lights.cull" || p.name == "lights.shade") ms += p.gpu_ms;
                gpu.push_back(ms);
                if (const LocalLights* l = renderer.localLights()) cpu.push_back(l->stats().build_ms);
                for (const auto& c : renderer.counters().collect(true)) {
                    if (f != o.frames - 1) continue;
                    if (c.name == "lights.evaluations") r.evaluations = c.value;
                    if (c.name == "lights.exact") r.exact = c.value;
                    if (c.name == "lights.overflow") r.overflow = c.value;
                }
            }
            r.gpu_ms = median(gpu);
            r.copies = copy_ms > 0.0 ? r.gpu_ms / copy_ms : 0.0;
            r.frame_cpu_ms = cpu.empty() ? 0.0 : median(cpu);
            if (const LocalLights* l = renderer.localLights()) {
                r.count = l->stats().count;
                r.memory_bytes = l->stats().memory_bytes;
            }
            const double efficiency = r.evaluations ? double(r.exact) / double(r.evaluations) : 0.0;
            std::printf("%-10s %7llu %10.3f %8.2f %13llu %11llu %10.3f %9.2f %9.3f %12zu %8llu\n", methodName(m),
                        (unsigned long long)r.count, r.gpu_ms, r.copies, (unsigned long long)r.evaluations,
                        (unsigned long long)r.exact, efficiency, r.build_ms, r.frame_cpu_ms, r.memory_bytes,
                        (unsigned long long)r.overflow);
            std::fflush(stdout);
            rows.push_back({{"method", methodName(m)}, {"lights", r.count}, {"gpu_ms_median", r.gpu_ms},
                            {"copies", r.copies}, {"evaluations", r.evaluations}, {"exact", r.exact},
                            {"efficiency", efficiency}, {"build_ms", r.build_ms}, {"frame_cpu_ms", r.frame_cpu_ms},
                            {"memory_bytes", r.memory_bytes}, {"overflow", r.overflow}});
            results[{int(m), n}] = r;
        }
    }

    // 002's comparisons: naive/tiled and tiled/clustered in evaluations, hashed against clustered,
    // and the frame-time gain over naive.
    nlohmann::json ratios = nlohmann::json::array();
    auto find = [&](LightCulling m, int n) -> const Result* {
        auto it = results.find({int(m), n});
        return it == results.end() ? nullptr : &it->second;
    };
    auto ratio = [](double a, double b) { return b > 0.0 ? a / b : 0.0; };
    std::printf("\n%7s %14s %18s %18s %16s %16s\n", "lights", "naive/tiled", "tiled/clustered", "hashed/clustered",
                "naive/clustered", "naive/hashed");
    std::printf("%7s %14s %18s %18s %16s %16s\n", "", "(evaluations)", "(evaluations)", "(evaluations)", "(gpu time)",
                "(gpu time)");
    for (int n : o.lights) {
        const Result *na = find(LightCulling::Naive, n), *ti = find(LightCulling::Tiled, n),
                     *cl = find(LightCulling::Clustered, n), *ha = find(LightCulling::Hashed, n);
        if (n == 0) continue;
        nlohmann::json row = {{"lights", n}};
        double a = na && ti ? ratio(double(na->evaluations), double(ti->evaluations)) : 0.0;
        double b = ti && cl ? ratio(double(ti->evaluations), double(cl->evaluations)) : 0.0;
        double c = ha && cl ? ratio(double(ha->evaluations), double(cl->evaluations)) : 0.0;
        double d = na && cl ? ratio(na->gpu_ms, cl->gpu_ms) : 0.0;
        double e = na && ha ? ratio(na->gpu_ms, ha->gpu_ms) : 0.0;
        std::printf("%7d %14.2f %18.2f %18.2f %16.2f %16.2f\n", n, a, b, c, d, e);
        row["naive_over_tiled_evaluations"] = a;
        row["tiled_over_clustered_evaluations"] = b;
        row["hashed_over_clustered_evaluations"] = c;
        row["naive_over_clustered_gpu"] = d;
        row["naive_over_hashed_gpu"] = e;
        ratios.push_back(row);
    }
    std::printf("\nreference_copy_ms %.4f  size %dx%d  tile %d px  renderer %s\n", copy_ms, o.width, o.height,
                tilePixels(s.lights.tile_size), context->renderer().c_str());
    if (!o.json.empty()) {
        nlohmann::json out = {{"rows", rows},
                              {"ratios", ratios},
                              {"reference_copy_ms", copy_ms},
                              {"size", {o.width, o.height}},
                              {"tile_px", tilePixels(s.lights.tile_size)},
                              {"radius_m", o.radius_m},
                              {"renderer", context->renderer()},
                              {"backend", backendName(o.backend)}};
        std::string problem = writeFileAtomic(o.json, out.dump(2) + "\n", o.force);
        if (!problem.empty()) return fail(1, problem);
    }
    return 0;
}

}  // namespace vista
