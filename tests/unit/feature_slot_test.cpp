// FeatureSlot: a feature exists only while a frame uses it, and its memory counts only then.
#include "renderer/feature_slot.h"

#include <doctest/doctest.h>

using namespace vista;

namespace {

struct Probe {
    static inline int alive = 0;
    static inline int released = 0;
    Probe() { ++alive; }
    ~Probe() { --alive; }
    std::size_t memoryBytes() const { return 64; }
    void release(GlDevice&) { ++released; }
};

struct WithCpuMemory {
    std::size_t memoryBytes() const { return 1000; }    // CPU and GPU
    std::size_t gpuMemoryBytes() const { return 10; }   // of that, on the GPU
};

}  // namespace

TEST_CASE("feature slot: made on first use, dropped by the first frame that does not use it") {
    Probe::alive = 0;
    FeatureSlot<Probe> slot("probe.memory_bytes");
    CHECK(!slot);
    CHECK(slot.memoryBytes() == 0);
    Probe* first = &slot.use();
    CHECK(Probe::alive == 1);
    CHECK(&slot.use() == first);  // one feature across uses
    CHECK(slot.memoryBytes() == 64);
    slot.releaseUnused();  // used this frame: kept
    CHECK(Probe::alive == 1);
    slot.releaseUnused();  // not used since: dropped
    CHECK(Probe::alive == 0);
    CHECK(slot.memoryBytes() == 0);
    CHECK(std::string(slot.memoryCounter()) == "probe.memory_bytes");
}

TEST_CASE("feature slot: release gives pooled GPU objects back before dropping the feature") {
    Probe::alive = 0;
    Probe::released = 0;
    GlDevice device;  // no GL call without textures
    FeatureSlot<Probe> slot(nullptr);
    slot.release(device);  // nothing there: nothing to give back
    CHECK(Probe::released == 0);
    slot.use();
    slot.release(device);
    CHECK(Probe::released == 1);
    CHECK(Probe::alive == 0);
    CHECK(!slot);
}

TEST_CASE("feature slot: a feature with CPU memory reports its GPU bytes") {
    FeatureSlot<WithCpuMemory> slot("terrain.memory_bytes");
    slot.use();
    CHECK(slot.memoryBytes() == 10);
    slot.adopt(nullptr);
    CHECK(slot.memoryBytes() == 0);
}
