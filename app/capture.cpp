// Capture: validate everything first (path, output directory, existing files), then
// render frame by frame at a fixed time step.
#include "app/capture.h"

#include "app/camera_path.h"
#include "app/frame.h"
#include "app/image_writer.h"
#include "app/progress.h"
#include "app/scene.h"

#include <chrono>
#include <cstdio>
#include <fstream>

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
    std::filesystem::path probe = dir / ".vista-write-test";
    {
        std::ofstream out(probe);
        if (!out) return dir.string() + ": output directory is not writable";
    }
    std::filesystem::remove(probe, ec);
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
    if (job.write_images && !job.force)
        for (int i = 0; i < c.frames; ++i)
            if (std::filesystem::exists(captureFileName(out, i, c.format)))
                return {fail(2, captureFileName(out, i, c.format).string() +
                                    " already exists; pass --force to overwrite, or choose another --out"), {}, {}};

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
            std::string problem = exr ? writeExr(file, c.width, c.height, hdr) : writePng(file, c.width, c.height, ldr);
            if (!problem.empty()) return {fail(1, problem), std::move(result.stats), result.images};
            result.images.push_back(file);
        }
        if (!dot.empty()) {
            std::string problem = writeFileAtomic(job.dot_file, dot);
            if (!problem.empty()) return {fail(1, problem), std::move(result.stats), result.images};
        }
        if (job.progress) progress.update(frame + 1);
    }
    if (job.progress) progress.finish();
    stats.addTimings(renderer.timers().collect(/*wait=*/true));
    for (const auto& v : renderer.counters().collect(true)) stats.addCounter(v.frame, v.name, double(v.value));

    if (!job.stats_file.empty()) {
        std::string problem = writeFileAtomic(job.stats_file, stats.json());
        if (!problem.empty()) return {fail(1, problem), std::move(result.stats), result.images};
    }
    return result;
}

}  // namespace vista
