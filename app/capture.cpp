// Capture: validate everything first (path, frame selection, output directory, existing files,
// a manifest to resume), then render the selected frames at a fixed time step, each run of
// consecutive frames after its settle frames, keeping the manifest current after every frame.
#include "app/capture.h"

#include "app/camera_path.h"
#include "app/frame.h"
#include "app/image_writer.h"
#include "app/memory_budget.h"
#include "app/progress.h"
#include "app/scene.h"
#include "app/video.h"
#include "renderer/temporal.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <optional>
#include <unistd.h>

namespace vista {

std::filesystem::path captureFileName(const std::filesystem::path& out, int frame, ImageFormat format) {
    char name[64];
    std::snprintf(name, sizeof name, "frame_%04d.%s", frame, format == ImageFormat::Exr ? "exr" : "png");
    return out / name;
}

std::string checkWritableDir(const std::filesystem::path& dir) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) return dir.string() + ": cannot create output directory (" + ec.message() + ")";
    // access(), not a probe file: a fixed probe name would race with a second capture.
    if (!std::filesystem::is_directory(dir, ec)) return dir.string() + ": is not a directory";
    if (::access(dir.c_str(), W_OK | X_OK) != 0) return dir.string() + ": output directory is not writable";
    return {};
}

std::string checkCaptureOutputs(const CaptureJob& job) {
    const CaptureSettings& c = job.settings.capture;
    std::vector<std::filesystem::path> inputs = job.inputs;
    inputs.push_back(resolveInput(c.path));
    inputs.push_back(resolveInput(job.settings.terrain.heightmap));
    if (!job.settings.terrain.dem.empty()) inputs.push_back(resolveInput(job.settings.terrain.dem));
    if (!job.settings.grade.lut.empty()) inputs.push_back(resolveInput(job.settings.grade.lut));
    const std::pair<const char*, const std::filesystem::path*> outputs[] = {{"--stats", &job.stats_file},
                                                                            {"--dot", &job.dot_file}};
    for (const auto& [option, file] : outputs) {
        if (file->empty()) continue;
        std::string problem = checkOutputFile(*file, job.force, option);
        if (!problem.empty()) return problem;
        for (const auto& input : inputs)
            if (samePath(*file, input))
                return std::string(option) + " " + file->string() + ": is an input of this capture; choose another name";
        std::filesystem::path dir = file->parent_path().empty() ? std::filesystem::path(".") : file->parent_path();
        const std::string frame_ext = c.format == ImageFormat::Exr ? ".exr" : ".png";
        if (job.write_images && samePath(dir, c.out) && file->filename().string().rfind("frame_", 0) == 0 &&
            file->extension() == frame_ext)
            return std::string(option) + " " + file->string() + ": would replace a captured frame; choose another name";
    }
    if (samePath(job.stats_file, job.dot_file) || (!job.stats_file.empty() && job.stats_file == job.dot_file))
        return "--stats and --dot both name " + job.stats_file.string() + "; choose two names";
    return {};
}

double captureFrameTime(double start_s, int frame, double fps) {
    return start_s + std::max(frame, 0) / fps;
}

namespace {

// Why an existing manifest cannot be resumed by this run ("" when it can).
std::string resumeMismatch(const Manifest& old, const Manifest& now) {
    auto field = [](const std::string& what, const std::string& was, const std::string& is) {
        return what + " " + was + " (this run: " + is + ")";
    };
    if (old.version != now.version) return field("vista version", old.version, now.version);
    if (old.scene_hash != now.scene_hash) return field("scene hash", old.scene_hash, now.scene_hash);
    if (old.path_hash != now.path_hash) return field("camera path hash", old.path_hash, now.path_hash);
    if (old.total_frames != now.total_frames)
        return field("frame count", std::to_string(old.total_frames), std::to_string(now.total_frames));
    if (old.fps != now.fps) return field("fps", std::to_string(old.fps), std::to_string(now.fps));
    if (old.width != now.width || old.height != now.height)
        return field("size", std::to_string(old.width) + "x" + std::to_string(old.height),
                     std::to_string(now.width) + "x" + std::to_string(now.height));
    if (old.format != now.format) return field("format", old.format, now.format);
    return {};
}

}  // namespace

CaptureResult runCapture(const CaptureJob& job) {
    const auto run_start = std::chrono::steady_clock::now();
    CaptureResult result;
    // Says why (stderr) and returns what was done so far with the exit code.
    auto stop = [&](int code, const std::string& message) {
        result.exit_code = fail(code, message);
        return std::move(result);
    };
    const Settings& s = job.settings;
    const CaptureSettings& c = s.capture;

    InputErrors errors;
    const std::filesystem::path path_file = resolveInput(c.path);
    CameraPath path = CameraPath::load(path_file, errors, s.camera.fov_deg);
    if (!errors.empty()) {
        printErrors(errors);
        result.exit_code = 2;
        return result;
    }
    FrameSpan span;
    if (std::string problem = selectFrames(job.selection, c.frames, span); !problem.empty()) return stop(2, problem);
    std::filesystem::path out = c.out;
    if (job.write_images || !job.stats_file.empty()) {
        std::string problem = checkWritableDir(job.write_images ? out : job.stats_file.parent_path().empty()
                                                                            ? std::filesystem::path(".")
                                                                            : job.stats_file.parent_path());
        if (!problem.empty()) return stop(2, problem);
    }
    const bool exr = c.format == ImageFormat::Exr;
    const ImageFormat file_format = exr ? ImageFormat::Exr : ImageFormat::Png;  // mp4: PNG frames first

    // The manifest: what this run is, and (resuming) what an earlier run of it left.
    Manifest manifest;
    manifest.version = vistaVersion();
    manifest.scene_hash = sceneHash(s);
    manifest.path_hash = pathHash(path_file);
    manifest.path_file = c.path;
    manifest.settings = sceneText(s);
    manifest.total_frames = c.frames;
    manifest.fps = c.fps;
    manifest.width = c.width;
    manifest.height = c.height;
    manifest.format = exr ? "exr" : "png";
    manifest.shard = job.selection.shard;
    manifest.shards = job.selection.shards;
    manifest.span = span;
    manifest.settle_frames = job.write_images ? c.settle_frames : job.warmup_frames;
    const std::filesystem::path manifest_file = out / manifestName(job.selection);
    const bool whole_video = c.format == ImageFormat::Mp4 && span == FrameSpan{0, c.frames};
    const std::filesystem::path video_file = out / "capture.mp4";

    std::vector<int> todo;
    if (job.write_images && job.resume && std::filesystem::exists(manifest_file)) {
        Manifest old;
        if (std::string problem = Manifest::load(manifest_file, old); !problem.empty())
            return stop(2, problem + "; remove it to start the run over");
        if (std::string differs = resumeMismatch(old, manifest); !differs.empty())
            return stop(2, manifest_file.string() + ": cannot resume a run of another capture: its " + differs +
                                "; choose another --out or remove the manifest");
        manifest.settle_ms = old.settle_ms;
        manifest.wall_s = old.wall_s;
        for (int k = span.first; k < span.end; ++k)
            if (const ManifestFrame* done = old.find(k); done && fileChecksum(out / done->file) == done->checksum) {
                manifest.frames.push_back(*done);
                ++result.kept;
            }
    }
    for (int k = span.first; k < span.end; ++k)
        if (!manifest.find(k)) todo.push_back(k);
    if (job.write_images && !job.force && !job.resume) {
        for (int k = span.first; k < span.end; ++k)
            if (std::filesystem::exists(captureFileName(out, k, file_format)))
                return stop(2, captureFileName(out, k, file_format).string() +
                                    " already exists; pass --force to overwrite, --resume to keep the frames its manifest "
                                    "vouches for, or choose another --out");
        if (std::filesystem::exists(manifest_file))
            return stop(2, manifest_file.string() + " already exists; pass --resume to continue that run, --force to "
                                                     "start over, or choose another --out");
        if (whole_video && std::filesystem::exists(video_file))
            return stop(2, video_file.string() + " already exists; pass --force to replace it, or choose another --out");
    }
    if (std::string problem = checkCaptureOutputs(job); !problem.empty()) return stop(2, problem);

    if (std::string problem = checkFrameMemory(c.width, c.height); !problem.empty()) return {fail(1, problem), {}, {}};
    std::string error;
    ContextOptions options{c.width, c.height, /*visible=*/false, false, false, s.window.gl_debug, "vista capture"};
    auto context = createContext(job.backend, options, error);
    if (!context) return stop(1, error);
    FrameRenderer renderer(vistaRoot());
    errors = renderer.prepare(s);
    if (!errors.empty()) {
        printErrors(errors);
        result.exit_code = 2;
        return result;
    }

    RunStats& stats = result.stats;
    stats.renderer = context->renderer();
    stats.backend = backendName(job.backend);
    stats.gpu_timer = timerModeName(renderer.timers().mode());
    stats.width = c.width;
    stats.height = c.height;
    bool want_stats = !job.stats_file.empty() || !job.write_images;
    if (want_stats) stats.reference_copy_ms = renderer.measureReferenceCopy(c.width, c.height);

    std::vector<unsigned char> ldr;
    std::vector<std::uint16_t> hdr;
    FrameRequest request;
    if (exr)
        request.capture_hdr = &hdr;
    else
        request.capture_ldr = &ldr;
    request.count_nonfinite = want_stats;
    request.count_lights = want_stats;
    request.count_grass = want_stats;
    request.count_objects = want_stats;
    request.count_weather = want_stats;

    std::string dot;  // the last frame's graph, with --dot
    // Settle frames render exactly as written frames do (same request, read back and all), so
    // the temporal state they leave is the state a sequential run has at that frame.
    auto viewAt = [&](int frame) {
        const CameraPose pose = path.sample(captureFrameTime(path.startTime(), frame, double(c.fps)));
        return ViewParams{pose.position, pose.yaw_deg, pose.pitch_deg, pose.fov_deg, s.camera.near_m, c.width, c.height};
    };
    // sequence: the jitter and blue-noise index (default: the path frame, not the run's count).
    auto renderFrame = [&](int frame, bool last, std::optional<int> sequence = std::nullopt) {
        request.graph_dot = last && !job.dot_file.empty() ? &dot : nullptr;
        request.sequence_frame = sequence.value_or(frame);
        return renderer.render(s, viewAt(frame), captureFrameTime(path.startTime(), frame, double(c.fps)), request);
    };
    // A written frame the camera cuts to (TAA's cut thresholds) has no history. Before it,
    // [capture] cut_settle_frames unwritten frames at its own pose and time (indexed as the path
    // frames before it, so jitter and blue noise move) build one; the time standing still, the
    // exposure keeps what the frames before the cut adapted it to. Decided by the path alone, so a
    // shard renders the same frames.
    // Only where there is a history to build (TAA or the clouds' accumulation): without one the
    // frames would change nothing but the exposure's last steps, and shards stay bit-identical.
    const bool history = (s.taa.enabled && s.postfx.enabled) || s.clouds.temporal;
    const int cut_settle = job.write_images && history ? c.cut_settle_frames : 0;
    auto settleAfterCut = [&](int frame) {
        if (cut_settle <= 0 || !cameraCut(viewAt(frame - 1), viewAt(frame), s.taa.cut_distance_m, s.taa.cut_angle_deg))
            return 0;
        for (int k = frame - cut_settle; k < frame; ++k) renderFrame(frame, false, k);
        return cut_settle;
    };
    auto flushStats = [&](bool wait) {
        stats.addTimings(renderer.timers().collect(wait));
        for (const auto& v : renderer.counters().collect(wait))
            if (stats.frames().count(v.frame)) stats.addCounter(v.frame, v.name, double(v.value));  // not settle frames'
    };

    // A resumed run re-renders frames whose files its manifest no longer vouches for.
    const bool replace = job.force || job.resume;
    Progress progress(int(todo.size()), job.write_images ? "capture" : "bench");
    const std::vector<FrameSpan> runs = consecutiveRuns(todo);
    const int settle = job.write_images ? c.settle_frames : job.warmup_frames;
    // Programs compile on first use, so a capture compiles the variants its scene uses, not the
    // whole list (allPrograms()). One unwritten frame compiles them before any timing starts (the
    // runs' resetHistory() forgets it); a compile error there, or in a later frame that needs
    // another variant, stops the capture before its image is written.
    auto shaderFailure = [&] {
        std::string failed = renderer.programErrors();
        return failed.empty() ? std::optional<CaptureResult>() : stop(1, "shader compilation failed:\n" + failed);
    };
    if (!runs.empty()) renderFrame(runs.front().first - settle, false);
    if (auto failed = shaderFailure()) return *failed;
    int done = 0;
    for (const FrameSpan& run : runs) {
        // Every run starts from a fresh history, sequential runs too: frame k then depends on
        // frames k - settle .. k alone, whichever process renders it.
        renderer.resetHistory();
        const auto settle_start = std::chrono::steady_clock::now();
        for (int k = run.first - settle; k < run.first; ++k) renderFrame(k, false);
        manifest.settle_ms += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - settle_start).count();
        result.settle_frames += settle;

        for (int frame = run.first; frame < run.end; ++frame) {
            const auto cut_start = std::chrono::steady_clock::now();
            if (const int n = settleAfterCut(frame); n > 0) {
                manifest.settle_ms += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - cut_start).count();
                result.settle_frames += n;
            }
            const auto start = std::chrono::steady_clock::now();
            const std::uint64_t index = renderer.frameIndex();
            FrameReport report = renderFrame(frame, &run == &runs.back() && frame + 1 == run.end);
            if (auto failed = shaderFailure()) return *failed;
            const double cpu_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();

            stats.executed = report.executed;
            stats.culled = report.culled;
            stats.addFrame(index, cpu_ms);
            for (const auto& [name, value] : report.counters) stats.addCounter(index, name, value);
            flushStats(false);
            if (job.write_images) {
                std::filesystem::path file = captureFileName(out, frame, file_format);
                std::string problem = exr ? writeExr(file, c.width, c.height, hdr, replace)
                                      : writePng(file, c.width, c.height, ldr, replace);
                std::optional<std::string> sum = problem.empty() ? fileChecksum(file) : std::nullopt;
                if (problem.empty() && !sum) problem = file.string() + ": cannot read back the image just written";
                if (!problem.empty()) return stop(1, problem);
                result.images.push_back(file);
                const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
                ManifestFrame entry{frame, file.filename().string(), *sum, ms};
                manifest.frames.insert(std::upper_bound(manifest.frames.begin(), manifest.frames.end(), entry,
                                                        [](const auto& a, const auto& b) { return a.index < b.index; }),
                                       entry);
                // After every frame: a run killed at any point leaves a manifest of what it finished.
                problem = writeFileAtomic(manifest_file, manifest.json(), /*force=*/true);  // this run's own file
                if (!problem.empty()) return stop(1, problem);
            }
            if (request.graph_dot) {
                std::string problem = writeFileAtomic(job.dot_file, dot, job.force);
                if (!problem.empty()) return stop(1, problem);
            }
            if (job.progress) progress.update(++done);
        }
    }
    if (job.progress) progress.finish();
    flushStats(true);

    if (job.write_images) {
        manifest.complete = true;
        manifest.wall_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - run_start).count();
        if (std::string problem = writeFileAtomic(manifest_file, manifest.json(), /*force=*/true); !problem.empty())
            return stop(1, problem);
        result.manifest = manifest_file;
        if (whole_video) {
            std::vector<std::filesystem::path> frames;
            for (const ManifestFrame& f : manifest.frames) frames.push_back(out / f.file);
            std::string problem = encodeVideo(frames, video_file, {double(c.fps), c.crf, job.force || job.resume});
            if (!problem.empty()) return stop(1, problem);
            result.video = video_file;
        }
    }
    if (!job.stats_file.empty()) {
        std::string problem = writeFileAtomic(job.stats_file, stats.json(), job.force);
        if (!problem.empty()) return stop(1, problem);
    }
    return result;
}

}  // namespace vista
