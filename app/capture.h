// Headless rendering of a camera path to numbered images, with optional stats; also the
// engine of `vista bench frame` (same frames, no images written).
#pragma once

#include "app/gl_context.h"
#include "app/shard.h"
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
    FrameSelection selection;         // --frames-range / --shard: the part of the path's frames to write
    bool resume = false;              // keep the frames whose files match this run's manifest
};

struct CaptureResult {
    int exit_code = 0;  // 0 ok, 1 runtime failure, 2 bad input
    RunStats stats;
    std::vector<std::filesystem::path> images;  // written by this run
    int kept = 0;                                // frames a resumed run found done
    int settle_frames = 0;                       // rendered, not written (every run of frames)
    std::filesystem::path manifest, video;       // empty: none written
};

// Renders the selected frames. Before the first frame of each run of consecutive written frames
// it calls FrameRenderer::resetHistory() and renders [capture] settle_frames unwritten frames at
// the path times of the frames before it (clamped to the path's start), so frame k is the same
// whichever run renders it; before a written frame the camera cuts to, [capture] cut_settle_frames
// unwritten frames at that frame's own pose and time. Writing images, it keeps the run's manifest (shard.h) up to date
// after every frame, and with [capture] format mp4 and the whole path selected, it encodes the
// video out/capture.mp4 at the end.
CaptureResult runCapture(const CaptureJob& job);

// The frame-k path time: the start plus k / fps, with k clamped to 0 (settle frames before the
// start).
double captureFrameTime(double start_s, int frame, double fps);

// Creates dir if needed and checks it is a writable directory: "" or the reason.
std::string checkWritableDir(const std::filesystem::path& dir);

// Checks --stats and --dot before rendering: each is a file name in a writable folder, not
// existing without force, and none names another output, a frame or an input. "" or why.
std::string checkCaptureOutputs(const CaptureJob& job);

// The image file for frame i: out/frame_0000.png.
std::filesystem::path captureFileName(const std::filesystem::path& out, int frame, ImageFormat format);

}  // namespace vista
