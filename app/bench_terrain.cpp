// Terrain benchmark: everything measured in one run, GPU cost also in reference copies.
#include "app/bench_terrain.h"

#include "app/bench_start.h"
#include "app/frame.h"
#include "app/scene.h"
#include "app/stats.h"
#include "terrain/heightmap.h"

#include <glm/gtc/packing.hpp>
#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <random>

namespace vista {
namespace {

// Camera poses over the inner part of the map, 10..600 m above the ground, looking ahead
// and down: what a fly-through sees. Deterministic for a seed.
std::vector<ViewParams> randomPoses(const Terrain& terrain, const TerrainSettings& s, int count, std::uint32_t seed,
                                    int width, int height) {
    std::mt19937 rng(seed);
    auto uniform = [&](double lo, double hi) { return lo + (hi - lo) * double(rng()) / double(rng.max()); };
    std::vector<ViewParams> poses;
    double half = s.size_m * 0.4;
    for (int i = 0; i < count; ++i) {
        double x = s.origin.x + uniform(-half, half), z = s.origin.z + uniform(-half, half);
        double above = std::exp(uniform(std::log(10.0), std::log(600.0)));
        ViewParams v;
        v.position = {x, terrain.heightAt(x, z) + above, z};
        v.yaw_deg = uniform(-180.0, 180.0);
        v.pitch_deg = uniform(-30.0, -3.0);
        v.fov_deg = 60.0;
        v.near_m = 0.5;
        v.width = width;
        v.height = height;
        poses.push_back(v);
    }
    return poses;
}

// Largest vertical screen error (px) of a frame rendered with [terrain] view = error, which
// writes it to the HDR target's alpha (background pixels hold 0).
double maxErrorPx(FrameRenderer& renderer, Settings s, const ViewParams& view) {
    std::vector<std::uint16_t> hdr;
    FrameRequest request;
    request.capture_hdr = &hdr;
    s.terrain.view = TerrainView::Error;
    renderer.render(s, view, 0.0, request);
    double worst = 0.0;
    for (std::size_t i = 3; i < hdr.size(); i += 4) worst = std::max(worst, double(glm::unpackHalf1x16(hdr[i])));
    return worst;
}

}  // namespace

int runBenchTerrain(const BenchScene& isolated, const BenchTerrainOptions& o) {
    const Settings& scene = isolated.settings;
    const int width = o.width, height = o.height;
    BenchRenderer bench;
    if (const int failed = startBench(isolated, o.backend, o.width, o.height, bench)) return failed;
    FrameRenderer& renderer = *bench.renderer;
    const GlContext& context = *bench.context;

    Settings s = scene;
    s.terrain.enabled = true;
    s.sky.enabled = false;  // the terrain pass alone is measured; keep the frame small
    InputErrors errors;
    Heightmap map;
    auto start = std::chrono::steady_clock::now();
    if (!o.heightmap.empty()) {
        s.terrain.heightmap = resolveInput(o.heightmap).string();
        map = loadHeightmap(s.terrain.heightmap, s.terrain.raw_width, s.terrain.raw_height, errors);
    } else {
        if (o.size < 2 || o.size > 16385) return fail(2, "--size " + std::to_string(o.size) + ": accepted 2..16385");
        std::fprintf(stderr, "bench terrain: generating a %dx%d island (seed %u)...\n", o.size, o.size, o.seed);
        map = generateIsland(IslandParams{o.size, o.seed});
        s.terrain.heightmap = "generated island " + std::to_string(o.size) + "^2 seed " + std::to_string(o.seed);
        // Keep the default island's 4 m texels, so larger maps are larger islands.
        s.terrain.size_m = float(o.size - 1) * 4.0f;
    }
    if (!errors.empty()) {
        printErrors(errors);
        return 2;
    }
    double prepare_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    start = std::chrono::steady_clock::now();
    std::unique_ptr<Terrain> made = Terrain::create(std::move(map), s.terrain, renderer.shaders(), errors);
    if (!made) {
        printErrors(errors);
        return 2;
    }
    double load_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    Terrain& terrain = *made;
    renderer.adoptTerrain(std::move(made));

    RunStats stats;
    stats.reference_copy_ms = renderer.measureReferenceCopy(width, height);
    // The same poses with distance-only CDLOD whose ranges are raised to meet the same error
    // bound: what the per-node error metric saves.
    Settings distance = s;
    distance.terrain.lod_metric = LodMetric::Distance;
    std::vector<double> select_ms, triangles, nodes, draws, gpu_ms, triangles_distance, base_distance;
    double max_error = 0.0, max_error_distance = 0.0, base_error = 0.0;
    std::vector<unsigned char> ldr;
    FrameRequest request;
    request.capture_ldr = &ldr;
    for (const ViewParams& view : randomPoses(terrain, s.terrain, o.poses, o.seed, width, height)) {
        glm::dmat4 view_proj(viewMatrices(view).view_proj);
        const double error_scale = screenErrorScale(view.fov_deg, view.height);
        std::vector<double> samples;
        for (int r = 0; r < 15; ++r) {  // selection is microseconds: take the median of repeats
            auto t0 = std::chrono::steady_clock::now();
            terrain.select(view.position, view_proj, s.terrain, error_scale);
            samples.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
        }
        select_ms.push_back(median(samples));
        for (int r = 0; r < 2; ++r) renderer.render(s, view, 0.0, request);  // first frame warms up
        FrameTiming timing = renderer.timers().collect(true).back();
        for (const auto& p : timing.passes)
            if (p.name == "terrain.gbuffer") gpu_ms.push_back(p.gpu_ms);
        const TerrainCounters& c = terrain.counters();
        triangles.push_back(double(c.triangles));
        nodes.push_back(double(c.nodes));
        draws.push_back(double(c.draws));
        base_error = c.base_range_m;
        max_error = std::max(max_error, maxErrorPx(renderer, s, view));

        max_error_distance = std::max(max_error_distance, maxErrorPx(renderer, distance, view));
        triangles_distance.push_back(double(terrain.counters().triangles));
        base_distance.push_back(terrain.counters().base_range_m);
    }

    double gpu = median(gpu_ms);
    nlohmann::json out = {
        {"size", {terrain.heightmap().width, terrain.heightmap().height}},
        {"size_m", s.terrain.size_m},
        {"poses", o.poses},
        {"select_ms_median", median(select_ms)},
        {"triangles_median", median(triangles)},
        {"nodes_median", median(nodes)},
        {"draws_median", median(draws)},
        {"max_error_px", max_error},
        {"error_bound_px", s.terrain.max_error_px},
        {"triangles_distance_only_median", median(triangles_distance)},
        {"max_error_px_distance_only", max_error_distance},
        {"base_range_m", base_error},
        {"base_range_m_distance_only", median(base_distance)},
        {"memory_bytes", terrain.memoryBytes()},
        {"terrain_gpu_ms_median", gpu},
        {"reference_copy_ms", stats.reference_copy_ms},
        {"terrain_copies", stats.reference_copy_ms > 0 ? gpu / stats.reference_copy_ms : 0.0},
        {"viewport", {width, height}},
        {"renderer", context.renderer()},
        {"backend", backendName(o.backend)},
        {"heightmap_seconds", prepare_s},
        {"load_seconds", load_s},
    };
    for (auto it = out.begin(); it != out.end(); ++it) {
        std::string value = it.value().dump();
        std::printf("%-32s %s\n", it.key().c_str(), value.c_str());
    }
    out["scene"] = isolated.json();
    return writeBenchJson(o.json, out.dump(2) + "\n", o.force);
}

}  // namespace vista
