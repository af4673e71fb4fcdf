// Headless rendering of a camera path to numbered images, with optional stats; also the
// engine of `vista bench frame` (same frames, no images written).
#pragma once

#include "app/gl_context.h"
#include "app/stats.h"
#include "config/settings.h"

#include <filesystem>
#include <string>
#include <vector>

namespace vista {

struct CaptureJob {
    Settings settings;                // [capture] holds path, frames, fps, size, format, out
    std::filesystem::path stats_file; // empty: no stats file
    std::filesystem::path dot_file;   // empty: none; else the last frame's graph (Graphviz)
    Backend backend = Backend::OSMesa;
    bool force = false;               // overwrite existing images, stats and DOT files
    std::vector<std::filesystem::path> inputs;  // scene files: no output may name one
    bool write_images = true;         // false for benchmarks
    int warmup_frames = 0;            // rendered first, not recorded
    bool progress = true;
};

struct CaptureResult {
    int exit_code = 0;  // 0 ok, 1 runtime failure, 2 bad input
    RunStats stats;
    std::vector<std::filesystem::path> images;
};

CaptureResult runCapture(const CaptureJob& job);

// Creates dir if needed and checks it is a writable directory: "" or the reason.
std::string checkWritableDir(const std::filesystem::path& dir);

// Checks --stats and --dot before rendering: each is a file name in a writable folder, not
// existing without force, and none names another output, a frame or an input. "" or why.
std::string checkCaptureOutputs(const CaptureJob& job);

// The image file for frame i: out/frame_0000.png.
std::filesystem::path captureFileName(const std::filesystem::path& out, int frame, ImageFormat format);

}  // namespace vista
