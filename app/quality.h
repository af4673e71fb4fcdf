// `vista quality`: renders the same camera-path frames at every preset (low, medium, high,
// ultra, reference) and, for each quality knob the scene uses, at each preset value of that
// knob with everything else at the reference; reports error against the reference beside GPU
// time (app/quality_report.h) into --out, and the temporal error of each run (single-frame PSNR
// against a converged, supersampled reference, flicker, frames to converge after a cut).
// `vista bench temporal` is the same runner with two runs: the reference and the scene as given.
#pragma once

#include "app/gl_context.h"
#include "app/temporal_metrics.h"
#include "config/presets.h"
#include "config/settings.h"

#include <filesystem>
#include <string>
#include <vector>

namespace vista {

struct QualityOptions {
    Settings scene;                // the scene, [capture] path/fps/size already from the command line
    std::string scene_name;        // for the report
    int frames = 2;                // measured frames per run
    int warmup = 8;                // settle frames rendered first at the path's first pose, not measured
    std::filesystem::path out;     // output directory
    Backend backend = Backend::OSMesa;
    bool all_knobs = true;         // false: only `knobs` (empty: presets only)
    std::vector<std::string> knobs;
    bool progress = true;
    TemporalQualityOptions temporal;  // the temporal columns (docs/temporal.md, "Temporal error")
    bool bench = false;               // `vista bench temporal`: the reference and the scene as given, no knobs
    QualityPreset reference_preset = QualityPreset::Reference;  // bench temporal --reference-preset
    // The command line's --set assignments: applied again over every preset, so they hold in
    // every run (as over capture --preset); a swept knob still sets its own key.
    std::vector<std::string> pinned;
};

// One run of `vista quality`: a preset, the scene as given, or the reference with one knob lowered.
struct QualityRunSpec {
    std::string name, kind, knob, value;  // kind: "preset", "scene" or "knob"
    Settings settings;
};

// The runs in order: the reference, the other presets (or the scene as given), then per chosen
// knob every level below the reference's. Knobs the scene leaves without effect go to
// `inactive_knobs`; the swept ones, in order, to `knob_order`.
std::vector<QualityRunSpec> qualityRuns(const QualityOptions& options, std::vector<std::string>& inactive_knobs,
                                    std::vector<std::string>& knob_order);

// Names of the knobs a --knobs list may give (qualityKnobs()), comma-separated, for messages.
std::string qualityKnobNames();

// Returns the exit code (0; 1 runtime failure; 2 bad input).
int runQuality(const QualityOptions& options);

}  // namespace vista
