// Report tables and the chart. The chart is drawn with OpenImageIO's ImageBufAlgo (fill,
// render_line, render_box, render_text with a DejaVu font when one is installed).
#include "app/quality_report.h"

#include "app/chart.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>

namespace vista {

std::vector<bool> paretoFront(const std::vector<double>& cost, const std::vector<double>& error) {
    const std::size_t n = cost.size();
    std::vector<bool> front(n, true);
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n && front[i]; ++j)
            if (j != i && cost[j] <= cost[i] && error[j] <= error[i] && (cost[j] < cost[i] || error[j] < error[i]))
                front[i] = false;
    return front;
}

void markParetoFront(QualityReport& r) {
    std::vector<double> cost, error;
    for (const QualityRun& run : r.runs) {
        cost.push_back(run.gpu_ms);
        error.push_back(-run.ldr.psnr_db);
    }
    const std::vector<bool> front = paretoFront(cost, error);
    for (std::size_t i = 0; i < r.runs.size(); ++i) {
        QualityRun& run = r.runs[i];
        run.pareto = front[i];
        double best = run.ldr.psnr_db;
        for (const QualityRun& other : r.runs)
            if (other.gpu_ms <= run.gpu_ms) best = std::max(best, other.ldr.psnr_db);
        run.front_gap_db = best == run.ldr.psnr_db ? 0.0 : std::isinf(best) ? best : best - run.ldr.psnr_db;
    }
}

std::string formatDb(double db) {
    if (std::isnan(db)) return "-";  // not measured
    if (std::isinf(db)) return db > 0 ? "inf" : "-inf";
    char s[32];
    std::snprintf(s, sizeof s, "%.2f", db);
    return s;
}

namespace {

std::string fmt(const char* format, double v) {
    char s[64];
    std::snprintf(s, sizeof s, format, v);
    return s;
}

const QualityRun* findRun(const QualityReport& r, const std::string& name) {
    for (const QualityRun& run : r.runs)
        if (run.name == name) return &run;
    return nullptr;
}

// The columns every table shares.
std::string metricCells(const QualityRun& run) {
    return formatDb(run.ldr.psnr_db) + " | " + fmt("%.4f", run.ldr.ssim) + " | " + fmt("%.0f", run.ldr.max_error) + " | " +
           formatDb(run.hdr.psnr_db) + " | " + fmt("%.4f", run.hdr.ssim) + " | " + fmt("%.2f", run.hdr.max_error) + " | " +
           fmt("%.1f", run.gpu_ms) + " | " + fmt("%.1f", run.copies()) + " | " + (run.pareto ? "**yes**" : "") + " | " +
           (run.pareto ? "0" : formatDb(run.front_gap_db)) + " |";
}

const char* kMetricHeader =
    "PSNR dB | SSIM | max err (levels) | HDR PSNR dB | HDR SSIM | HDR max err (stops) | GPU ms | copies | Pareto | gap dB |";
const char* kMetricRule = "---:|---:|---:|---:|---:|---:|---:|---:|:---:|---:|";

// The run's flicker over the reference run's (the reference sequence); NaN without a reference figure.
double flickerRatio(const QualityReport& r, const QualityRun& run) {
    const double ref = r.runs.empty() ? 0.0 : r.runs.front().temporal.flicker.mean;
    return ref > 0.0 ? run.temporal.flicker.mean / ref : std::numeric_limits<double>::quiet_NaN();
}

std::string temporalCsvCells(const QualityReport& r, const QualityRun& run) {
    const TemporalFigures& t = run.temporal;
    return formatDb(t.single_psnr_db) + "," + formatDb(t.converged_psnr_db) + "," + fmt("%.3f", t.flicker.mean) + "," +
           fmt("%.2f", t.flicker.p99) + "," + fmt("%.3f", flickerRatio(r, run)) + "," + std::to_string(t.ghost_frames);
}

}  // namespace

std::string QualityReport::incompleteNote() const {
    return "INCOMPLETE: " + std::to_string(runs.size()) + " of " + std::to_string(planned_runs) +
           " runs measured (vista quality is still running or was interrupted)";
}

std::string qualityCsv(const QualityReport& r) {
    // An incomplete report starts with a comment line, so no reader mistakes it for the whole.
    std::string out = r.complete() ? std::string() : "# " + r.incompleteNote() + "\n";
    out +=
        "name,kind,knob,value,psnr_ldr_db,ssim_ldr,max_err_ldr,psnr_hdr_db,ssim_hdr,max_err_hdr_stops,gpu_ms_median,"
        "cpu_ms_median,reference_copy_ms,copies,pareto,front_gap_db,single_frame_psnr_db,converged_psnr_db,flicker_mean,"
        "flicker_p99,flicker_ratio,ghost_frames\n";
    for (const QualityRun& run : r.runs) {
        out += run.name + "," + run.kind + "," + run.knob + "," + run.value + "," + formatDb(run.ldr.psnr_db) + "," +
               fmt("%.6f", run.ldr.ssim) + "," + fmt("%.1f", run.ldr.max_error) + "," + formatDb(run.hdr.psnr_db) + "," +
               fmt("%.6f", run.hdr.ssim) + "," + fmt("%.4f", run.hdr.max_error) + "," + fmt("%.3f", run.gpu_ms) + "," +
               fmt("%.3f", run.cpu_ms) + "," + fmt("%.4f", run.copy_ms) + "," + fmt("%.2f", run.copies()) + "," +
               (run.pareto ? "1" : "0") + "," + formatDb(run.front_gap_db) + "," + temporalCsvCells(r, run) + "\n";
    }
    return out;
}

std::string qualityPassesCsv(const QualityReport& r) {
    std::string out = r.complete() ? std::string() : "# " + r.incompleteNote() + "\n";
    out += "name,pass,gpu_ms,cpu_ms,copies\n";
    for (const QualityRun& run : r.runs)
        for (const PassSummary& p : run.passes)
            out += run.name + "," + p.name + "," + fmt("%.4f", p.gpu_ms) + "," + fmt("%.4f", p.cpu_ms) + "," +
                   fmt("%.3f", run.copy_ms > 0 ? p.gpu_ms / run.copy_ms : 0.0) + "\n";
    return out;
}

std::string qualityMarkdown(const QualityReport& r, bool chart_has_labels) {
    std::string md = "# vista quality\n\n";
    if (!r.complete()) md += "> **" + r.incompleteNote() + "**\n\n";
    md += "Scene `" + r.scene + "`, camera path `" + r.path + "`, " + std::to_string(r.frames) + " frame(s) at " +
          std::to_string(r.width) + "x" + std::to_string(r.height) + " after " + std::to_string(r.warmup) +
          " warm-up frame(s); " + r.renderer + " (" + r.backend + ", " + r.gpu_timer + " timer).\n\n";
    md += "Every run renders the same frames as the reference (preset `reference`: every knob at its maximum, the "
          "terrain at full resolution). Final image: PSNR over sRGB R, G, B (peak 1), SSIM (Wang et al. 2004, Gaussian "
          "11x11, sigma 1.5, K1 0.01, K2 0.03) on sRGB luma, max error in 8-bit levels. HDR (the scene's linear target "
          "before the post chain): on log2 luminance with the reference's range (" +
          fmt("%.1f", r.hdr_range.range) +
          " stops) as the peak; max error in stops. GPU ms: median frame time; copies: that over a full-screen RGBA16F "
          "copy measured before the run. Pareto: on the front of final-image PSNR against GPU ms over all runs; gap: dB "
          "below the best run that costs no more.\n\n";
    md += "## Presets\n\n| preset | " + std::string(kMetricHeader) + "\n|---|" + kMetricRule + "\n";
    for (const QualityRun& run : r.runs)
        if (run.kind == "preset" || run.kind == "scene") md += "| " + run.name + " | " + metricCells(run) + "\n";

    const TemporalQualityOptions& to = r.temporal;
    md += "\n## Temporal error\n\n1-frame: LDR PSNR of the first measured frame (after the warm-up frames, as a "
          "capture's first frame after its settle frames) against a converged, supersampled reference of that frame: the "
          "reference's settings with its exposure, the mean of " + std::to_string(to.converge_frames) +
          " history-free frames (TAA and temporal clouds off, a different blue-noise index each) at " +
          std::to_string(to.supersample) + "x the size, averaged in linear light. Converged: the same after " +
          std::to_string(to.cut_frames) + " frames of a still camera following a camera cut. Flicker: mean and 99th "
          "percentile of the per-pixel luma change (8-bit levels) between consecutive measured frames after "
          "reprojecting the previous frame by depth (occluded and off-screen pixels left out); x reference: over the "
          "reference run's (the reference sequence). Ghost: frames after a cut (from " + std::to_string(to.settle_frames) +
          " frames of the view turned 180 degrees; 0 is the cut frame) until the image stays within 1 dB of its converged "
          "PSNR.\n\n| run | 1-frame dB | converged dB | flicker mean | flicker p99 | x reference | ghost frames | copies |\n"
          "|---|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const QualityRun& run : r.runs) {
        const TemporalFigures& t = run.temporal;
        md += "| " + run.name + " | " + formatDb(t.single_psnr_db) + " | " + formatDb(t.converged_psnr_db) + " | " +
              fmt("%.2f", t.flicker.mean) + " | " + fmt("%.1f", t.flicker.p99) + " | " + fmt("%.2f", flickerRatio(r, run)) +
              " | " + (t.ghost_frames < 0 ? std::string("-") : std::to_string(t.ghost_frames)) + " | " +
              fmt("%.1f", run.copies()) + " |\n";
    }

    // Per-pass times of the presets.
    std::vector<const QualityRun*> presets;
    std::vector<std::string> passes;
    for (const QualityRun& run : r.runs)
        if (run.kind == "preset" || run.kind == "scene") {
            presets.push_back(&run);
            for (const PassSummary& p : run.passes)
                if (std::find(passes.begin(), passes.end(), p.name) == passes.end()) passes.push_back(p.name);
        }
    md += "\n## Per-pass GPU ms of the presets\n\n| pass |";
    for (const QualityRun* p : presets) md += " " + p->name + " |";
    md += "\n|---|";
    for (std::size_t i = 0; i < presets.size(); ++i) md += "---:|";
    md += "\n";
    for (const std::string& name : passes) {
        md += "| " + name + " |";
        for (const QualityRun* p : presets) {
            auto it = std::find_if(p->passes.begin(), p->passes.end(), [&](const PassSummary& s) { return s.name == name; });
            md += it != p->passes.end() ? fmt(" %.2f |", it->gpu_ms) : std::string(" |");
        }
        md += "\n";
    }

    md += "\n## Knobs (each changes one setting from the reference)\n";
    const QualityRun* reference = findRun(r, "reference");
    for (const std::string& knob : r.knob_order) {
        if (std::none_of(r.runs.begin(), r.runs.end(), [&](const QualityRun& run) { return run.knob == knob; })) continue;
        md += "\n### " + knob + "\n\n| value | " + std::string(kMetricHeader) + "\n|---|" + kMetricRule + "\n";
        for (const QualityRun& run : r.runs)
            if (run.kind == "knob" && run.knob == knob) md += "| " + run.value + " | " + metricCells(run) + "\n";
        if (reference) md += "| reference | " + metricCells(*reference) + "\n";
    }
    if (!r.inactive_knobs.empty()) {
        md += "\nNot swept (their feature is off in this scene, so they change nothing):";
        for (const std::string& k : r.inactive_knobs) md += " `" + k + "`";
        md += ".\n";
    }
    md += "\n## Chart\n\n![PSNR against GPU ms](quality.png)\n\nquality.png: final-image PSNR (dB) against median GPU "
          "frame ms (log scale); grey squares are knob runs, coloured squares the presets, the black polyline the Pareto "
          "front; infinite PSNR (the reference) sits on the top edge.";
    if (!chart_has_labels) md += " No font was found, so the chart has no text; the runs are the tables above.";
    md += "\n";
    return md;
}

namespace {

struct Axes {
    int x0, y0, x1, y1;  // plot area, pixels (y0 top)
    double lx0, lx1;     // log10 ms at x0, x1
    double db0, db1;     // PSNR at y1 (bottom), y0 (top)
    int x(double ms) const { return x0 + int(std::lround((std::log10(ms) - lx0) / (lx1 - lx0) * (x1 - x0))); }
    int y(double db) const {
        if (std::isinf(db)) return y0 + 6;
        return y1 - int(std::lround((std::min(db, db1) - db0) / (db1 - db0) * (y1 - y0 - 14)));
    }
};

constexpr std::array<std::array<float, 3>, 5> kPresetColors{{
    {0.15f, 0.35f, 0.85f}, {0.1f, 0.6f, 0.2f}, {0.95f, 0.55f, 0.0f}, {0.85f, 0.1f, 0.1f}, {0.55f, 0.2f, 0.7f}}};


}  // namespace

std::string writeQualityChart(const std::filesystem::path& file, const QualityReport& r, bool& labels) {
    namespace IBA = OIIO::ImageBufAlgo;
    const int w = 960, h = 600;
    OIIO::ImageBuf img(OIIO::ImageSpec(w, h, 3, OIIO::TypeDesc::FLOAT));
    const float white[3] = {1, 1, 1}, black[3] = {0, 0, 0}, grid[3] = {0.88f, 0.88f, 0.88f}, grey[3] = {0.55f, 0.55f, 0.55f};
    IBA::fill(img, white);

    double ms_lo = 1e300, ms_hi = 0.0, db_lo = 1e300, db_hi = -1e300;
    for (const QualityRun& run : r.runs) {
        const double ms = std::max(run.gpu_ms, 1e-3);
        ms_lo = std::min(ms_lo, ms);
        ms_hi = std::max(ms_hi, ms);
        if (std::isfinite(run.ldr.psnr_db)) {
            db_lo = std::min(db_lo, run.ldr.psnr_db);
            db_hi = std::max(db_hi, run.ldr.psnr_db);
        }
    }
    if (ms_hi <= 0.0) ms_lo = ms_hi = 1.0;
    if (db_lo > db_hi) db_lo = db_hi = 40.0;
    Axes ax{80, 50, w - 30, h - 70, std::floor(std::log10(ms_lo) * 4.0) / 4.0, std::ceil(std::log10(ms_hi) * 4.0) / 4.0,
            std::floor(db_lo / 5.0) * 5.0, std::ceil(db_hi / 5.0) * 5.0};
    if (ax.lx1 - ax.lx0 < 0.5) ax.lx1 = ax.lx0 + 0.5;
    if (ax.db1 - ax.db0 < 5.0) ax.db1 = ax.db0 + 5.0;

    const std::string font = chartFontFile();
    labels = true;
    auto text = [&](int x, int y, const std::string& s, int size, const float* color, OIIO::ImageBufAlgo::TextAlignX ax_ =
                                                                                       OIIO::ImageBufAlgo::TextAlignX::Left) {
        if (labels && !IBA::render_text(img, x, y, s, size, font, OIIO::cspan<float>(color, 3), ax_)) labels = false;
    };

    // Grid, ticks and labels: x at 1-2-5 per decade, y every 5 dB.
    for (int decade = int(std::floor(ax.lx0)); decade <= int(std::ceil(ax.lx1)); ++decade)
        for (double m : {1.0, 2.0, 5.0}) {
            const double ms = m * std::pow(10.0, decade), l = std::log10(ms);
            if (l < ax.lx0 - 1e-9 || l > ax.lx1 + 1e-9) continue;
            const int x = ax.x(ms);
            IBA::render_line(img, x, ax.y0, x, ax.y1, grid);
            text(x, ax.y1 + 18, fmt(ms < 1.0 ? "%.2g" : "%.0f", ms), 13, black, IBA::TextAlignX::Center);
        }
    for (double db = ax.db0; db <= ax.db1 + 1e-9; db += 5.0) {
        const int y = ax.y(db);
        IBA::render_line(img, ax.x0, y, ax.x1, y, grid);
        text(ax.x0 - 8, y + 5, fmt("%.0f", db), 13, black, IBA::TextAlignX::Right);
    }
    text(ax.x0 - 8, ax.y(INFINITY) + 5, "inf", 13, black, IBA::TextAlignX::Right);
    IBA::render_box(img, ax.x0, ax.y0, ax.x1, ax.y1, black);
    text((ax.x0 + ax.x1) / 2, h - 25, "median GPU frame ms (log scale)", 15, black, IBA::TextAlignX::Center);
    text(10, ax.y0 - 14, "PSNR dB", 15, black);
    text(ax.x0 + 60, 24,
         "vista quality: final image PSNR against GPU time, " + std::to_string(r.width) + "x" + std::to_string(r.height) +
             ", " + std::to_string(r.frames) + " frame(s), " + r.renderer,
         15, black);
    if (!r.complete()) {
        static const float red[3] = {0.8f, 0.0f, 0.0f};
        text(ax.x0 + 60, 44, r.incompleteNote(), 15, red);
    }

    // Knob runs, the front, then the presets on top.
    for (const QualityRun& run : r.runs)
        if (run.kind == "knob") {
            const int x = ax.x(std::max(run.gpu_ms, 1e-3)), y = ax.y(run.ldr.psnr_db);
            IBA::render_box(img, x - 2, y - 2, x + 2, y + 2, grey, true);
        }
    std::vector<const QualityRun*> front;
    for (const QualityRun& run : r.runs)
        if (run.pareto) front.push_back(&run);
    std::sort(front.begin(), front.end(), [](const QualityRun* a, const QualityRun* b) { return a->gpu_ms < b->gpu_ms; });
    for (std::size_t i = 1; i < front.size(); ++i)
        IBA::render_line(img, ax.x(std::max(front[i - 1]->gpu_ms, 1e-3)), ax.y(front[i - 1]->ldr.psnr_db),
                         ax.x(std::max(front[i]->gpu_ms, 1e-3)), ax.y(front[i]->ldr.psnr_db), black);
    int preset = 0;
    for (const QualityRun& run : r.runs)
        if (run.kind == "preset" || run.kind == "scene") {
            const float* color = kPresetColors[std::size_t(std::min(preset++, 4))].data();
            const int x = ax.x(std::max(run.gpu_ms, 1e-3)), y = ax.y(run.ldr.psnr_db);
            IBA::render_box(img, x - 5, y - 5, x + 5, y + 5, OIIO::cspan<float>(color, 3), true);
            IBA::render_box(img, x - 5, y - 5, x + 5, y + 5, black);
            text(x + 9, y - 7, run.name, 14, color);
        }
    text(ax.x1 - 8, ax.y1 - 10, "grey: one knob from the reference; line: Pareto front", 13, grey, IBA::TextAlignX::Right);

    // Encoded in memory and written atomically, so a full disk is a reported error.
    std::vector<unsigned char> bytes;
    OIIO::Filesystem::IOVecOutput memory(bytes);
    auto out = OIIO::ImageOutput::create("png");
    if (!out) return file.string() + ": OpenImageIO has no png writer (" + OIIO::geterror() + ")";
    out->set_ioproxy(&memory);
    OIIO::ImageSpec spec = img.spec();
    spec.set_format(OIIO::TypeDesc::UINT8);
    bool ok = out->open(file.string(), spec) && img.write(out.get());
    ok = out->close() && ok;
    if (!ok) return file.string() + ": " + (out->geterror().empty() ? img.geterror() : out->geterror());
    return writeFileAtomic(file, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()), true);
}

std::string writeQualityReport(const std::filesystem::path& dir, const QualityReport& r) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) return dir.string() + ": cannot create output directory (" + ec.message() + ")";
    bool labels = false;
    // The report files are replaced on purpose (--out's help says so): force.
    for (std::string problem : {writeFileAtomic(dir / "quality.csv", qualityCsv(r), true),
                                writeFileAtomic(dir / "quality_passes.csv", qualityPassesCsv(r), true),
                                writeQualityChart(dir / "quality.png", r, labels),
                                writeFileAtomic(dir / "quality.md", qualityMarkdown(r, labels), true)})
        if (!problem.empty()) return problem;
    return {};
}

}  // namespace vista
