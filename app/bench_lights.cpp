// Light culling benchmark: every (method, light count) on the same view in one run, and the
// sweeps of the KU Leuven experiment (002) over the same scene.
#include "app/bench_lights.h"

#include "app/chart.h"
#include "app/bench_start.h"
#include "app/frame.h"
#include "app/scene.h"
#include "app/stats.h"
#include "renderer/lighting/light_settings.h"
#include "renderer/lighting/local_lights.h"
#include "terrain/heightmap.h"

#include <nlohmann/json.hpp>

#include <algorithm>
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
    double gpu_ms = 0.0, cull_ms = 0.0, shade_ms = 0.0, copies = 0.0, build_ms = 0.0, frame_cpu_ms = 0.0;
    std::uint64_t count = 0, evaluations = 0, exact = 0, overflow = 0;
    std::size_t memory_bytes = 0;
    LightHashStats hash;  // hashed only
};

const char* const kSweeps[] = {"counts", "resolution", "tiles", "nodes", "forward", "path", "classes"};

// The distance bands of the classes sweep (view-space depth, m); the sky is its own class.
constexpr double kBands[] = {50.0, 150.0, 400.0, 1000.0, 1e30};

struct Context {
    FrameRenderer& renderer;
    const BenchLightsOptions& o;
    std::map<std::pair<int, int>, double> copy_ms;  // per frame size

    double copyMs(int w, int h) {
        auto it = copy_ms.find({w, h});
        if (it == copy_ms.end()) it = copy_ms.emplace(std::make_pair(w, h), renderer.measureReferenceCopy(w, h)).first;
        return it->second;
    }

    // Warm-up frames (programs, the hashed octree, the list pool), then `frames` timed ones: medians.
    Result measure(const Settings& s, const ViewParams& view, int frames, bool forward, int warmup = 3) {
        Result r;
        FrameRequest request;
        request.count_lights = true;
        request.forward_lights = forward;
        std::vector<unsigned char> image;
        request.capture_ldr = &image;  // a sink, so the graph keeps the passes
        for (int w = 0; w < warmup; ++w) {
            renderer.render(s, view, 0.0, request);
            renderer.timers().collect(true);
            renderer.counters().collect(true);
            if (w == 0)
                if (const LocalLights* l = renderer.localLights()) r.build_ms = l->stats().build_ms;
        }
        std::vector<double> gpu, cull, shade, cpu;
        for (int f = 0; f < frames; ++f) {
            renderer.render(s, view, 0.0, request);
            FrameTiming t = renderer.timers().collect(true).back();
            cull.push_back(passMs(t, "lights.cull"));
            shade.push_back(passMs(t, "lights.shade"));
            gpu.push_back(cull.back() + shade.back());
            if (const LocalLights* l = renderer.localLights()) cpu.push_back(l->stats().build_ms);
            for (const auto& c : renderer.counters().collect(true)) {
                if (f != frames - 1) continue;
                if (c.name == "lights.evaluations") r.evaluations = c.value;
                if (c.name == "lights.exact") r.exact = c.value;
                if (c.name == "lights.overflow") r.overflow = c.value;
            }
        }
        r.gpu_ms = median(gpu);
        r.cull_ms = median(cull);
        r.shade_ms = median(shade);
        const double copy = copyMs(view.width, view.height);
        r.copies = copy > 0.0 ? r.gpu_ms / copy : 0.0;
        r.frame_cpu_ms = cpu.empty() ? 0.0 : median(cpu);
        if (const LocalLights* l = renderer.localLights()) {
            r.count = l->stats().count;
            r.memory_bytes = l->stats().memory_bytes;
            r.hash = l->stats().hash;
        }
        return r;
    }
};

nlohmann::json rowJson(const char* sweep, LightCulling m, const Result& r, const ViewParams& view, const Settings& s) {
    nlohmann::json row = {{"sweep", sweep},
                          {"method", methodName(m)},
                          {"lights", r.count},
                          {"width", view.width},
                          {"height", view.height},
                          {"tile_px", tilePixels(s.lights.tile_size)},
                          {"gpu_ms_median", r.gpu_ms},
                          {"cull_ms", r.cull_ms},
                          {"shade_ms", r.shade_ms},
                          {"copies", r.copies},
                          {"evaluations", r.evaluations},
                          {"exact", r.exact},
                          {"efficiency", r.evaluations ? double(r.exact) / double(r.evaluations) : 0.0},
                          {"build_ms", r.build_ms},
                          {"frame_cpu_ms", r.frame_cpu_ms},
                          {"memory_bytes", r.memory_bytes},
                          {"overflow", r.overflow}};
    if (m == LightCulling::Hashed)
        row["hash"] = {{"node_size_m", r.hash.node_size_m}, {"levels", r.hash.levels}, {"degraded", r.hash.degraded},
                       {"leaf_cells", r.hash.leaf_cells}, {"index_count", r.hash.index_count},
                       {"gpu_bytes", r.hash.gpu_bytes}, {"build_ms", r.hash.ms}};
    return row;
}

void printRow(const char* label, LightCulling m, const Result& r) {
    const double efficiency = r.evaluations ? double(r.exact) / double(r.evaluations) : 0.0;
    std::printf("%-16s %-10s %7llu %10.3f %8.2f %13llu %11llu %10.3f %9.2f %9.3f %12zu %8llu\n", label, methodName(m),
                (unsigned long long)r.count, r.gpu_ms, r.copies, (unsigned long long)r.evaluations,
                (unsigned long long)r.exact, efficiency, r.build_ms, r.frame_cpu_ms, r.memory_bytes,
                (unsigned long long)r.overflow);
    std::fflush(stdout);
}

void printHeader(const char* sweep) {
    std::printf("\n== sweep %s\n%-16s %-10s %7s %10s %8s %13s %11s %10s %9s %9s %12s %8s\n", sweep, "point", "method",
                "lights", "gpu_ms", "copies", "evaluations", "exact", "efficiency", "build_ms", "frame_ms", "memory_bytes",
                "overflow");
}

std::string setLightField(Settings& s, int n, float radius_m) {
    s.lights.lights.clear();
    s.lights.volumes.clear();
    if (n <= 0) return {};
    NamedLightVolume v{"field", {}};
    std::string problem = parseVolumeSpec(fieldSpec(n, radius_m), v.volume);
    if (!problem.empty()) return "--lights " + std::to_string(n) + ": " + problem;
    s.lights.volumes.push_back(v);
    return {};
}

// The path sweep's camera: from 200 m south of the field, 150 m up, to over its middle at 40 m,
// turning from 20 deg left to 20 deg right and pitching down.
ViewParams pathView(double ground, double u, int width, int height) {
    const double z = 200.0 - 1300.0 * u, y = std::max(ground, 0.0) + 150.0 - 110.0 * u;
    return ViewParams{{0.0, y, z}, -20.0 + 40.0 * u, -12.0 - 10.0 * u, 60.0, 0.5, width, height};
}

double percentile(std::vector<double> v, double p) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    const std::size_t i = std::min(v.size() - 1, std::size_t(std::ceil(p * double(v.size()))) - 1);
    return v[i];
}

}  // namespace

std::vector<std::string> benchLightsSweeps() { return {std::begin(kSweeps), std::end(kSweeps)}; }

int runBenchLights(const BenchScene& isolated, const BenchLightsOptions& o) {
    const Settings& scene = isolated.settings;
    BenchRenderer bench;
    if (const int failed = startBench(isolated, o.backend, o.width, o.height, bench)) return failed;
    FrameRenderer& renderer = *bench.renderer;
    const GlContext& context = *bench.context;

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
    const ViewParams view{{0.0, std::max(ground, 0.0) + 150.0, 0.0}, 0.0, -12.0, 60.0, 0.5, o.width, o.height};
    Context ctx{renderer, o, {}};
    const double copy_ms = ctx.copyMs(o.width, o.height);

    auto wants = [&](const char* sweep) {
        return std::find(o.sweeps.begin(), o.sweeps.end(), sweep) != o.sweeps.end() ||
               std::find(o.sweeps.begin(), o.sweeps.end(), "all") != o.sweeps.end();
    };
    // The sweeps but counts leave naive out unless asked for: its cost grows as lights x pixels.
    std::vector<LightCulling> sweep_methods;
    for (LightCulling m : o.methods)
        if (o.methods_given || m != LightCulling::Naive) sweep_methods.push_back(m);
    const std::filesystem::path chart_dir =
        !o.charts.empty() ? o.charts : o.json.empty() ? std::filesystem::path() : o.json.parent_path();
    std::vector<std::string> chart_files;
    auto chart = [&](const std::string& name, const Chart& c) -> std::string {
        if (chart_dir.empty() && o.charts.empty() && o.json.empty()) return {};
        std::error_code ec;
        std::filesystem::create_directories(chart_dir.empty() ? "." : chart_dir, ec);
        const std::filesystem::path file = (chart_dir.empty() ? std::filesystem::path(".") : chart_dir) / ("lights_" + name + ".png");
        std::string problem = writeChart(file, c);
        if (problem.empty()) chart_files.push_back(file.string());
        return problem;
    };
    nlohmann::json rows = nlohmann::json::array(), ratios = nlohmann::json::array(), sweeps = nlohmann::json::object();
    std::string chart_problem;

    if (wants("counts")) {
        std::map<std::pair<int, int>, Result> results;  // (method, lights)
        printHeader("counts");
        for (int n : o.lights) {
            if (std::string p = setLightField(s, n, o.radius_m); !p.empty()) return fail(2, p);
            for (LightCulling m : o.methods) {
                s.lights.culling = m;
                Result r = ctx.measure(s, view, o.frames, false);
                printRow(("lights=" + std::to_string(n)).c_str(), m, r);
                rows.push_back(rowJson("counts", m, r, view, s));
                results[{int(m), n}] = r;
            }
        }
        // 002's comparisons: naive/tiled and tiled/clustered in evaluations, hashed against clustered,
        // and the frame-time gain over naive.
        auto find = [&](LightCulling m, int n) -> const Result* {
            auto it = results.find({int(m), n});
            return it == results.end() ? nullptr : &it->second;
        };
        auto ratio = [](double a, double b) { return b > 0.0 ? a / b : 0.0; };
        std::printf("\n%7s %14s %18s %18s %16s %16s\n", "lights", "naive/tiled", "tiled/clustered", "hashed/clustered",
                    "naive/clustered", "naive/hashed");
        std::printf("%7s %14s %18s %18s %16s %16s\n", "", "(evaluations)", "(evaluations)", "(evaluations)", "(gpu time)",
                    "(gpu time)");
        Chart c{"bench lights: evaluations per frame against light count", "lights", "evaluations per frame", true, true, {}};
        for (LightCulling m : o.methods) {
            ChartSeries series{methodName(m), {}, {}};
            for (int n : o.lights)
                if (const Result* r = find(m, n); r && n > 0) {
                    series.x.push_back(double(n));
                    series.y.push_back(double(r->evaluations));
                }
            c.series.push_back(series);
        }
        if (std::string p = chart("counts", c); !p.empty()) chart_problem = p;
        for (int n : o.lights) {
            const Result *na = find(LightCulling::Naive, n), *ti = find(LightCulling::Tiled, n),
                         *cl = find(LightCulling::Clustered, n), *ha = find(LightCulling::Hashed, n);
            if (n == 0) continue;
            nlohmann::json row = {{"lights", n}};
            double a = na && ti ? ratio(double(na->evaluations), double(ti->evaluations)) : 0.0;
            double b = ti && cl ? ratio(double(ti->evaluations), double(cl->evaluations)) : 0.0;
            double d2 = ha && cl ? ratio(double(ha->evaluations), double(cl->evaluations)) : 0.0;
            double d = na && cl ? ratio(na->gpu_ms, cl->gpu_ms) : 0.0;
            double e = na && ha ? ratio(na->gpu_ms, ha->gpu_ms) : 0.0;
            std::printf("%7d %14.2f %18.2f %18.2f %16.2f %16.2f\n", n, a, b, d2, d, e);
            row["naive_over_tiled_evaluations"] = a;
            row["tiled_over_clustered_evaluations"] = b;
            row["hashed_over_clustered_evaluations"] = d2;
            row["naive_over_clustered_gpu"] = d;
            row["naive_over_hashed_gpu"] = e;
            ratios.push_back(row);
        }
    }

    if (std::string p = setLightField(s, o.sweep_lights, o.radius_m); !p.empty()) return fail(2, p);
    const LightTileSize default_tile = s.lights.tile_size;

    if (wants("resolution")) {
        printHeader("resolution");
        Chart c{"bench lights: evaluations per frame against resolution, " + std::to_string(o.sweep_lights) + " lights",
                "pixels", "evaluations per frame", true, true, {}};
        for (LightCulling m : sweep_methods) {
            s.lights.culling = m;
            ChartSeries series{methodName(m), {}, {}};
            for (auto [w, h] : o.resolutions) {
                ViewParams v = view;
                v.width = w, v.height = h;
                Result r = ctx.measure(s, v, o.frames, false);
                printRow((std::to_string(w) + "x" + std::to_string(h)).c_str(), m, r);
                rows.push_back(rowJson("resolution", m, r, v, s));
                series.x.push_back(double(w) * double(h));
                series.y.push_back(double(r.evaluations));
            }
            c.series.push_back(series);
        }
        if (std::string p = chart("resolution", c); !p.empty()) chart_problem = p;
    }

    if (wants("tiles")) {
        printHeader("tiles");
        Chart c{"bench lights: GPU cost (cull + shade) against tile size, " + std::to_string(o.sweep_lights) + " lights",
                "tile px", "copies", true, false, {}};
        for (LightCulling m : sweep_methods) {
            if (m != LightCulling::Tiled && m != LightCulling::Clustered) continue;  // the others have no tiles
            s.lights.culling = m;
            ChartSeries series{methodName(m), {}, {}};
            for (LightTileSize t : {LightTileSize::Px8, LightTileSize::Px16, LightTileSize::Px32, LightTileSize::Px64}) {
                s.lights.tile_size = t;
                Result r = ctx.measure(s, view, o.frames, false);
                printRow(("tile=" + std::to_string(tilePixels(t))).c_str(), m, r);
                rows.push_back(rowJson("tiles", m, r, view, s));
                series.x.push_back(double(tilePixels(t)));
                series.y.push_back(r.copies);
            }
            c.series.push_back(series);
        }
        s.lights.tile_size = default_tile;
        if (std::string p = chart("tiles", c); !p.empty()) chart_problem = p;
    }

    if (wants("nodes") && std::find(sweep_methods.begin(), sweep_methods.end(), LightCulling::Hashed) != sweep_methods.end()) {
        printHeader("nodes");
        Chart c{"bench lights: hashed octree against leaf node size, " + std::to_string(o.sweep_lights) + " lights",
                "node size / light radius", "value", true, true, {}};
        ChartSeries evals{"evaluations", {}, {}}, memory{"GPU bytes", {}, {}}, build{"build us (CPU)", {}, {}};
        s.lights.culling = LightCulling::Hashed;
        for (double f : {0.25, 0.5, 1.0, 2.0}) {
            s.lights.hash_node_m = float(f * o.radius_m);
            Result r = ctx.measure(s, view, o.frames, false);
            char label[32];
            std::snprintf(label, sizeof label, "node=%.2gr", f);
            printRow(label, LightCulling::Hashed, r);
            nlohmann::json row = rowJson("nodes", LightCulling::Hashed, r, view, s);
            row["node_over_radius"] = f;
            rows.push_back(row);
            evals.x.push_back(f), evals.y.push_back(double(r.evaluations));
            memory.x.push_back(f), memory.y.push_back(double(r.hash.gpu_bytes));
            build.x.push_back(f), build.y.push_back(r.hash.ms * 1000.0);
        }
        s.lights.hash_node_m = scene.lights.hash_node_m;
        c.series = {evals, memory, build};
        if (std::string p = chart("nodes", c); !p.empty()) chart_problem = p;
    }

    if (wants("forward")) {
        printHeader("forward");
        for (LightCulling m : sweep_methods) {
            s.lights.culling = m;
            for (bool forward : {false, true}) {
                Result r = ctx.measure(s, view, o.frames, forward);
                printRow(forward ? "forward lists" : "deferred", m, r);
                nlohmann::json row = rowJson("forward", m, r, view, s);
                row["forward"] = forward;
                rows.push_back(row);
            }
        }
    }

    if (wants("path")) {
        printHeader("path");
        Chart c{"bench lights: GPU cost per frame along the camera path, " + std::to_string(o.sweep_lights) + " lights",
                "frame", "copies", false, false, {}};
        nlohmann::json summary = nlohmann::json::array();
        std::printf("%-10s %12s %12s %10s %16s %16s\n", "method", "ms_median", "ms_p95", "p95/median", "evals_median",
                    "evals_p95");
        for (LightCulling m : sweep_methods) {
            s.lights.culling = m;
            ctx.measure(s, pathView(ground, 0.0, o.width, o.height), 1, false);  // warm-up at the start
            ChartSeries series{methodName(m), {}, {}};
            std::vector<double> ms, evals;
            for (int f = 0; f < o.path_frames; ++f) {
                const double u = o.path_frames > 1 ? double(f) / double(o.path_frames - 1) : 0.0;
                const ViewParams v = pathView(ground, u, o.width, o.height);
                Result r = ctx.measure(s, v, 1, false, 0);
                nlohmann::json row = rowJson("path", m, r, v, s);
                row["frame"] = f;
                rows.push_back(row);
                ms.push_back(r.gpu_ms);
                evals.push_back(double(r.evaluations));
                series.x.push_back(double(f));
                series.y.push_back(r.copies);
            }
            c.series.push_back(series);
            const double med = median(ms), p95 = percentile(ms, 0.95);
            std::printf("%-10s %12.3f %12.3f %10.2f %16.0f %16.0f\n", methodName(m), med, p95, med > 0 ? p95 / med : 0.0,
                        median(evals), percentile(evals, 0.95));
            summary.push_back({{"method", methodName(m)}, {"gpu_ms_median", med}, {"gpu_ms_p95", p95},
                               {"p95_over_median", med > 0 ? p95 / med : 0.0}, {"evaluations_median", median(evals)},
                               {"evaluations_p95", percentile(evals, 0.95)}, {"frames", o.path_frames}});
        }
        sweeps["path"] = summary;
        if (std::string p = chart("path", c); !p.empty()) chart_problem = p;
    }

    if (wants("classes")) {
        // Where the evaluations go: per pixel, by view distance band (and the sky), from the
        // per-pixel heat target and the depth buffer read back.
        std::printf("\n== sweep classes (evaluations per pixel by view distance)\n%-10s", "method");
        const char* names[] = {"<50m", "50-150m", "150-400m", "400-1000m", ">1000m", "sky"};
        for (const char* n : names) std::printf(" %12s", n);
        std::printf("\n%-10s", "(pixels)");
        nlohmann::json classes = nlohmann::json::array();
        Chart c{"bench lights: evaluations per pixel by view distance, " + std::to_string(o.sweep_lights) + " lights",
                "distance band upper edge (m)", "evaluations per pixel", true, true, {}};
        bool first = true;
        for (LightCulling m : sweep_methods) {
            s.lights.culling = m;
            ctx.measure(s, view, 1, false);  // warm-up
            std::vector<float> heat, depth;
            std::vector<unsigned char> image;
            FrameRequest request;
            request.capture_ldr = &image;
            request.light_heat = &heat;
            request.depth = &depth;
            renderer.render(s, view, 0.0, request);
            renderer.timers().collect(true);
            renderer.counters().collect(true);
            double pixels[6] = {}, evals[6] = {};
            const std::size_t n = std::size_t(view.width) * std::size_t(view.height);
            if (heat.size() == n * 4 && depth.size() == n)
                for (std::size_t i = 0; i < n; ++i) {
                    int k = 5;
                    if (depth[i] > 0.0f) {
                        const double z = view.near_m / double(depth[i]);
                        k = 0;
                        while (z >= kBands[k]) ++k;
                    }
                    pixels[k] += 1.0;
                    evals[k] += double(heat[i * 4]);
                }
            if (first) {
                for (double p : pixels) std::printf(" %12.0f", p);
                first = false;
            }
            std::printf("\n%-10s", methodName(m));
            nlohmann::json row = {{"method", methodName(m)}};
            ChartSeries series{methodName(m), {}, {}};
            for (int k = 0; k < 6; ++k) {
                const double per = pixels[k] > 0 ? evals[k] / pixels[k] : 0.0;
                std::printf(" %12.2f", per);
                row[names[k]] = {{"pixels", pixels[k]}, {"evaluations", evals[k]}, {"per_pixel", per}};
                if (k < 5) series.x.push_back(std::min(kBands[k], 4000.0)), series.y.push_back(per);
            }
            classes.push_back(row);
            c.series.push_back(series);
        }
        std::printf("\n");
        sweeps["classes"] = classes;
        if (std::string p = chart("classes", c); !p.empty()) chart_problem = p;
    }

    std::printf("\nreference_copy_ms %.4f  size %dx%d  tile %d px  renderer %s\n", copy_ms, o.width, o.height,
                tilePixels(default_tile), context.renderer().c_str());
    for (const std::string& f : chart_files) std::printf("chart: %s\n", f.c_str());
    if (!chart_problem.empty()) std::fprintf(stderr, "vista: bench lights: chart not written: %s\n", chart_problem.c_str());
    if (!o.json.empty()) {
        nlohmann::json out = {{"rows", rows},
                              {"ratios", ratios},
                              {"sweeps", sweeps},
                              {"charts", chart_files},
                              {"reference_copy_ms", copy_ms},
                              {"size", {o.width, o.height}},
                              {"tile_px", tilePixels(default_tile)},
                              {"radius_m", o.radius_m},
                              {"sweep_lights", o.sweep_lights},
                              {"renderer", context.renderer()},
                              {"backend", backendName(o.backend)}};
        out["scene"] = isolated.json();
        std::string problem = writeFileAtomic(o.json, out.dump(2) + "\n", o.force);
        if (!problem.empty()) return fail(1, problem);
    }
    return chart_problem.empty() ? 0 : 1;
}

}  // namespace vista
