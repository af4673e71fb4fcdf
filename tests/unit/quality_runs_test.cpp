// The runs `vista quality` plans (app/quality.h): the reference, the presets, the knob sweeps,
// and the command line's --set holding in every one of them.
#include "app/quality.h"

#include <doctest/doctest.h>

#include <algorithm>

using namespace vista;

namespace {

const QualityRunSpec& run(const std::vector<QualityRunSpec>& runs, const std::string& name) {
    const auto it = std::find_if(runs.begin(), runs.end(), [&](const QualityRunSpec& r) { return r.name == name; });
    REQUIRE_MESSAGE(it != runs.end(), "no run " << name);
    return *it;
}

}  // namespace

TEST_CASE("quality: --set holds over every preset, and a swept knob still sets its own key") {
    QualityOptions o;
    o.all_knobs = false;
    o.knobs = {"terrain.pom.max_steps", "terrain.tessellation.max_factor"};
    std::vector<std::string> inactive, order;

    // Without --set the reference tessellates (so its 80 m hide POM's 40 m from the POM knob).
    std::vector<QualityRunSpec> runs = qualityRuns(o, inactive, order);
    CHECK(runs.front().name == "reference");
    CHECK(runs.front().settings.terrain.tessellation.enabled);
    CHECK(order == o.knobs);

    // Pinned off: every preset and the POM sweep run without tessellation; the tessellation
    // sweep still turns it on at its own levels.
    o.pinned = {"terrain.tessellation.enabled=false"};
    order.clear();
    runs = qualityRuns(o, inactive, order);
    for (const char* name : {"reference", "low", "medium", "high", "ultra", "terrain.pom.max_steps=off", "terrain.pom.max_steps=24"}) {
        CAPTURE(name);
        CHECK_FALSE(run(runs, name).settings.terrain.tessellation.enabled);
    }
    CHECK(run(runs, "reference").settings.terrain.pom.enabled);
    CHECK(run(runs, "reference").settings.terrain.pom.max_steps == 128);
    CHECK(run(runs, "terrain.pom.max_steps=24").settings.terrain.pom.max_steps == 24);
    CHECK_FALSE(run(runs, "terrain.pom.max_steps=off").settings.terrain.pom.enabled);
    CHECK(run(runs, "terrain.tessellation.max_factor=8").settings.terrain.tessellation.enabled);
    CHECK(inactive.empty());
}
