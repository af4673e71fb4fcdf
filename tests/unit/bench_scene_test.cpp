// Bench isolation: every feature outside the kept sections is off, whatever sections exist.
#include "app/bench_scene.h"

#include <doctest/doctest.h>

#include <algorithm>

using namespace vista;

TEST_CASE("bench scene: only the kept sections (and their sub-sections) stay enabled") {
    Settings s;
    s.water.enabled = true;
    s.weather.enabled = true;
    s.dof.enabled = true;
    BenchScene b = isolateBenchScene("sky", s, {"sky", "clouds"}, {"debug.grid=false"}, {});
    for (const std::string& section : enabledSections(b.settings)) {
        CAPTURE(section);
        CHECK((section == "sky" || section.rfind("clouds", 0) == 0));
    }
    CHECK(b.settings.clouds.low.enabled);  // [clouds.low] is under the kept [clouds]
    CHECK_FALSE(b.settings.water.enabled);
    CHECK_FALSE(b.settings.dof.enabled);
    CHECK(std::find(b.disabled.begin(), b.disabled.end(), "postfx.dof.enabled=false") != b.disabled.end());
    CHECK_FALSE(b.settings.debug.grid);
    CHECK(b.summary().find("water.enabled=false") != std::string::npos);
}

TEST_CASE("bench scene: the user's --set wins over the isolation") {
    Settings s;
    s.water.enabled = true;
    BenchScene b = isolateBenchScene("sky", s, {"sky"}, {}, {"water.enabled=true", "sky.sun_elevation_deg=5"});
    CHECK(b.settings.water.enabled);
    CHECK(b.settings.sky.sun_elevation_deg == 5.0f);
    CHECK(std::find(b.disabled.begin(), b.disabled.end(), "water.enabled=false") == b.disabled.end());
}

TEST_CASE("bench scene: every bench keeps sections that exist") {
    const std::vector<std::string> all = enabledSections(Settings{});
    for (const char* bench : {"sky", "shadows", "grass", "terrain", "lights"}) {
        CAPTURE(bench);
        const std::vector<std::string> keep = benchKeptSections(bench);
        CHECK_FALSE(keep.empty());
        for (const std::string& k : keep) CHECK(std::find(all.begin(), all.end(), k) != all.end());
    }
}
