// One optional feature of the frame (the sea, the clouds, the spot atlas ...): made by the first
// frame that uses it, released with every GPU object it holds by the first frame that does not,
// and reported under one memory counter. A feature that is off costs no pass and no memory.
#pragma once

#include "renderer/gl_device.h"

#include <cstddef>
#include <memory>
#include <utility>

namespace vista {

template <class T>
class FeatureSlot {
public:
    // memory_counter: the stats key of its GPU bytes ("water.memory_bytes"); null when an owner
    // reports them with something else (TAA's go into postfx.memory_bytes).
    explicit FeatureSlot(const char* memory_counter) : memory_counter_(memory_counter) {}

    // The feature this frame, default-made on first use.
    T& use() {
        used_ = true;
        if (!feature_) feature_ = std::make_unique<T>();
        return *feature_;
    }
    // At the end of a frame: drops the feature unless use() asked for it since the last call.
    void releaseUnused() {
        if (!used_) feature_.reset();
        used_ = false;
    }
    // A feature made elsewhere (a loaded terrain); null releases.
    void adopt(std::unique_ptr<T> feature) { feature_ = std::move(feature); }
    std::unique_ptr<T> take() { return std::move(feature_); }

    // Off this frame: drops the feature. GPU objects it borrowed from the device's pool
    // (T::release(GlDevice&), e.g. history targets) go back first.
    void release(GlDevice& device) {
        if (!feature_) return;
        if constexpr (requires(T& t) { t.release(device); }) feature_->release(device);
        feature_.reset();
    }
    // For features that borrow nothing from the device's pool.
    void release() { feature_.reset(); }

    T* get() const { return feature_.get(); }
    T* operator->() const { return feature_.get(); }
    T& operator*() const { return *feature_; }
    explicit operator bool() const { return bool(feature_); }

    const char* memoryCounter() const { return memory_counter_; }
    // GPU bytes held (0 while off): gpuMemoryBytes() where a feature also holds CPU memory.
    std::size_t memoryBytes() const {
        if (!feature_) return 0;
        if constexpr (requires(const T& t) { t.gpuMemoryBytes(); })
            return feature_->gpuMemoryBytes();
        else
            return feature_->memoryBytes();
    }

private:
    std::unique_ptr<T> feature_;
    const char* memory_counter_;
    bool used_ = false;  // use() called since the last releaseUnused()
};

}  // namespace vista
