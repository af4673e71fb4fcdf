// The quality runner: one context and one renderer for every run. Each run measures the
// reference copy, resets every history, renders its warm-up (settle) frames at the path's first
// pose at times before the path starts, then the measured frames, each with its path frame as
// its sequence index (as captures do), so every run sees the same sequence. The reference runs
// first; the others are compared with its frames as they render. The temporal columns follow
// each run's measured frames: flicker from the measured frames themselves, then the first
// frame's converged reference (once, with the reference's settings) and the cut sequence.
#include "app/quality.h"

#include "app/camera_path.h"
#include "app/capture.h"
#include "app/frame.h"
#include "app/progress.h"
#include "app/quality_report.h"
#include "app/scene.h"
#include "app/stats.h"
#include "app/temporal_quality.h"
#include "config/ini.h"
#include "config/presets.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

namespace vista {
namespace {

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

std::vector<QualityRunSpec> qualityRuns(const QualityOptions& o, std::vector<std::string>& inactive_knobs,
                                    std::vector<std::string>& knob_order) {
    const Settings& scene = o.scene;
    std::vector<QualityRunSpec> runs;
    auto preset = [&](QualityPreset p) {
        QualityRunSpec r{qualityPresetName(p), "preset", "", "", scene};
        applyQualityPreset(r.settings, p);
        for (const std::string& assignment : o.pinned) applyOverride(assignment, r.settings);  // valid: the scene took them
        runs.push_back(std::move(r));
    };
    preset(o.reference_preset);
    runs.front().name = "reference";
    if (o.bench)
        runs.push_back(QualityRunSpec{"scene", "scene", "", "", scene});
    else
        for (QualityPreset p : {QualityPreset::Low, QualityPreset::Medium, QualityPreset::High, QualityPreset::Ultra}) preset(p);
    const Settings reference = runs.front().settings;
    for (const QualityKnob& k : o.bench ? std::vector<QualityKnob>{} : qualityKnobs()) {
        const bool chosen = o.all_knobs || std::find(o.knobs.begin(), o.knobs.end(), k.name) != o.knobs.end();
        if (!chosen) continue;
        if (!k.active(scene)) {
            inactive_knobs.push_back(k.name);
            continue;
        }
        std::vector<double> values;
        for (int i = 0; i + 1 < kQualityPresetCount; ++i) {
            const double v = k.levels[std::size_t(i)];
            if (v != k.levels.back() && std::find(values.begin(), values.end(), v) == values.end()) values.push_back(v);
        }
        if (values.empty()) continue;
        knob_order.push_back(k.name);
        for (double v : values) {
            QualityRunSpec r{std::string(k.name) + "=" + knobValue(k, v), "knob", k.name, knobValue(k, v), reference};
            k.apply(r.settings, v, scene);
            runs.push_back(std::move(r));
        }
    }
    return runs;
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
    QualityReport report;
    const std::vector<QualityRunSpec> runs = qualityRuns(o, report.inactive_knobs, report.knob_order);

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
    std::vector<unsigned char> ldr, converged;  // converged: the first measured frame's converged reference
    std::vector<std::uint16_t> hdr;
    std::vector<float> depth;
    FrameRequest request;
    request.capture_ldr = &ldr;
    request.capture_hdr = &hdr;
    report.temporal = o.temporal;
    const double step = 1.0 / double(c.fps);
    const int per_run = o.warmup + o.frames;
    Progress progress(int(runs.size()) * per_run, "quality");
    int done = 0;
    for (const QualityRunSpec& spec : runs) {
        errors = renderer.prepare(spec.settings);
        if (!errors.empty()) {
            printErrors(errors);
            return 2;
        }
        RunStats stats;
        const double copy_ms = renderer.measureReferenceCopy(c.width, c.height);
        ErrorAccumulator ldr_error, hdr_error;
        const bool is_reference = ref.ldr.empty();
        std::vector<SequenceFrame> sequence;  // the measured frames, for flicker
        double exposure_scale = 0.0;          // auto exposure's scale at the first measured frame
        ViewParams first_view;
        const double first_t = path.startTime();
        renderer.resetHistory();
        for (int i = -o.warmup; i < o.frames; ++i) {
            const double t = path.startTime() + double(i) * step;  // warm-up: before the start
            const CameraPose pose = path.sample(std::max(t, path.startTime()));
            const ViewParams view{pose.position, pose.yaw_deg, pose.pitch_deg, pose.fov_deg, scene.camera.near_m, c.width, c.height};
            const std::uint64_t index = renderer.frameIndex();
            request.sequence_frame = i;  // the jitter and blue noise of path frame i, as in a capture
            request.depth = i >= 0 ? &depth : nullptr;
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
                sequence.push_back({ldr, depth, view});
                if (i == 0) {
                    first_view = view;
                    if (const AutoExposure* a = renderer.postfx().autoExposure()) exposure_scale = a->read().scale;
                }
            }
            stats.addTimings(renderer.timers().collect());
            if (o.progress) progress.update(++done);
        }
        stats.addTimings(renderer.timers().collect(/*wait=*/true));
        stats.reference_copy_ms = copy_ms;
        if (is_reference) report.hdr_range = log2LuminanceRange(ref.hdr, c.width, c.height);

        // Temporal error: flicker over consecutive measured frames; the first frame and the cut
        // sequence against the first frame's converged reference (rendered once, from the
        // reference's settings, with its exposure).
        TemporalFigures temporal;
        std::vector<double> changes;
        for (std::size_t k = 1; k < sequence.size(); ++k) {
            std::vector<double> pair = reprojectedLumaChange(sequence[k - 1], sequence[k]);
            changes.insert(changes.end(), pair.begin(), pair.end());
        }
        temporal.flicker = flickerStats(std::move(changes));
        if (is_reference && o.temporal.converge_frames > 0 && !sequence.empty())
            converged = renderConvergedReference(renderer, spec.settings, first_view, first_t, exposure_scale, o.temporal);
        if (!converged.empty() && !sequence.empty()) {
            ErrorAccumulator single;
            single.addLdr(sequence.front().ldr, converged, c.width, c.height);
            temporal.single_psnr_db = single.result().psnr_db;
            temporal.cut_psnr_db = renderCutCurve(renderer, spec.settings, first_view, first_t, exposure_scale, converged, o.temporal);
            if (!temporal.cut_psnr_db.empty()) {
                temporal.ghost_frames = framesUntilConverged(temporal.cut_psnr_db, 1.0);
                temporal.converged_psnr_db = temporal.cut_psnr_db.back();
            }
        }
        if (o.progress) progress.update(done);

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
        run.temporal = std::move(temporal);
        report.runs.push_back(std::move(run));
        // The report so far after every run: an interrupted run leaves the runs it finished.
        markParetoFront(report);
        problem = writeQualityReport(o.out, report);
        if (!problem.empty()) return fail(1, problem);
    }
    if (o.progress) progress.finish();
    std::printf("%-34s %8s %8s %9s %8s %8s %7s %8s %8s %6s %6s\n", "run", "PSNR dB", "SSIM", "HDR dB", "GPU ms", "copies",
                "Pareto", "1-frame", "flicker", "p99", "ghost");
    const TemporalFigures& reference_t = report.runs.front().temporal;
    for (const QualityRun& r : report.runs) {
        const TemporalFigures& t = r.temporal;
        std::printf("%-34s %8s %8.4f %9s %8.1f %8.1f %7s %8s %8.2f %6.1f %6s\n", r.name.c_str(), formatDb(r.ldr.psnr_db).c_str(),
                    r.ldr.ssim, formatDb(r.hdr.psnr_db).c_str(), r.gpu_ms, r.copies(), r.pareto ? "yes" : "",
                    formatDb(t.single_psnr_db).c_str(), t.flicker.mean, t.flicker.p99,
                    t.ghost_frames < 0 ? "-" : std::to_string(t.ghost_frames).c_str());
    }
    std::printf("1-frame: dB of the first frame against the converged reference (%d frames at %dx its size); flicker: "
                "mean and p99 luma change (8-bit levels) between reprojected consecutive frames (the reference "
                "sequence's: %.2f, %.1f); ghost: frames after a cut until within 1 dB of converged\n",
                o.temporal.converge_frames, o.temporal.supersample, reference_t.flicker.mean, reference_t.flicker.p99);
    std::printf("vista: wrote quality.csv, quality_passes.csv, quality.md and quality.png to %s/\n", o.out.string().c_str());
    return 0;
}

}  // namespace vista
