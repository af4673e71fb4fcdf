// Lights over the sea (app/light_placement.h): `ground H` is measured from the water's surface
// where the sea covers the terrain, and `vista check`'s warnings for lights under water or
// inside the terrain name the key's file and line.
#include "app/light_placement.h"
#include "app/scene.h"
#include "app/scene_check.h"
#include "config/ini.h"
#include "terrain/terrain.h"

#include <doctest/doctest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

using namespace vista;

namespace {

// A slope: terrain at y = x / 10 (sea floor for x < 0, land for x > 0).
double slope(double x, double) { return x / 10.0; }

}  // namespace

TEST_CASE("light placement: ground is the water's surface where the sea covers the terrain") {
    WaterSettings water;
    water.enabled = true;
    water.level_m = 1.0f;
    const GroundHeight ground = lightGround(slope, water);
    CHECK(ground(-100.0, 0.0) == doctest::Approx(1.0));  // sea floor at -10: the surface
    CHECK(ground(50.0, 0.0) == doctest::Approx(5.0));    // land above the sea: the terrain
    water.enabled = false;
    CHECK(lightGround(slope, water)(-100.0, 0.0) == doctest::Approx(-10.0));
    CHECK(!lightGround(GroundHeight{}, water));

    // A volume of lamps `ground 2.5` across the shore: each 2.5 m above the water or the land.
    water.enabled = true;
    LightsSettings lights;
    LightVolume v;
    v.min_m = {-200.0, 0.0, 0.0};
    v.max_m = {200.0, 0.0, 0.0};
    v.count = {20, 1, 1};
    v.ground_m = 2.5f;
    lights.volumes.push_back({"shore", v});
    for (const Light& l : collectSceneLights(lights, lightGround(slope, water), 1.0))
        CHECK(l.position.y == doctest::Approx(std::max(l.position.x / 10.0, 1.0) + 2.5));
}

TEST_CASE("light placement: check warns about lights under water or inside the terrain, naming the line") {
    const std::filesystem::path file =
        std::filesystem::temp_directory_path() / ("vista-light-placement-" + std::to_string(::getpid()) + ".ini");
    std::ofstream(file) << "[water]\nenabled = true\nlevel_m = 0\n[lights]\n"
                           "light.ok = point 50 9 0 radius 5\n"
                           "light.buried = point 50 2 0 radius 5\n"
                           "light.drowned = point -50 -1 0 radius 5\n"
                           "light.placed = point -50 -100 0 radius 5 ground 1\n"
                           "volume.sunk = box -300 -2 0 -100 -2 0 count 4 1 1 radius 5\n"
                           "volume.floating = box -300 0 0 -100 0 0 count 4 1 1 radius 5 ground 2\n";
    Settings s;
    const InputErrors errors = loadScene(file, {}, s);
    REQUIRE(errors.empty());
    const InputErrors w = checkLightPlacement(s, slope, {file}, {});
    REQUIRE(w.size() == 3);
    CHECK(w[0].line == 6);
    CHECK(w[0].message.find("light.buried") != std::string::npos);
    CHECK(w[0].message.find("inside the terrain") != std::string::npos);
    CHECK(w[1].line == 7);
    CHECK(w[1].message.find("light.drowned") != std::string::npos);
    CHECK(w[1].message.find("under the water") != std::string::npos);
    CHECK(w[2].line == 9);
    CHECK(w[2].message.find("volume.sunk: 0 of 4 lights inside the terrain and 4 under the water") != std::string::npos);
    CHECK(w[0].str().starts_with(file.string() + ":6: "));
    // An override is located at --set.
    const InputErrors o = checkLightPlacement(s, slope, {file}, {"lights.light.buried=point 50 2 0 radius 5"});
    CHECK(o[0].file == "--set");
    std::filesystem::remove(file);
}

TEST_CASE("light placement: the default scene's lamps stand above the sea and check finds no misplaced light") {
    Settings s;
    REQUIRE(loadScene(defaultScenePath(), {}, s).empty());
    CheckedTerrain checked;
    REQUIRE(validateSceneInputs(s, &checked).empty());
    REQUIRE(!checked.map.samples.empty());
    const GroundHeight terrain = [&checked, origin = s.terrain.origin](double x, double z) {
        return terrainHeightAt(checked.map, checked.mapping, origin, x, z);
    };
    CHECK(checkLightPlacement(s, terrain, {defaultScenePath()}, {}).empty());
    // The shore path runs along the waterline: some of its 40 lamps are over the sea, and
    // every one stands its 2.5 m above the water or the land.
    int over_sea = 0;
    LightsSettings shore;
    for (const NamedLightVolume& v : s.lights.volumes)
        if (v.name == "shore_path") shore.volumes.push_back(v);
    REQUIRE(shore.volumes.size() == 1);
    for (const Light& l : collectSceneLights(shore, lightGround(terrain, s.water), 1.0)) {
        const double floor = terrain(l.position.x, l.position.z);
        over_sea += floor < s.water.level_m;
        CHECK(l.position.y >= std::max(floor, double(s.water.level_m)) + 2.5 - 1e-6);
    }
    CHECK(over_sea > 0);
}
