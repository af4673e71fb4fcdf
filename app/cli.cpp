// Subcommands and their options; each one loads the scene the same way and hands over to
// the window loop, the capture runner or the checker.
#include "app/cli.h"
#include "config/ini.h"
#include "config/presets.h"

#include "app/bench_grass.h"
#include "app/bench_objects.h"
#include "app/bench_scene.h"
#include "app/bench_lights.h"
#include "app/bench_shadows.h"
#include "app/bench_sky.h"
#include "app/bench_terrain.h"
#include "app/camera_path.h"
#include "app/capture.h"
#include "app/farm.h"
#include "app/quality.h"
#include "app/run_window.h"
#include "app/scene.h"
#include "app/light_placement.h"
#include "app/scene_check.h"
#include "app/sky_cmd.h"
#include "terrain/terrain.h"
#include "terrain/gen_heightmap.h"
#include "app/terrain_cache_cmd.h"
#include "renderer/meshes/gen_props.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <sstream>

namespace vista {
namespace {

std::string clipForMessage(const std::string& text);

// One side of --size: decimal digits only, parsed without overflow (sscanf's %d wrapped
// 4294967360 to 64).
bool parseSide(std::string_view text, int& value) {
    if (text.empty() || text.size() > 5) return false;
    value = 0;
    for (char c : text) {
        if (c < '0' || c > '9') return false;
        value = value * 10 + (c - '0');
    }
    return true;
}

// --size WxH into width and height (unchanged on error); false with a message when malformed.
bool parseSize(const std::string& size, int& width, int& height) {
    const auto x = size.find_first_of("xX");
    int w = 0, h = 0;
    if (x == std::string::npos || !parseSide(std::string_view(size).substr(0, x), w) ||
        !parseSide(std::string_view(size).substr(x + 1), h) || w < 1 || h < 1 || w > 16384 || h > 16384) {
        std::fprintf(stderr, "vista: --size %s: expected WxH with each side 1..16384, e.g. 320x180\n",
                     clipForMessage(size).c_str());
        return false;
    }
    width = w;
    height = h;
    return true;
}

// CLI11 reads "0x10" as 16 and "1e3" as 1000 for integers: options taking a count accept
// plain decimal digits only.
const CLI::Validator kDecimal(
    [](std::string& text) -> std::string {
        if (text.empty() || text.size() > 10 || text.find_first_not_of("0123456789") != std::string::npos)
            return "'" + clipForMessage(text) + "' is not a decimal whole number";
        return {};
    },
    "DECIMAL");

// CLI::Range lets NaN through (every comparison with it is false): reals must be finite.
const CLI::Validator kFinite(
    [](std::string& text) -> std::string {
        char* end = nullptr;
        const double v = std::strtod(text.c_str(), &end);
        if (end == text.c_str() || *end != '\0' || !std::isfinite(v))
            return "'" + clipForMessage(text) + "' is not a finite number";
        return {};
    },
    "FINITE");

// A value echoed in a message: at most 64 characters, so a 10 MB argument is not printed back.
std::string clipForMessage(const std::string& text) {
    return text.size() <= 64 ? text : text.substr(0, 61) + "... (" + std::to_string(text.size()) + " characters)";
}


struct SceneOptions {
    std::vector<std::string> configs;  // -c may repeat: later files override earlier ones
    std::vector<std::string> overrides;
    std::string preset;

    void add(CLI::App* cmd) {
        cmd->add_option("-c,--config", configs,
                        "scene file (default: config/default.ini); may repeat: later files override earlier ones, "
                        "e.g. -c config/default.ini -c config/presets/sunset.ini")
            ->allow_extra_args(false)
            ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
        cmd->add_option("--set", overrides, "override a scene key: --set section.key=value (repeatable)");
        cmd->add_option("--preset", preset, "quality preset over the scene's knobs (--set still wins)")
            ->check(CLI::IsMember({"low", "medium", "high", "ultra", "reference"}));
    }
    // The scene files in order (the default scene when none was given).
    std::vector<std::filesystem::path> files() const {
        if (configs.empty()) return {defaultScenePath()};
        std::vector<std::filesystem::path> out;
        for (const auto& c : configs) out.push_back(resolveInput(c));
        return out;
    }
    // The last scene file: the one a window saves to, and the one named in messages.
    std::filesystem::path file() const { return files().back(); }
    // Loads the scene; prints every problem and returns false on bad input.
    bool load(Settings& s) const {
        InputErrors errors = loadScene(files(), overrides, s);
        if (errors.empty() && !preset.empty()) {
            applyQualityPreset(s, *qualityPresetFromName(preset));
            for (const std::string& o : overrides) applyOverride(o, s);  // valid: loadScene took them
        }
        printErrors(errors);
        return errors.empty();
    }
};

struct CaptureOptions {
    std::string path, size, out, format, stats, dot, backend = "osmesa";
    int frames = 0;
    double fps = 0.0;
    bool force = false;
    std::string shard, frames_range;  // farm: the part of the path's frames to write
    bool resume = false;

    void add(CLI::App* cmd, bool images) {
        cmd->add_option("--path", path, "camera path file (default: [capture] path)");
        cmd->add_option("--frames", frames, "number of frames (default: [capture] frames)")->check(kDecimal)->check(CLI::Range(1, 1000000));
        cmd->add_option("--fps", fps, "frames per second of path time (default: [capture] fps)")->check(kFinite)->check(CLI::Range(0.01, 1000.0));
        cmd->add_option("--size", size, "image size WxH, e.g. 320x180 (default: [capture] width x height)");
        cmd->add_option("--backend", backend, "GL context: osmesa (default), egl or glfw (hidden window)")
            ->check(CLI::IsMember({"osmesa", "egl", "glfw"}));
        if (!images) return;
        cmd->add_option("--out", out, "output directory (default: [capture] out)");
        cmd->add_option("--format", format, "png (8-bit sRGB), exr (linear half float) or mp4 (PNG frames and an H.264 video)")
            ->check(CLI::IsMember({"png", "exr", "mp4"}));
        cmd->add_option("--stats", stats, "write per-pass timings and counters as JSON to this file");
        cmd->add_option("--dot", dot, "write the last frame's pass graph (Graphviz DOT; culled passes dashed)");
        cmd->add_flag("--force", force, "overwrite existing images, --stats and --dot files");
        cmd->add_option("--shard", shard, "render shard K of N (K from 0) of the selected frames: contiguous blocks");
        cmd->add_option("--frames-range", frames_range, "render frames A..B-1 of the path's frames only");
        cmd->add_flag("--resume", resume, "keep the frames whose files match this run's manifest; render the rest");
    }

    // --shard and --frames-range into a selection; false (with a message) when malformed.
    bool selection(FrameSelection& sel) const {
        std::string problem;
        if (!shard.empty()) problem = parseShard(shard, sel.shard, sel.shards);
        if (problem.empty() && !frames_range.empty()) problem = parseFrameRange(frames_range, sel.range.emplace());
        if (!problem.empty()) std::fprintf(stderr, "vista: %s\n", problem.c_str());
        return problem.empty();
    }

    // Applies the flags over [capture]; false (with a message) on a malformed --size.
    bool apply(CaptureSettings& c) const {
        if (!path.empty()) c.path = path;
        if (frames > 0) c.frames = frames;
        if (fps > 0.0) c.fps = float(fps);
        if (!out.empty()) c.out = out;
        if (!format.empty()) c.format = format == "exr" ? ImageFormat::Exr : format == "mp4" ? ImageFormat::Mp4 : ImageFormat::Png;
        return size.empty() || parseSize(size, c.width, c.height);
    }

    Backend backendValue() const {
        static const std::map<std::string, Backend> names{{"osmesa", Backend::OSMesa}, {"egl", Backend::Egl}, {"glfw", Backend::Glfw}};
        return names.at(backend);
    }
};

int capture(const SceneOptions& scene, const CaptureOptions& opts) {
    CaptureJob job;
    if (!scene.load(job.settings) || !opts.apply(job.settings.capture) || !opts.selection(job.selection)) return 2;
    job.stats_file = opts.stats;
    job.dot_file = opts.dot;
    job.backend = opts.backendValue();
    job.force = opts.force;
    job.resume = opts.resume;
    job.inputs = scene.files();
    CaptureResult r = runCapture(job);
    if (r.exit_code == 0) {
        std::printf("vista: wrote %zu image(s) to %s/ (%d kept from an earlier run, %d settle frames)\n", r.images.size(),
                    job.settings.capture.out.c_str(), r.kept, r.settle_frames);
        if (!r.manifest.empty()) std::printf("vista: wrote the manifest %s\n", r.manifest.c_str());
        if (!r.video.empty()) std::printf("vista: wrote the video %s\n", r.video.c_str());
        if (!job.stats_file.empty()) std::printf("vista: wrote stats to %s\n", job.stats_file.c_str());
    }
    return r.exit_code;
}

struct QualityCliOptions {
    std::string path, size, out, knobs, backend = "osmesa";
    int frames = 2, warmup = -1;  // warm-up -1: [capture] settle_frames
    double fps = 0.0;
    TemporalQualityOptions temporal;
    bool bench = false;  // `vista bench temporal`: the reference and the scene as given
    std::string reference_preset = "reference";

    void add(CLI::App* cmd, SceneOptions& scene, bool bench_temporal = false) {
        bench = bench_temporal;
        cmd->add_option("-c,--config", scene.configs, "scene file (default: config/default.ini); may repeat")
            ->allow_extra_args(false)
            ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
        cmd->add_option("--set", scene.overrides, "override a scene key: --set section.key=value (repeatable)");
        cmd->add_option("--path", path, "camera path file (default: [capture] path)");
        cmd->add_option("--frames", frames, "measured frames per run (default 2)")->check(kDecimal)->check(CLI::Range(1, 10000));
        cmd->add_option("--warmup", warmup, "settle frames rendered before measuring each run (default: [capture] settle_frames)")
            ->check(kDecimal)->check(CLI::Range(0, 1000));
        cmd->add_option("--fps", fps, "frames per second of path time (default 24: consecutive frames of a slow camera)")->check(kFinite)->check(CLI::Range(0.01, 1000.0));
        cmd->add_option("--size", size, "image size WxH (default: [capture] width x height)");
        cmd->add_option("--out", out, std::string("output directory (default: [capture] out/") +
                                          (bench ? "bench_temporal" : "quality") + "; the report files are replaced)");
        cmd->add_option("--backend", backend, "GL context: osmesa (default) or egl")->check(CLI::IsMember({"osmesa", "egl"}));
        if (bench)
            cmd->add_option("--reference-preset", reference_preset,
                            "the preset whose frames are the reference (default reference; a cheaper one for quick checks)")
                ->check(CLI::IsMember({"low", "medium", "high", "ultra", "reference"}));
        else
            cmd->add_option("--knobs", knobs, "comma-separated knobs to sweep, or none for the presets alone (default: all)");
        cmd->add_option("--converge-frames", temporal.converge_frames,
                        "history-free frames averaged into the converged reference (default 16; 0: no 1-frame and ghost figures)")
            ->check(kDecimal)->check(CLI::Range(0, 4096));
        cmd->add_option("--supersample", temporal.supersample, "the converged reference's size factor (default 2)")
            ->check(kDecimal)->check(CLI::Range(1, 8));
        cmd->add_option("--cut-frames", temporal.cut_frames, "frames rendered after the camera cut (default 16; 0: no ghost figure)")
            ->check(kDecimal)->check(CLI::Range(0, 1000));
    }
};

int quality(const SceneOptions& scene, const QualityCliOptions& q) {
    QualityOptions o;
    if (!scene.load(o.scene)) return 2;
    CaptureSettings& c = o.scene.capture;
    if (!q.path.empty()) c.path = q.path;
    // Consecutive frames of a real frame rate by default: flicker and TAA need a slow camera
    // (the default scene's capture rate, 0.2 fps, makes every frame a camera cut).
    c.fps = q.fps > 0.0 ? float(q.fps) : 24.0f;
    if (!q.size.empty() && !parseSize(q.size, c.width, c.height)) return 2;
    o.scene_name = scene.configs.empty() ? "config/default.ini" : scene.configs.back();
    o.frames = q.frames;
    o.warmup = q.warmup >= 0 ? q.warmup : c.settle_frames;
    o.temporal = q.temporal;
    o.temporal.settle_frames = o.warmup;
    o.bench = q.bench;
    o.reference_preset = *qualityPresetFromName(q.reference_preset);
    o.pinned = scene.overrides;
    o.out = q.out.empty() ? std::filesystem::path(c.out) / (q.bench ? "bench_temporal" : "quality") : std::filesystem::path(q.out);
    o.backend = q.backend == "egl" ? Backend::Egl : Backend::OSMesa;
    if (!q.knobs.empty()) {
        o.all_knobs = false;
        std::stringstream list(q.knobs);
        for (std::string name; std::getline(list, name, ',');)
            if (!name.empty() && name != "none") o.knobs.push_back(name);
    }
    return runQuality(o);
}

int check(const SceneOptions& scene) {
    Settings s;
    const std::filesystem::path file = scene.file();
    InputErrors errors = loadScene(scene.files(), scene.overrides, s);
    // Everything a capture validates before rendering, without a GL context.
    InputErrors warnings;
    if (errors.empty()) {
        CheckedTerrain checked;
        InputErrors more = validateSceneInputs(s, &checked);
        errors.insert(errors.end(), more.begin(), more.end());
        warnings = checkLightPlacement(s, checked.ground, scene.files(), scene.overrides);
    }
    for (const InputError& w : warnings) std::fprintf(stderr, "vista: warning: %s\n", w.str().c_str());
    CameraPath::load(resolveInput(s.capture.path), errors, s.camera.fov_deg);
    printErrors(errors);
    if (!errors.empty()) {
        std::fprintf(stderr, "vista: %zu problem(s) in %s\n", errors.size(), file.c_str());
        return 2;
    }
    std::printf("vista: %s is valid\n", file.c_str());
    return 0;
}

int benchFrame(const SceneOptions& scene, const CaptureOptions& opts, const std::string& json, int warmup, bool force) {
    CaptureJob job;
    if (!scene.load(job.settings) || !opts.apply(job.settings.capture)) return 2;
    if (opts.frames == 0) job.settings.capture.frames = 16;
    if (!json.empty())
        if (std::string problem = checkOutputFile(json, force, "--json"); !problem.empty()) return fail(2, problem);
    job.backend = opts.backendValue();
    job.write_images = false;
    job.warmup_frames = warmup;
    // What bench frame measures is the scene as given: it states the scene instead of isolating.
    BenchScene stated{"frame", enabledSections(job.settings), {}, {}, scene.overrides, job.settings};
    std::printf("bench frame: scene %s, as given: features on [", scene.configs.empty() ? "config/default.ini" : scene.configs.back().c_str());
    for (std::size_t i = 0; i < stated.kept.size(); ++i) std::printf("%s%s", i ? ", " : "", stated.kept[i].c_str());
    std::printf("]; --set [");
    for (std::size_t i = 0; i < stated.user.size(); ++i) std::printf("%s%s", i ? ", " : "", stated.user[i].c_str());
    std::printf("]\n");
    CaptureResult r = runCapture(job);
    if (r.exit_code != 0) return r.exit_code;
    const RunStats& st = r.stats;
    std::printf("%s", st.table().c_str());
    std::printf("frame total (median of %zu frames): %.3f ms GPU = %.1f copies, %.3f ms CPU\n", st.frames().size(),
                st.gpuMedian(), st.reference_copy_ms > 0.0 ? st.gpuMedian() / st.reference_copy_ms : 0.0, st.cpuMedian());
    if (!json.empty()) {
        nlohmann::json doc = nlohmann::json::parse(st.json());
        doc["scene"] = stated.json();
        doc["scene"]["file"] = scene.configs.empty() ? "config/default.ini" : scene.configs.back();
        std::string problem = writeFileAtomic(json, doc.dump(2) + "\n", force);
        if (!problem.empty()) {
            std::fprintf(stderr, "vista: %s\n", problem.c_str());
            return 1;
        }
    }
    return 0;
}

// A bench's --json checked before it runs (minutes may be at stake): 0 or 2 after saying why.
int checkBenchJson(const std::filesystem::path& json, bool force) {
    if (json.empty()) return 0;
    std::string problem = checkOutputFile(json, force, "--json");
    return problem.empty() ? 0 : fail(2, problem);
}

}  // namespace

// Parses and runs one command; runCli wraps it.
int runCommand(int argc, char** argv) {
    CLI::App app{"vista: outdoor terrain renderer (OpenGL 4.5)"};
    app.require_subcommand(0, 1);

    SceneOptions run_scene, capture_scene, check_scene, bench_scene;
    CaptureOptions capture_opts, bench_opts;
    std::string bench_json;
    int bench_warmup = 2;
    bool bench_force = false;

    CLI::App* run_cmd = app.add_subcommand("run", "open a window on the scene (the default)");
    run_scene.add(run_cmd);
    CLI::App* capture_cmd = app.add_subcommand("capture", "render a camera path headless to images");
    capture_scene.add(capture_cmd);
    capture_opts.add(capture_cmd, true);
    CLI::App* check_cmd = app.add_subcommand("check", "validate a scene file and its camera path; list every problem");
    check_scene.add(check_cmd);
    bool check_reference = false;
    check_cmd->add_flag("--reference", check_reference,
                        "print the scene-file reference (Markdown, from the settings' descriptions; docs/scene-file.md)");
    CLI::App* bench_cmd = app.add_subcommand("bench", "measure per-pass GPU/CPU times");
    bench_cmd->require_subcommand(1);
    CLI::App* bench_frame = bench_cmd->add_subcommand("frame", "whole frames along the capture path");
    bench_scene.add(bench_frame);
    bench_opts.add(bench_frame, false);
    bench_frame->add_option("--json", bench_json, "also write the stats JSON to this file");
    bench_frame->add_flag("--force", bench_force, "replace an existing --json file");
    bench_frame->add_option("--warmup", bench_warmup, "frames rendered before measuring")->check(kDecimal)->check(CLI::Range(0, 1000));

    SceneOptions terrain_scene;
    BenchTerrainOptions terrain_opts;
    std::string terrain_backend = "osmesa", terrain_heightmap, terrain_json;
    CLI::App* bench_terrain = bench_cmd->add_subcommand("terrain", "CDLOD selection, triangles, error and GPU cost over random poses");
    terrain_scene.add(bench_terrain);
    bench_terrain->add_option("--heightmap", terrain_heightmap, "heightmap file (default: generate an island of --size)");
    bench_terrain->add_option("--size", terrain_opts.size, "samples per side of the generated island, 2..16385")
        ->check(kDecimal)->check(CLI::Range(2, 16385));
    bench_terrain->add_option("--poses", terrain_opts.poses, "random camera poses")->check(kDecimal)->check(CLI::Range(1, 100000));
    bench_terrain->add_option("--seed", terrain_opts.seed, "island and pose seed")->check(kDecimal);
    bench_terrain->add_option("--backend", terrain_backend, "osmesa (default) or egl")->check(CLI::IsMember({"osmesa", "egl"}));
    bench_terrain->add_option("--json", terrain_json, "also write the results as JSON");
    std::string terrain_frame_size;
    bench_terrain->add_option("--frame-size", terrain_frame_size, "frame size WxH of the poses (default 640x360)");
    bench_terrain->add_flag("--force", terrain_opts.force, "replace an existing --json file");

    SceneOptions lights_scene;
    BenchLightsOptions lights_opts;
    std::string lights_backend = "osmesa", lights_size, lights_json, lights_methods;
    std::vector<int> lights_counts;
    CLI::App* bench_lights = bench_cmd->add_subcommand("lights", "light culling methods: GPU cost, evaluations against exact pairs, memory");
    lights_scene.add(bench_lights);
    bench_lights->add_option("--lights", lights_counts, "light counts, e.g. 0,64,256,1024,4096,16384 (the default)")
        ->delimiter(',')->check(kDecimal)->check(CLI::Range(0, 1000000));
    bench_lights->add_option("--methods", lights_methods, "comma-separated: naive,tiled,clustered,hashed (default: all)");
    bench_lights->add_option("--size", lights_size, "frame size WxH (default 320x180)");
    bench_lights->add_option("--frames", lights_opts.frames, "timed frames per row, after three warm-up frames")->check(kDecimal)->check(CLI::Range(1, 1000));
    bench_lights->add_option("--radius", lights_opts.radius_m, "radius of every light (m)")->check(kFinite)->check(CLI::Range(0.0f, 1.0e4f));
    bench_lights->add_option("--backend", lights_backend, "osmesa (default) or egl")->check(CLI::IsMember({"osmesa", "egl"}));
    bench_lights->add_option("--json", lights_json, "also write the results as JSON");
    std::string lights_sweeps, lights_resolutions;
    bench_lights->add_option("--sweep", lights_sweeps,
                             "comma-separated sweeps: counts (default), resolution, tiles, nodes, forward, path, classes, or all");
    bench_lights->add_option("--resolutions", lights_resolutions, "frame sizes of the resolution sweep, e.g. 320x180,640x360 (the default)");
    bench_lights->add_option("--sweep-lights", lights_opts.sweep_lights, "light count of every sweep but counts (default 1024)")
        ->check(CLI::Range(1, 1000000));
    bench_lights->add_option("--path-frames", lights_opts.path_frames, "frames of the path sweep (default 16)")->check(CLI::Range(1, 10000));
    std::string lights_charts;
    bench_lights->add_option("--charts", lights_charts, "directory for the PNG charts (default: beside --json)");
    bench_lights->add_flag("--force", lights_opts.force, "replace an existing --json file");

    SceneOptions sky_scene;
    BenchSkyOptions sky_opts;
    std::string sky_backend = "osmesa", sky_size, sky_json;
    CLI::App* bench_sky = bench_cmd->add_subcommand("sky", "atmosphere LUT sizes: PSNR against the CPU reference, build and frame cost");
    sky_scene.add(bench_sky);
    bench_sky->add_option("--size", sky_size, "frame size for the timings, WxH (default 320x180)");
    bench_sky->add_option("--backend", sky_backend, "osmesa (default) or egl")->check(CLI::IsMember({"osmesa", "egl"}));
    bench_sky->add_option("--json", sky_json, "also write the results as JSON");
    bench_sky->add_option("--presets", sky_opts.presets, "LUT presets to measure: low,medium,default,high (default: all)")
        ->delimiter(',')->check(CLI::IsMember(benchSkyPresetNames()));
    bool sky_no_clouds = false;
    std::string sky_psnr_size;
    bench_sky->add_option("--psnr-size", sky_psnr_size, "size of the views compared with the CPU reference, WxH (default 128x72)");
    bench_sky->add_flag("--no-clouds", sky_no_clouds, "skip the cloud octave/step sweep");
    bench_sky->add_flag("--force", sky_opts.force, "replace an existing --json file");

    SceneOptions shadows_scene;
    BenchShadowsOptions shadows_opts;
    std::string shadows_backend = "osmesa", shadows_size, shadows_json;
    bool shadows_no_reference = false;
    CLI::App* bench_shadows = bench_cmd->add_subcommand("shadows", "sun shadows: shimmer, acne, error against an 8192-texel reference, cost");
    shadows_scene.add(bench_shadows);
    bench_shadows->add_option("--size", shadows_size, "frame size WxH (default 320x180)");
    bench_shadows->add_option("--backend", shadows_backend, "osmesa (default) or egl")->check(CLI::IsMember({"osmesa", "egl"}));
    bench_shadows->add_flag("--no-reference", shadows_no_reference, "skip the 8192-texel reference (error_vs_reference)");
    bench_shadows->add_option("--json", shadows_json, "also write the results as JSON");
    bench_shadows->add_flag("--force", shadows_opts.force, "replace an existing --json file");
    SceneOptions objects_scene;
    BenchObjectsOptions objects_opts;
    std::string objects_backend = "osmesa", objects_size, objects_json;
    std::vector<int> objects_trees;
    CLI::App* bench_objects = bench_cmd->add_subcommand("objects", "objects: a forest of N trees, instances and triangles drawn, GPU cost");
    objects_scene.add(bench_objects);
    bench_objects->add_option("--trees", objects_trees, "tree counts, e.g. 1000,10000,100000 (the default)")
        ->delimiter(',')->check(CLI::Range(1, 10000000));
    bench_objects->add_option("--size", objects_size, "frame size WxH (default 640x360)");
    bench_objects->add_option("--frames", objects_opts.frames, "timed frames per count, after two warm-up frames")->check(kDecimal)->check(CLI::Range(1, 1000));
    bench_objects->add_option("--backend", objects_backend, "osmesa (default) or egl")->check(CLI::IsMember({"osmesa", "egl"}));
    bench_objects->add_option("--json", objects_json, "also write the results as JSON");
    bench_objects->add_flag("--force", objects_opts.force, "replace an existing --json file");
    SceneOptions grass_scene;
    BenchGrassOptions grass_opts;
    std::string grass_backend = "osmesa", grass_size, grass_json;
    std::vector<float> grass_densities;
    CLI::App* bench_grass = bench_cmd->add_subcommand("grass", "grass passes: blades drawn and GPU cost at a few densities");
    grass_scene.add(bench_grass);
    bench_grass->add_option("--densities", grass_densities, "blades per m^2, e.g. 4,8,16,24,48 (the default)")
        ->delimiter(',')->check(kFinite)->check(CLI::Range(0.25f, 400.0f));
    bench_grass->add_option("--size", grass_size, "frame size WxH (default 640x360)");
    bench_grass->add_option("--frames", grass_opts.frames, "timed frames per density, after two warm-up frames")->check(kDecimal)->check(CLI::Range(1, 1000));
    bench_grass->add_option("--backend", grass_backend, "osmesa (default) or egl")->check(CLI::IsMember({"osmesa", "egl"}));
    bench_grass->add_option("--json", grass_json, "also write the results as JSON");
    bench_grass->add_flag("--force", grass_opts.force, "replace an existing --json file");

    SceneOptions sky_cmd_scene;
    SkyCliArgs sky_args;
    CLI::App* sky_cmd = app.add_subcommand("sky", "sky radiance (linear sRGB and luminance, cd/m^2) for given geometries");
    sky_cmd_scene.add(sky_cmd);
    sky_cmd->add_option("--altitude-m", sky_args.altitude_m, "camera altitude above the ground (m)");
    sky_cmd->add_option("--sun-zenith-deg", sky_args.sun_zenith_deg, "sun zenith angle, 0..180 deg");
    sky_cmd->add_option("--view-zenith-deg", sky_args.view_zenith_deg, "view zenith angle, 0..180 deg");
    sky_cmd->add_option("--view-azimuth-deg", sky_args.view_azimuth_deg, "view azimuth from the sun's, -360..360 deg");
    sky_cmd->add_option("--in", sky_args.in, "CSV of geometries (header altitude_m,sun_zenith_deg,view_zenith_deg,view_azimuth_deg)");
    sky_cmd->add_option("--out", sky_args.out, "write the CSV here (default: stdout)");
    sky_cmd->add_flag("--reference", sky_args.reference, "the spectral CPU reference instead of the GPU");
    sky_cmd->add_flag("--ground", sky_args.ground, "add the sunlit ground where a ray meets the planet");
    sky_cmd->add_flag("--force", sky_args.force, "replace an existing --out file");
    sky_cmd->add_option("--backend", sky_args.backend, "osmesa (default) or egl")->check(CLI::IsMember({"osmesa", "egl"}));

    SceneOptions quality_scene;
    QualityCliOptions quality_opts;
    CLI::App* quality_cmd = app.add_subcommand(
        "quality", "image error against the reference beside GPU time for every preset and quality knob");
    quality_opts.add(quality_cmd, quality_scene);
    SceneOptions temporal_scene;
    QualityCliOptions temporal_opts;
    CLI::App* bench_temporal = bench_cmd->add_subcommand(
        "temporal", "temporal error of the scene as given: 1-frame PSNR against a converged reference, flicker, frames after a cut");
    temporal_opts.add(bench_temporal, temporal_scene, /*bench_temporal=*/true);

    // Farm: video from finished frames, merging shards, Slurm job arrays (app/farm.h).
    EncodeOptions encode_opts;
    CLI::App* encode_cmd = app.add_subcommand("encode", "encode a directory's frame_NNNN.png sequence into an H.264 video");
    encode_cmd->add_option("dir", encode_opts.dir, "directory of frame_NNNN.png files")->required();
    encode_cmd->add_option("--out", encode_opts.out, "video file (default DIR/capture.mp4)");
    encode_cmd->add_option("--fps", encode_opts.fps, "frames per second (default: the manifest's, else 24)")->check(CLI::Range(0.01, 1000.0));
    encode_cmd->add_option("--crf", encode_opts.crf, "H.264 quality: 0 lossless, 18 (default) visually lossless, 51 worst")->check(CLI::Range(0, 51));
    encode_cmd->add_flag("--force", encode_opts.force, "replace an existing video");
    CLI::App* farm_cmd = app.add_subcommand("farm", "render farms: merge shards, submit Slurm job arrays");
    farm_cmd->require_subcommand(1);
    MergeOptions merge_opts;
    CLI::App* merge_cmd = farm_cmd->add_subcommand("merge", "check the shards' manifests fit together, then encode the video");
    merge_cmd->add_option("dirs", merge_opts.dirs, "directories the shards wrote (manifest*.json and frames)")->required();
    merge_cmd->add_option("--out", merge_opts.out, "video file (default FIRST_DIR/capture.mp4)");
    merge_cmd->add_option("--crf", merge_opts.crf, "H.264 quality: 0 lossless, 18 (default), 51 worst")->check(CLI::Range(0, 51));
    merge_cmd->add_flag("--force", merge_opts.force, "replace an existing video");
    merge_cmd->add_flag("--check", merge_opts.check_only, "only check the shards; encode nothing");
    SlurmOptions slurm_opts;
    CLI::App* slurm_cmd = farm_cmd->add_subcommand("slurm", "print (or --submit) the sbatch commands of a sharded capture and its merge");
    slurm_cmd->add_option("--tasks", slurm_opts.tasks, "array tasks (shards)")->check(CLI::Range(1, 100000))->required();
    slurm_cmd->add_option("--out", slurm_opts.out, "the shards' common output directory (shared file system)")->required();
    slurm_cmd->add_option("--backend", slurm_opts.backend, "egl (GPU nodes, the default) or osmesa (CPU nodes)")
        ->check(CLI::IsMember({"egl", "osmesa"}));
    slurm_cmd->add_option("--vista", slurm_opts.vista, "the vista executable on the nodes (default: this one)");
    slurm_cmd->add_option("--partition", slurm_opts.partition, "sbatch --partition");
    slurm_cmd->add_option("--time", slurm_opts.time_limit, "sbatch --time of each task");
    slurm_cmd->add_option("--gres", slurm_opts.gres, "sbatch --gres of each task, e.g. gpu:1");
    slurm_cmd->add_option("--crf", slurm_opts.crf, "H.264 quality of the merged video")->check(CLI::Range(0, 51));
    slurm_cmd->add_flag("--submit", slurm_opts.submit, "run sbatch now instead of printing the commands");
    slurm_cmd->add_option("capture_args", slurm_opts.capture_args, "after --: options for every vista capture (--path, --size, -c, --set ...)");

    int gen_size = 1025;
    std::uint32_t gen_seed = 1;
    std::string gen_out;
    CLI::App* gen_cmd = app.add_subcommand("gen-heightmap", "generate a deterministic island heightmap (16-bit PNG, float EXR, or float TIFF written row by row)");
    bool gen_force = false;
    gen_cmd->add_option("--size", gen_size, "samples per side, 2..65537 (.tif; .png and .exr up to 16385; 2^n + 1 suits the quadtree)")->check(kDecimal);
    gen_cmd->add_option("--seed", gen_seed, "random seed; the same seed gives the same file everywhere")->check(kDecimal);
    gen_cmd->add_option("--out", gen_out, "output file (.png, .exr, or .tif for maps larger than memory)")->required();
    gen_cmd->add_flag("--force", gen_force, "replace an existing --out file");
    std::string props_out = "data/props";
    std::uint32_t props_seed = 1;
    bool props_force = false;
    CLI::App* props_cmd = app.add_subcommand("gen-props", "write the procedural props (tree.glb, rock.glb, house.glb) into a folder");
    props_cmd->add_option("--out", props_out, "folder to write into (default data/props, relative to the working directory)");
    props_cmd->add_option("--seed", props_seed, "random seed of the tree and the rock")->check(kDecimal);
    props_cmd->add_flag("--force", props_force, "replace existing files");

    TerrainCacheOptions cache_opts;
    CLI::App* cache_cmd = app.add_subcommand("terrain-cache", "build the tile cache (LOD pyramid on disk) of a DEM or heightmap once (docs/dem.md)");
    cache_cmd->add_option("file", cache_opts.input, "DEM (GDAL) or heightmap image")->required();
    cache_cmd->add_option("--out", cache_opts.out, "cache file (default: FILE.vtc)");
    cache_cmd->add_option("--tile", cache_opts.tile, "samples between tile origins, 2..4096")->check(kDecimal);
    cache_cmd->add_option("--size-m", cache_opts.size_m, "a heightmap image's extent in m ([terrain] size_m)");
    cache_cmd->add_option("--height-scale-m", cache_opts.height_scale_m, "a heightmap image's height of value 1 in m");
    cache_cmd->add_option("--height-offset-m", cache_opts.height_offset_m, "a heightmap image's height of value 0 in m");
    cache_cmd->add_option("--raw-width", cache_opts.raw_width, "a raw .r16's width in samples ([terrain] raw_width)")->check(kDecimal);
    cache_cmd->add_option("--raw-height", cache_opts.raw_height, "a raw .r16's height in samples ([terrain] raw_height)")->check(kDecimal);
    cache_cmd->add_flag("--force", cache_opts.force, "rebuild even when the cache is up to date");

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::fprintf(stderr, "vista: %s\nRun 'vista --help' for usage.\n", e.what());
        return 2;
    }

    if (*capture_cmd) return capture(capture_scene, capture_opts);
    if (*encode_cmd) return runEncode(encode_opts);
    if (*merge_cmd) return runFarmMerge(merge_opts);
    if (*slurm_cmd) return runFarmSlurm(slurm_opts);
    if (*check_cmd && check_reference) {
        std::fputs(sceneFileReference().c_str(), stdout);
        return std::fflush(stdout) == 0 && !std::ferror(stdout) ? 0 : fail(1, "cannot write the reference to stdout");
    }
    if (*check_cmd) return check(check_scene);
    if (*quality_cmd) return quality(quality_scene, quality_opts);
    if (*bench_temporal) return quality(temporal_scene, temporal_opts);
    if (*gen_cmd) return runGenHeightmap(gen_size, gen_seed, gen_out, gen_force);
    if (*cache_cmd) return runTerrainCache(cache_opts);
    if (*props_cmd) return runGenProps(props_out, props_seed, props_force);
    if (*bench_frame) return benchFrame(bench_scene, bench_opts, bench_json, bench_warmup, bench_force);
    if (*bench_terrain) {
        Settings s;
        if (!terrain_scene.load(s)) return 2;
        terrain_opts.heightmap = terrain_heightmap;
        terrain_opts.json = terrain_json;
        if (!terrain_frame_size.empty() && !parseSize(terrain_frame_size, terrain_opts.width, terrain_opts.height)) return 2;
        if (int code = checkBenchJson(terrain_opts.json, terrain_opts.force)) return code;
        terrain_opts.backend = terrain_backend == "egl" ? Backend::Egl : Backend::OSMesa;
        return runBenchTerrain(isolateBenchScene("terrain", s, benchKeptSections("terrain"), benchFixedKeys("terrain"), terrain_scene.overrides),
                              terrain_opts);
    }
    if (*bench_lights) {
        Settings s;
        if (!lights_scene.load(s)) return 2;
        if (!lights_size.empty() && !parseSize(lights_size, lights_opts.width, lights_opts.height)) return 2;
        if (!lights_counts.empty()) lights_opts.lights = lights_counts;
        if (!lights_methods.empty()) {
            lights_opts.methods.clear();
            std::stringstream list(lights_methods);
            for (std::string name; std::getline(list, name, ',');) {
                const std::map<std::string, LightCulling> names = {{"naive", LightCulling::Naive}, {"tiled", LightCulling::Tiled},
                                                                   {"clustered", LightCulling::Clustered}, {"hashed", LightCulling::Hashed}};
                auto it = names.find(name);
                if (it == names.end()) {
                    std::fprintf(stderr, "vista: --methods: '%s' is not a method; accepted naive, tiled, clustered, hashed\n",
                                 name.c_str());
                    return 2;
                }
                lights_opts.methods.push_back(it->second);
            }
        }
        lights_opts.json = lights_json;
        lights_opts.charts = lights_charts;
        lights_opts.methods_given = !lights_methods.empty();
        if (!lights_sweeps.empty()) {
            lights_opts.sweeps.clear();
            const std::vector<std::string> known = benchLightsSweeps();
            std::stringstream list(lights_sweeps);
            for (std::string name; std::getline(list, name, ',');) {
                if (name != "all" && std::find(known.begin(), known.end(), name) == known.end()) {
                    std::fprintf(stderr, "vista: --sweep: '%s' is not a sweep; accepted counts, resolution, tiles, nodes, "
                                         "forward, path, classes, all\n", name.c_str());
                    return 2;
                }
                lights_opts.sweeps.push_back(name);
            }
        }
        if (!lights_resolutions.empty()) {
            lights_opts.resolutions.clear();
            std::stringstream list(lights_resolutions);
            for (std::string size; std::getline(list, size, ',');) {
                int w = 0, h = 0;
                if (!parseSize(size, w, h)) return 2;
                lights_opts.resolutions.push_back({w, h});
            }
        }
        if (int code = checkBenchJson(lights_opts.json, lights_opts.force)) return code;
        lights_opts.backend = lights_backend == "egl" ? Backend::Egl : Backend::OSMesa;
        return runBenchLights(isolateBenchScene("lights", s, benchKeptSections("lights"), benchFixedKeys("lights"), lights_scene.overrides),
                              lights_opts);
    }
    if (*bench_shadows) {
        Settings s;
        if (!shadows_scene.load(s)) return 2;
        if (!shadows_size.empty() && !parseSize(shadows_size, shadows_opts.width, shadows_opts.height)) return 2;
        shadows_opts.json = shadows_json;
        if (int code = checkBenchJson(shadows_opts.json, shadows_opts.force)) return code;
        shadows_opts.reference = !shadows_no_reference;
        shadows_opts.backend = shadows_backend == "egl" ? Backend::Egl : Backend::OSMesa;
        return runBenchShadows(isolateBenchScene("shadows", s, benchKeptSections("shadows"), benchFixedKeys("shadows"), shadows_scene.overrides),
                              shadows_opts);
    }
    if (*bench_objects) {
        Settings s;
        if (!objects_scene.load(s)) return 2;
        if (!objects_size.empty() && !parseSize(objects_size, objects_opts.width, objects_opts.height)) return 2;
        if (!objects_trees.empty()) objects_opts.trees = objects_trees;
        objects_opts.json = objects_json;
        if (int code = checkBenchJson(objects_opts.json, objects_opts.force)) return code;
        objects_opts.backend = objects_backend == "egl" ? Backend::Egl : Backend::OSMesa;
        return runBenchObjects(isolateBenchScene("objects", s, benchKeptSections("objects"), benchFixedKeys("objects"),
                                                 objects_scene.overrides),
                               objects_opts);
    }
    if (*bench_grass) {
        Settings s;
        if (!grass_scene.load(s)) return 2;
        if (!grass_size.empty() && !parseSize(grass_size, grass_opts.width, grass_opts.height)) return 2;
        if (!grass_densities.empty()) grass_opts.densities = grass_densities;
        grass_opts.json = grass_json;
        if (int code = checkBenchJson(grass_opts.json, grass_opts.force)) return code;
        grass_opts.backend = grass_backend == "egl" ? Backend::Egl : Backend::OSMesa;
        return runBenchGrass(isolateBenchScene("grass", s, benchKeptSections("grass"), benchFixedKeys("grass"), grass_scene.overrides),
                              grass_opts);
    }
    if (*sky_cmd) {
        Settings s;
        if (!sky_cmd_scene.load(s)) return 2;
        return runSkyCli(s, sky_args);
    }
    if (*bench_sky) {
        Settings s;
        if (!sky_scene.load(s)) return 2;
        if (!sky_size.empty() && !parseSize(sky_size, sky_opts.width, sky_opts.height)) return 2;
        sky_opts.json = sky_json;
        sky_opts.clouds = !sky_no_clouds;
        if (!sky_psnr_size.empty() && !parseSize(sky_psnr_size, sky_opts.psnr_width, sky_opts.psnr_height)) return 2;
        if (int code = checkBenchJson(sky_opts.json, sky_opts.force)) return code;
        sky_opts.backend = sky_backend == "egl" ? Backend::Egl : Backend::OSMesa;
        return runBenchSky(isolateBenchScene("sky", s, benchKeptSections("sky"), benchFixedKeys("sky"), sky_scene.overrides),
                              sky_opts);
    }

    const SceneOptions& scene = *run_cmd ? run_scene : SceneOptions{};
    if (!displayAvailable()) {
        std::fprintf(stderr, "vista: no display found (DISPLAY and WAYLAND_DISPLAY are unset); capturing the "
                             "default camera path headless instead\n");
        CaptureOptions fallback;
        Settings s;
        if (!scene.load(s)) return 2;
        // Never overwrite an earlier capture: use the next free out/run-NNN when out/ is taken.
        std::filesystem::path out = s.capture.out;
        // A regular file named like a run folder is skipped too, not retried forever.
        for (int n = 2; std::filesystem::exists(captureFileName(out, 0, s.capture.format)) ||
                        (std::filesystem::exists(out) && !std::filesystem::is_directory(out));
             ++n) {
            char name[16];
            std::snprintf(name, sizeof name, "run-%03d", n);
            out = std::filesystem::path(s.capture.out) / name;
        }
        fallback.out = out.string();
        return capture(scene, fallback);
    }
    Settings s;
    if (!scene.load(s)) return 2;
    return runWindow(s, scene.file());
}

int runCli(int argc, char** argv) {
    installTemporaryCleanup();
    // A GL allocation failure (incomplete framebuffer) or std::bad_alloc under a memory limit
    // is a runtime failure with a message (exit 1), never an abort (exit 134).
    try {
        return runCommand(argc, argv);
    } catch (const std::bad_alloc&) {
        std::fprintf(stderr, "vista: out of memory (std::bad_alloc); try a smaller --size or fewer/smaller resources\n");
    } catch (const std::exception& e) {
        std::fprintf(stderr, "vista: runtime failure: %s\n", e.what());
    }
    return 1;
}

}  // namespace vista
