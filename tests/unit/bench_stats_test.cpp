// What the benches report about frames: warm-up frames' late counters stay out of the stats,
// and the window's frame rate follows the frame wall time.
#include "app/frame_rate.h"
#include "app/stats.h"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

using namespace vista;

TEST_CASE("stats: a warm-up frame's late counters add no frame entry") {
    RunStats stats;
    // Frames 0 and 1 were warm-up; their counters come back while frames 2 and 3 are recorded.
    stats.addFrame(2, 10.0);
    stats.addCounter(0, "lights.evaluations", 5);
    stats.addCounter(1, "nonfinite_pixels", 0);
    stats.addCounter(2, "nonfinite_pixels", 0);
    stats.addFrame(3, 12.0);
    stats.addCounter(3, "terrain.nodes", 7);
    REQUIRE(stats.frames().size() == 2);
    CHECK(stats.frames().count(0) == 0);
    CHECK(stats.frames().at(3).counters.at("terrain.nodes") == 7.0);
    CHECK(stats.cpuMedian() == 11.0);  // not pulled down by cpu_ms 0 entries
    CHECK(nlohmann::json::parse(stats.json())["frames"].size() == 2);
}

TEST_CASE("frame rate: fps from the frame wall time, not from a clamped step") {
    FrameRateMeter meter;
    CHECK(meter.fps() == 0.0);
    meter.addFrame(0.001);  // the first, nearly empty loop iteration
    for (int i = 0; i < 3; ++i) meter.addFrame(4.940);
    CHECK(meter.fps() == doctest::Approx(1.0 / 4.94));  // the panel showed 391.2 fps here
    CHECK(meter.frameMs() == doctest::Approx(4940.0));
    FrameRateMeter fast;
    for (int i = 0; i < 200; ++i) fast.addFrame(i % 2 ? 0.008 : 0.012);
    CHECK(fast.fps() == doctest::Approx(100.0).epsilon(0.05));
}
