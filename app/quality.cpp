// The quality runner: one context and one renderer for every run. Each run measures the
// reference copy, renders its warm-up frames at the path's first pose at times before the
// path starts (time going backwards resets the temporal state: auto exposure, autofocus, the
// motion blur's previous camera), then the measured frames, so every run sees the same
// sequence. The reference runs first; the others are compared with its frames as they render.
#include "app/quality.h"

#include "app/camera_path.h"
#include "app/capture.h"
#include "app/frame.h"
#include "app/progress.h"
#include "app/quality_report.h"
#include "app/scene.h"
#include "app/stats.h"
#include "config/presets.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

namespace vista {
namespace {

struct RunSpec {
    std::string name, kind, knob, value;
    Settings settings;
};

std::string knobValue(const QualityKnob& k, double v) {
    if (v == 0.0 && k.special_zero) return k.special_zero;
    if (k.flag) return v != 0.0 ? "on" : "off";
    char s[32];
    std::snprintf(s, sizeof s, "%g", v);
    return s;
}

struct Frames {
    std::vector<std::vector<unsigned char>> ldr;
    std::vector<std::vector<std::uint16_t>> hdr;
};

}  // namespace

std::string qualityKnobNames() {
    std::string names;
    for (const QualityKnob& k : qualityKnobs()) names += (names.empty() ? "" : ", ") + std::string(k.name);
    return names;
}

int runQuality(const QualityOptions& o) {
    const Settings& scene = o.scene;
    const CaptureSettings& c = scene.capture;
    InputErrors errors;
    CameraPath path = CameraPath::load(resolveInput(c.path), errors, scene.camera.fov_deg);
    if (!errors.empty()) {
        printErrors(errors);
        return 2;
    }
    for (const std::string& name : o.knobs)
        if (!findQualityKnob(name)) return fail(2, "--knobs: '" + name + "' is not a quality knob; accepted: " + qualityKnobNames());
    std::string problem = checkWritableDir(o.out);
    if (!problem.empty()) return fail(2, problem);

    // The runs: the reference first (every other run is compared with it), the other presets,
    // then per knob every preset value that differs from the reference's.
    std::vector<RunSpec> runs;
    QualityReport report;
    auto preset = [&](QualityPreset p) {
        RunSpec r{qualityPresetName(p), "preset", "", "", scene};
        applyQualityPreset(r.settings, p);
        runs.push_back(std::move(r));
    };
    preset(QualityPreset::Reference);
    for (QualityPreset p : {QualityPreset::Low, QualityPreset::Medium, QualityPreset::High, QualityPreset::Ultra}) preset(p);
    const Settings reference = runs.front().settings;
    for (const QualityKnob& k : qualityKnobs()) {
        const bool chosen = o.all_knobs || std::find(o.knobs.begin(), o.knobs.end(), k.name) != o.knobs.end();
        if (!chosen) continue;
        if (!k.active(scene)) {
            report.inactive_knobs.push_back(k.name);
            continue;
        }
        std::vector<double> values;
        for (int i = 0; i + 1 < kQualityPresetCount; ++i) {
            const double v = k.levels[std::size_t(i)];
            if (v != k.levels.back() && std::find(values.begin(), values.end(), v) == values.end()) values.push_back(v);
        }
        if (values.empty()) continue;
        report.knob_order.push_back(k.name);
        for (double v : values) {
            RunSpec r{std::string(k.name) + "=" + knobValue(k, v), "knob", k.name, knobValue(k, v), reference};
            k.apply(r.settings, v, scene);
            runs.push_back(std::move(r));
        }
    }

    std::string error;
    ContextOptions options{c.width, c.height, /*visible=*/false, false, false, scene.window.gl_debug, "vista quality"};
    auto context = createContext(o.backend, options, error);
    if (!context) return fail(1, error);
    FrameRenderer renderer(vistaRoot());
    if (!renderer.compilePrograms(error)) return fail(1, "shader compilation failed:\n" + error);

    report.scene = o.scene_name;
    report.path = c.path;
    report.renderer = context->renderer();
    report.backend = backendName(o.backend);
    report.gpu_timer = timerModeName(renderer.timers().mode());
    report.width = c.width;
    report.height = c.height;
    report.frames = o.frames;
    report.warmup = o.warmup;
    report.planned_runs = int(runs.size());

    Frames ref;
    std::vector<unsigned char> ldr;
    std::vector<std::uint16_t> hdr;
    FrameRequest request;
    request.capture_ldr = &ldr;
    request.capture_hdr = &hdr;
    const double step = 1.0 / double(c.fps);
    const int per_run = o.warmup + o.frames;
    Progress progress(int(runs.size()) * per_run, "quality");
    int done = 0;
    for (RunSpec& spec : runs) {
        errors = renderer.prepare(spec.settings);
        if (!errors.empty()) {
            printErrors(errors);
            return 2;
        }
        RunStats stats;
        const double copy_ms = renderer.measureReferenceCopy(c.width, c.height);
        ErrorAccumulator ldr_error, hdr_error;
        const bool is_reference = ref.ldr.empty();
        for (int i = -o.warmup; i < o.frames; ++i) {
            const double t = path.startTime() + double(i) * step;  // warm-up: before the start
            const CameraPose pose = path.sample(std::max(t, path.startTime()));
            const ViewParams view{pose.position, pose.yaw_deg, pose.pitch_deg, pose.fov_deg, scene.camera.near_m, c.width, c.height};
            const std::uint64_t index = renderer.frameIndex();
            const auto start = std::chrono::steady_clock::now();
            renderer.render(spec.settings, view, t, request);
            const double cpu_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
            if (i >= 0) {
                stats.addFrame(index, cpu_ms);
                if (is_reference) {
                    ref.ldr.push_back(ldr);
                    ref.hdr.push_back(hdr);
                } else {
                    ldr_error.addLdr(ldr, ref.ldr[std::size_t(i)], c.width, c.height);
                    hdr_error.addHdr(hdr, ref.hdr[std::size_t(i)], c.width, c.height, report.hdr_range);
                }
            }
            stats.addTimings(renderer.timers().collect());
            if (o.progress) progress.update(++done);
        }
        stats.addTimings(renderer.timers().collect(/*wait=*/true));
        stats.reference_copy_ms = copy_ms;
        if (is_reference) report.hdr_range = log2LuminanceRange(ref.hdr, c.width, c.height);

        QualityRun run;
        run.name = spec.name;
        run.kind = spec.kind;
        run.knob = spec.knob;
        run.value = spec.value;
        run.ldr = ldr_error.result();
        run.hdr = hdr_error.result();
        run.gpu_ms = stats.gpuMedian();
        run.cpu_ms = stats.cpuMedian();
        run.copy_ms = copy_ms;
        run.passes = stats.passSummary();
        report.runs.push_back(std::move(run));
        // The report so far after every run: an interrupted run leaves the runs it finished.
        markParetoFront(report);
        problem = writeQualityReport(o.out, report);
        if (!problem.empty()) return fail(1, problem);
    }
    if (o.progress) progress.finish();
    std::printf("%-34s %8s %8s %9s %8s %7s\n", "run", "PSNR dB", "SSIM", "HDR dB", "GPU ms", "Pareto");
    for (const QualityRun& r : report.runs)
        std::printf("%-34s %8s %8.4f %9s %8.1f %7s\n", r.name.c_str(), formatDb(r.ldr.psnr_db).c_str(), r.ldr.ssim,
                    formatDb(r.hdr.psnr_db).c_str(), r.gpu_ms, r.pareto ? "yes" : "");
    std::printf("vista: wrote quality.csv, quality_passes.csv, quality.md and quality.png to %s/\n", o.out.string().c_str());
    return 0;
}

}  // namespace vista
