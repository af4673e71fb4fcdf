// Per-pass GPU and CPU timing. Each executed pass gets a KHR_debug group, a GPU timer and
// a CPU stopwatch. On a GPU the timer is a GL_TIME_ELAPSED query read frames later, when
// available, so the CPU never waits on the GPU (except in collect(wait = true) at the end of
// a capture). Software rasterizers (llvmpipe) bin draws and rasterize them later on worker
// threads, so their queries do not cover a pass's work; there the "GPU" time is the wall
// time between glFinish() before and after the pass, which is exact because the GPU is the CPU.
#pragma once

#include "renderer/frame_graph.h"
#include "renderer/gl/objects.h"

#include <chrono>
#include <cstdint>
#include <deque>
#include <string>
#include <vector>

namespace vista {

struct PassTiming {
    std::string name;
    double gpu_ms = 0.0;
    double cpu_ms = 0.0;
};

struct FrameTiming {
    std::uint64_t frame = 0;
    std::vector<PassTiming> passes;  // in execution order
    double gpu_ms = 0.0;             // sum over passes
};

enum class TimerMode { Queries, Finish };

// Finish for software renderers (llvmpipe, softpipe, SwiftShader), Queries otherwise.
TimerMode timerModeFor(const std::string& gl_renderer);
const char* timerModeName(TimerMode mode);

class PassTimers final : public PassObserver {
public:
    explicit PassTimers(TimerMode mode = TimerMode::Queries) : mode_(mode) {}
    TimerMode mode() const { return mode_; }
    void setMode(TimerMode mode) { mode_ = mode; }

    void beginFrame(std::uint64_t frame);
    void beginPass(const std::string& name) override;
    void endPass(const std::string& name) override;
    void endFrame();

    // Frames whose every query has a result, oldest first. With wait, blocks until all
    // submitted frames are complete.
    std::vector<FrameTiming> collect(bool wait = false);

private:
    struct Pending {
        FrameTiming timing;
        std::vector<gl::Query> queries;  // one per pass
    };
    gl::Query takeQuery();

    TimerMode mode_;
    std::chrono::steady_clock::time_point gpu_start_;
    std::deque<Pending> pending_;
    Pending current_;
    std::vector<gl::Query> spare_;
    std::chrono::steady_clock::time_point pass_start_;
};

// Reads GPU-written counters (such as NaN/Inf pixels) back a few frames later without
// stalling: each request gets its own small buffer and a fence.
class CounterReadback {
public:
    struct Value {
        std::uint64_t frame;
        std::string name;
        std::uint64_t value;
    };
    // A zeroed buffer of two uints for frame's counter name, read back as the 64-bit value
    // low | high << 32: shaders add to the low word and carry into the high one
    // (renderer/shaders/counters.glsl), or use the low word alone. Write it on the GPU this frame.
    GLuint request(std::uint64_t frame, const std::string& name);
    // Call after the frame's commands are submitted.
    void endFrame();
    std::vector<Value> collect(bool wait = false);
    // GPU bytes of the pending and spare counter buffers.
    std::size_t memoryBytes() const;

private:
    struct Pending {
        std::uint64_t frame;
        std::string name;
        gl::Buffer buffer;
        GLsync fence = nullptr;
    };
    std::deque<Pending> pending_;
    std::vector<gl::Buffer> spare_;
};

}  // namespace vista
