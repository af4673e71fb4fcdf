// Run statistics for `vista capture --stats` and `vista bench --json` (the JSON layout in
// DESIGN.md is a contract): executed and culled passes, the reference copy, per-frame
// per-pass GPU/CPU times and counters, and medians.
#pragma once

#include "config/file_io.h"  // writeFileAtomic

#include "renderer/pass_timers.h"

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace vista {

struct FrameStats {
    std::uint64_t index = 0;
    double cpu_ms = 0.0;
    double gpu_ms = 0.0;
    std::vector<PassTiming> passes;
    std::map<std::string, double> counters;
};

struct PassSummary {
    std::string name;
    double gpu_ms = 0.0;  // median over frames
    double cpu_ms = 0.0;  // median over frames
    double copies = 0.0;  // gpu_ms / reference_copy_ms
};

class RunStats {
public:
    std::string renderer, backend;
    std::string gpu_timer = "query";  // "query" (GL timer queries) or "finish" (software GL)
    int width = 0, height = 0;
    std::vector<std::string> executed, culled;
    double reference_copy_ms = 0.0;

    // A frame's CPU time and the counters known right away.
    void addFrame(std::uint64_t index, double cpu_ms);
    // A counter of a frame added with addFrame(); those of other frames (warm-up frames whose
    // readback arrives late) are dropped.
    void addCounter(std::uint64_t index, const std::string& name, double value);
    // GPU results that arrived (frames later).
    void addTimings(const std::vector<FrameTiming>& timings);

    const std::map<std::uint64_t, FrameStats>& frames() const { return frames_; }
    std::vector<PassSummary> passSummary() const;  // in execution order
    double gpuMedian() const;
    double cpuMedian() const;

    std::string json() const;
    // Aligned text table: pass, GPU ms, CPU ms, copies.
    std::string table() const;

private:
    std::map<std::uint64_t, FrameStats> frames_;
};

double median(std::vector<double> values);

// Prints "vista: message" to stderr and returns code (the command's exit code).
int fail(int code, const std::string& message);
// A bench's --json output: writes text to file unless file is empty; 0, or 1 after saying why.
// force (--force): replace an existing file; the CLI refused one before the bench ran.
int writeBenchJson(const std::filesystem::path& file, const std::string& text, bool force);
// GPU ms of the pass called name in a frame's timings (0 when it did not run).
double passMs(const FrameTiming& t, const std::string& name);

}  // namespace vista
