// Stats aggregation: medians, costs in copies, the JSON layout of DESIGN.md.
#include "app/stats.h"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

using namespace vista;

TEST_CASE("stats: medians and costs in reference copies") {
    CHECK(median({}) == 0.0);
    CHECK(median({3.0, 1.0, 2.0}) == 2.0);
    CHECK(median({4.0, 1.0, 3.0, 2.0}) == 2.5);

    RunStats stats;
    stats.reference_copy_ms = 0.5;
    for (std::uint64_t i = 0; i < 3; ++i) {
        stats.addFrame(i, 1.0 + double(i));
        stats.addCounter(i, "nonfinite_pixels", 0);
    }
    std::vector<FrameTiming> timings;
    for (std::uint64_t i = 0; i < 3; ++i)
        timings.push_back(FrameTiming{i, {{"a", 1.0 + double(i), 0.1}, {"b", 2.0, 0.2}}, 3.0 + double(i)});
    timings.push_back(FrameTiming{99, {{"a", 50.0, 0.0}}, 50.0});  // not a recorded frame (warm-up)
    stats.addTimings(timings);
    auto summary = stats.passSummary();
    REQUIRE(summary.size() == 2);
    CHECK(summary[0].name == "a");
    CHECK(summary[0].gpu_ms == 2.0);
    CHECK(summary[0].copies == 4.0);
    CHECK(summary[1].cpu_ms == doctest::Approx(0.2));
    CHECK(stats.gpuMedian() == 4.0);
    CHECK(stats.cpuMedian() == 2.0);
    CHECK(stats.table().find("frame (median)") != std::string::npos);
}

TEST_CASE("stats: the JSON has every field of the contract") {
    RunStats stats;
    stats.renderer = "llvmpipe";
    stats.backend = "osmesa";
    stats.width = 320;
    stats.height = 180;
    stats.executed = {"frame.clear", "postfx.tonemap"};
    stats.culled = {"debug.view"};
    stats.reference_copy_ms = 0.2;
    stats.addFrame(0, 2.0);
    stats.addCounter(0, "nonfinite_pixels", 0);
    stats.addTimings({FrameTiming{0, {{"frame.clear", 0.1, 0.01}}, 0.1}});
    auto j = nlohmann::json::parse(stats.json());
    for (const char* key : {"renderer", "backend", "size", "passes_executed", "passes_culled", "reference_copy_ms",
                            "frames", "summary"})
        CHECK_MESSAGE(j.contains(key), key);
    CHECK(j["size"][0] == 320);
    CHECK(j["passes_culled"][0] == "debug.view");
    auto& f = j["frames"][0];
    CHECK(f["index"] == 0);
    CHECK(f["passes"]["frame.clear"]["gpu_ms"] == 0.1);
    CHECK(f["counters"]["nonfinite_pixels"] == 0);
    CHECK(j["summary"]["gpu_ms_median"] == 0.1);
}
