// The `vista quality` report: one row per run (a preset, or one knob changed from the
// reference), the Pareto front of error against GPU time, and the three outputs: quality.csv
// (plus quality_passes.csv, the per-pass times), quality.md (tables) and quality.png (PSNR
// against ms drawn with OpenImageIO). No GL.
#pragma once

#include "app/image_metrics.h"
#include "app/stats.h"
#include "app/temporal_metrics.h"

#include <filesystem>
#include <string>
#include <vector>

namespace vista {

struct QualityRun {
    std::string name;   // "low" ... "reference", or "shadows.resolution=512"
    std::string kind;   // "preset" or "knob"
    std::string knob;   // the knob's name (knob runs)
    std::string value;  // the knob's value as printed (knob runs)
    ImageError ldr, hdr;
    double gpu_ms = 0.0, cpu_ms = 0.0;  // medians over the measured frames
    double copy_ms = 0.0;               // the reference copy measured before this run
    std::vector<PassSummary> passes;    // medians, in execution order
    bool pareto = false;                // on the front of (gpu_ms, -psnr ldr)
    double front_gap_db = 0.0;          // best LDR PSNR of any run at no more gpu_ms, minus this run's (0: on the front)
    TemporalFigures temporal;           // single-frame PSNR, flicker, frames to converge after a cut

    double copies() const { return copy_ms > 0.0 ? gpu_ms / copy_ms : 0.0; }
};

struct QualityReport {
    std::string scene, path, renderer, backend, gpu_timer;
    int width = 0, height = 0, frames = 0, warmup = 0;
    StopsRange hdr_range;                    // the reference's log2 luminance range
    std::vector<QualityRun> runs;            // presets first (reference among them), then knobs in table order
    std::vector<std::string> inactive_knobs;  // knobs whose feature the scene does not use (no runs)
    std::vector<std::string> knob_order;     // knob names with runs, in table order
    TemporalQualityOptions temporal;         // how the temporal figures were measured
    int planned_runs = 0;                    // runs this report will hold; fewer: it is marked incomplete

    // False while runs are missing: the files written after each run say so, and a killed
    // `vista quality` leaves them saying so.
    bool complete() const { return int(runs.size()) >= planned_runs; }
    std::string incompleteNote() const;  // "INCOMPLETE: 3 of 40 runs measured (...)"
};

// Which points are on the Pareto front when both cost and error are minimised: no other point
// is at most as costly and at most as wrong, and strictly better in one.
std::vector<bool> paretoFront(const std::vector<double>& cost, const std::vector<double>& error);

// Sets pareto and front_gap_db of every run (error: -psnr of the final image).
void markParetoFront(QualityReport& report);

std::string qualityCsv(const QualityReport& report);
std::string qualityPassesCsv(const QualityReport& report);
std::string qualityMarkdown(const QualityReport& report, bool chart_has_labels);

// Draws the chart (x: GPU ms, log scale; y: LDR PSNR in dB, infinite at the top) to file through
// a temporary name. labels: set to whether text could be drawn (a font was found). "" or why not.
std::string writeQualityChart(const std::filesystem::path& file, const QualityReport& report, bool& labels);

// Writes quality.csv, quality_passes.csv, quality.md and quality.png into dir. "" or why not.
std::string writeQualityReport(const std::filesystem::path& dir, const QualityReport& report);

// A metric as the tables print it ("inf" for an infinite PSNR).
std::string formatDb(double db);

}  // namespace vista
