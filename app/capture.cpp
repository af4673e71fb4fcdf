// Capture: validate everything first (path, output directory, existing files), then
// render frame by frame at a fixed time step.
#include "app/capture.h"

#include "app/camera_path.h"
#include "app/frame.h"
#include "app/image_writer.h"
#include "app/memory_budget.h"
#include "app/progress.h"
#include "app/scene.h"

#include <chrono>
#include <cstdio>
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

CaptureResult runCapture(const CaptureJob& job) {
    CaptureResult result;
    const Settings& s = job.settings;
    const CaptureSettings& c = s.capture;

    InputErrors errors;
    CameraPath path = CameraPath::load(resolveInput(c.path), errors, s.camera.fov_deg);
    if (!errors.empty()) {
        printErrors(errors);
        result.exit_code = 2;
        return result;
    }
    std::filesystem::path out = c.out;
    if (job.write_images || !job.stats_file.empty()) {
        std::string problem = checkWritableDir(job.write_images ? out : job.stats_file.parent_path().empty()
                                                                            ? std::filesystem::path(".")
                                                                            : job.stats_file.parent_path());
        if (!problem.empty()) return {fail(2, problem), {}, {}};
    }
    if (std::string problem = checkCaptureOutputs(job); !problem.empty()) return {fail(2, problem), {}, {}};
    if (job.write_images && !job.force)
        for (int i = 0; i < c.frames; ++i)
            if (std::filesystem::exists(captureFileName(out, i, c.format)))
                return {fail(2, captureFileName(out, i, c.format).string() +
                                    " already exists; pass --force to overwrite, or choose another --out"), {}, {}};

    if (std::string problem = checkFrameMemory(c.width, c.height); !problem.empty()) return {fail(1, problem), {}, {}};
    std::string error;
    ContextOptions options{c.width, c.height, /*visible=*/false, false, false, s.window.gl_debug, "vista capture"};
    auto context = createContext(job.backend, options, error);
    if (!context) return {fail(1, error), {}, {}};
    FrameRenderer renderer(vistaRoot());
    if (!renderer.compilePrograms(error)) return {fail(1, "shader compilation failed:\n" + error), {}, {}};
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
    bool exr = c.format == ImageFormat::Exr;
    if (exr)
        request.capture_hdr = &hdr;
    else
        request.capture_ldr = &ldr;
    request.count_nonfinite = want_stats;
    request.count_lights = want_stats;
    request.count_grass = want_stats;
    request.count_weather = want_stats;

    Progress progress(c.frames, job.write_images ? "capture" : "bench");
    int total = job.warmup_frames + c.frames;
    for (int i = 0; i < total; ++i) {
        int frame = i - job.warmup_frames;  // negative while warming up
        double t = path.startTime() + std::max(frame, 0) / double(c.fps);
        CameraPose pose = path.sample(t);
        ViewParams view{pose.position, pose.yaw_deg, pose.pitch_deg, pose.fov_deg, s.camera.near_m, c.width, c.height};

        auto start = std::chrono::steady_clock::now();
        std::uint64_t index = renderer.frameIndex();
        std::string dot;
        request.graph_dot = !job.dot_file.empty() && i + 1 == total ? &dot : nullptr;
        FrameReport report = renderer.render(s, view, t, request);
        double cpu_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        if (frame < 0) continue;

        stats.executed = report.executed;
        stats.culled = report.culled;
        stats.addFrame(index, cpu_ms);
        for (const auto& [name, value] : report.counters) stats.addCounter(index, name, value);
        stats.addTimings(renderer.timers().collect());
        for (const auto& v : renderer.counters().collect()) stats.addCounter(v.frame, v.name, double(v.value));
        if (job.write_images) {
            std::filesystem::path file = captureFileName(out, frame, c.format);
            std::string problem = exr ? writeExr(file, c.width, c.height, hdr, job.force)
                                      : writePng(file, c.width, c.height, ldr, job.force);
            if (!problem.empty()) return {fail(1, problem), std::move(result.stats), result.images};
            result.images.push_back(file);
        }
        if (!dot.empty()) {
            std::string problem = writeFileAtomic(job.dot_file, dot, job.force);
            if (!problem.empty()) return {fail(1, problem), std::move(result.stats), result.images};
        }
        if (job.progress) progress.update(frame + 1);
    }
    if (job.progress) progress.finish();
    stats.addTimings(renderer.timers().collect(/*wait=*/true));
    for (const auto& v : renderer.counters().collect(true)) stats.addCounter(v.frame, v.name, double(v.value));

    if (!job.stats_file.empty()) {
        std::string problem = writeFileAtomic(job.stats_file, stats.json(), job.force);
        if (!problem.empty()) return {fail(1, problem), std::move(result.stats), result.images};
    }
    return result;
}

}  // namespace vista
