// Deferred GPU timer and counter readback.
#include "renderer/pass_timers.h"

namespace vista {

TimerMode timerModeFor(const std::string& gl_renderer) {
    for (const char* software : {"llvmpipe", "softpipe", "SwiftShader", "Software Rasterizer"})
        if (gl_renderer.find(software) != std::string::npos) return TimerMode::Finish;
    return TimerMode::Queries;
}

const char* timerModeName(TimerMode mode) { return mode == TimerMode::Finish ? "finish" : "query"; }

gl::Query PassTimers::takeQuery() {
    if (spare_.empty()) return gl::createQuery(GL_TIME_ELAPSED);
    gl::Query q = std::move(spare_.back());
    spare_.pop_back();
    return q;
}

void PassTimers::beginFrame(std::uint64_t frame) {
    current_ = Pending{};
    current_.timing.frame = frame;
}

void PassTimers::beginPass(const std::string& name) {
    glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, GLsizei(name.size()), name.c_str());
    current_.timing.passes.push_back(PassTiming{name, 0.0, 0.0});
    if (mode_ == TimerMode::Finish) {
        glFinish();  // earlier passes' work must not be billed to this one
        gpu_start_ = std::chrono::steady_clock::now();
    } else {
        gl::Query q = takeQuery();
        glBeginQuery(GL_TIME_ELAPSED, q.id());
        current_.queries.push_back(std::move(q));
    }
    pass_start_ = std::chrono::steady_clock::now();
}

void PassTimers::endPass(const std::string&) {
    using ms = std::chrono::duration<double, std::milli>;
    PassTiming& timing = current_.timing.passes.back();
    timing.cpu_ms = ms(std::chrono::steady_clock::now() - pass_start_).count();
    if (mode_ == TimerMode::Finish) {
        glFinish();
        timing.gpu_ms = ms(std::chrono::steady_clock::now() - gpu_start_).count();
        current_.timing.gpu_ms += timing.gpu_ms;
    } else {
        glEndQuery(GL_TIME_ELAPSED);
    }
    glPopDebugGroup();
}

void PassTimers::endFrame() { pending_.push_back(std::move(current_)); }

std::vector<FrameTiming> PassTimers::collect(bool wait) {
    std::vector<FrameTiming> done;
    while (!pending_.empty()) {
        Pending& p = pending_.front();
        if (!wait && !p.queries.empty()) {  // Finish mode has no queries: complete at once
            GLint available = 0;
            glGetQueryObjectiv(p.queries.back().id(), GL_QUERY_RESULT_AVAILABLE, &available);
            if (!available) break;  // results arrive in order: later frames are not ready either
        }
        for (std::size_t i = 0; i < p.queries.size(); ++i) {
            GLuint64 ns = 0;
            glGetQueryObjectui64v(p.queries[i].id(), GL_QUERY_RESULT, &ns);
            p.timing.passes[i].gpu_ms = double(ns) * 1e-6;
            p.timing.gpu_ms += p.timing.passes[i].gpu_ms;
            spare_.push_back(std::move(p.queries[i]));
        }
        done.push_back(std::move(p.timing));
        pending_.pop_front();
    }
    return done;
}

GLuint CounterReadback::request(std::uint64_t frame, const std::string& name) {
    gl::Buffer buffer;
    if (spare_.empty()) {
        buffer = gl::Buffer::create(2 * sizeof(GLuint), nullptr, GL_DYNAMIC_STORAGE_BIT, "counter " + name);
    } else {
        buffer = std::move(spare_.back());
        spare_.pop_back();
    }
    GLuint zero[2] = {0, 0};
    glNamedBufferSubData(buffer.id(), 0, sizeof zero, zero);
    GLuint id = buffer.id();
    pending_.push_back(Pending{frame, name, std::move(buffer), nullptr});
    return id;
}

void CounterReadback::endFrame() {
    GLsync fence = nullptr;
    for (auto& p : pending_)
        if (!p.fence) {
            if (!fence) fence = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
            p.fence = fence;
        }
}

std::size_t CounterReadback::memoryBytes() const {
    std::size_t bytes = 0;
    for (const Pending& p : pending_) bytes += std::size_t(p.buffer.size());
    for (const gl::Buffer& b : spare_) bytes += std::size_t(b.size());
    return bytes;
}

std::vector<CounterReadback::Value> CounterReadback::collect(bool wait) {
    std::vector<Value> done;
    while (!pending_.empty() && pending_.front().fence) {
        Pending& p = pending_.front();
        GLenum status = glClientWaitSync(p.fence, GL_SYNC_FLUSH_COMMANDS_BIT, wait ? GLuint64(10'000'000'000) : 0);
        if (status == GL_TIMEOUT_EXPIRED) break;
        GLuint words[2] = {0, 0};
        glGetNamedBufferSubData(p.buffer.id(), 0, sizeof words, words);
        done.push_back(Value{p.frame, p.name, std::uint64_t(words[0]) | std::uint64_t(words[1]) << 32});
        GLsync fence = p.fence;
        spare_.push_back(std::move(p.buffer));
        pending_.pop_front();
        // Several requests share a fence: delete it with the last one.
        if (pending_.empty() || pending_.front().fence != fence) glDeleteSync(fence);
    }
    return done;
}

}  // namespace vista
