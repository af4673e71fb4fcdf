// [objects] (terrain/scatter/object_settings.h) and scatter placement (terrain/scatter/scatter.h):
// the list keys parse, round-trip and reject bad values naming the token; placement is
// deterministic per world cell, the same after moving away and back, has the density asked
// for, and keeps the ground limits.
#include "config/ini.h"
#include "config_helpers.h"
#include "terrain/scatter/scatter.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <tuple>

using namespace vista;
using namespace vista::test;

namespace {

// Gentle hills: height 20 sin(x / 100) (slope up to 0.2), grass below 15 m.
GroundSample hills(double x, double z) {
    (void)z;
    GroundSample g;
    g.valid = std::abs(x) < 5000.0 && std::abs(z) < 5000.0;
    g.height_m = 20.0 * std::sin(x / 100.0);
    g.slope = std::abs(0.2 * std::cos(x / 100.0));
    g.grass = g.height_m < 15.0 ? 1.0 : 0.0;
    return g;
}

std::set<std::tuple<double, double, double, float, float, int>> asSet(const std::vector<PlacedObject>& v) {
    std::set<std::tuple<double, double, double, float, float, int>> s;
    for (const PlacedObject& p : v) s.insert({p.position.x, p.position.y, p.position.z, p.yaw_rad, p.scale, p.file});
    return s;
}

}  // namespace

TEST_CASE("objects config: object and scatter entries load, round-trip and name bad tokens") {
    Settings s;
    CHECK(messages(loadIniString("[objects]\nobject.mill = data/props/house.glb -10 0 20  ground 0.5  yaw 90  scale 1.5\n"
                                 "scatter.woods = data/props/tree.glb data/props/rock.glb  density 0.002  height 2 200  "
                                 "slope 0.8  grass 0.3  scale 0.7 1.3  cell 64  seed 3\n",
                                 "scene.ini", s)) == "");
    REQUIRE(s.objects.objects.size() == 1);
    REQUIRE(s.objects.scatters.size() == 1);
    const ObjectInstanceSpec& o = s.objects.objects[0].object;
    CHECK(o.file == "data/props/house.glb");
    CHECK(o.position == glm::dvec3(-10, 0, 20));
    CHECK(o.ground_m == 0.5f);
    CHECK(o.yaw_deg == 90.0f);
    CHECK(o.scale == 1.5f);
    const ScatterRule& r = s.objects.scatters[0].rule;
    CHECK(r.files == std::vector<std::string>{"data/props/tree.glb", "data/props/rock.glb"});
    CHECK(r.density == 0.002);
    CHECK(r.height_min_m == 2.0f);
    CHECK(r.slope_max == 0.8f);
    CHECK(r.grass_min == 0.3f);
    CHECK(r.scale_max == 1.3f);
    CHECK(r.seed == 3u);
    ObjectInstanceSpec o2;
    ScatterRule r2;
    CHECK(parseObjectSpec(formatObjectSpec(o), o2) == "");
    CHECK(o2 == o);
    CHECK(parseScatterSpec(formatScatterSpec(r), r2) == "");
    CHECK(r2 == r);
    CHECK(objectsWanted(s.objects));
    s.objects.enabled = false;
    CHECK(!objectsWanted(s.objects));

    Settings bad;
    CHECK(contains(oneError("[objects]\nobject.a = house.obj 0 0 0\n", bad, 2), "model file"));
    CHECK(contains(oneError("[objects]\nobject.a = house.glb 0 0\n", bad, 2), "position needs 3 numbers"));
    CHECK(contains(oneError("[objects]\nobject.a = house.glb 0 0 0 scale 0\n", bad, 2), "scale: 0 is outside [0.001, 1000]"));
    CHECK(contains(oneError("[objects]\nobject.a = house.glb 0 0 0 spin 3\n", bad, 2), "unknown word 'spin'"));
    CHECK(contains(oneError("[objects]\nscatter.a = tree.glb density 2\n", bad, 2), "density: 2 is outside [0, 1]"));
    CHECK(contains(oneError("[objects]\nscatter.a = tree.glb height 5 1\n", bad, 2), "MIN 5 is above MAX 1"));
    CHECK(contains(oneError("[objects]\nscatter.a = density 0.1\n", bad, 2), "model files"));
}

TEST_CASE("scatter: each cell always holds the same instances, whatever else is placed") {
    ScatterRule r;
    r.files = {"a.glb", "b.glb"};
    r.density = 0.01;
    r.cell_m = 32.0f;
    r.scale_min = 0.5f;
    r.scale_max = 2.0f;
    r.seed = 9;
    const auto first = scatterRegion(r, {-4, -4}, {4, 4}, hills);
    CHECK(!first.empty());
    // Move away (a region that does not overlap), then back: the same instances.
    const auto away = scatterRegion(r, {100, 100}, {108, 108}, hills);
    const auto back = scatterRegion(r, {-4, -4}, {4, 4}, hills);
    CHECK(first == back);
    CHECK(asSet(away) != asSet(first));
    // A larger region holds the smaller one's instances exactly, and cells in another order too.
    const auto larger = asSet(scatterRegion(r, {-6, -5}, {7, 6}, hills));
    for (const auto& p : asSet(first)) CHECK(larger.count(p) == 1);
    std::vector<PlacedObject> reversed;
    for (int k = 4; k >= -4; --k)
        for (int i = 4; i >= -4; --i) scatterCell(r, {i, k}, hills, reversed);
    CHECK(asSet(reversed) == asSet(first));
    // Each instance lies in its cell; another seed places differently.
    for (const PlacedObject& p : first) {
        const glm::ivec2 c = scatterCellOf(r, {p.position.x, p.position.z});
        CHECK(c.x >= -4);
        CHECK(c.x <= 4);
        CHECK(p.scale >= 0.5f);
        CHECK(p.scale <= 2.0f);
        CHECK((p.file == 0 || p.file == 1));
    }
    r.seed = 10;
    CHECK(asSet(scatterRegion(r, {-4, -4}, {4, 4}, hills)) != asSet(first));
}

TEST_CASE("scatter: density per m^2 on average, and the ground limits hold") {
    ScatterRule r;
    r.files = {"t.glb"};
    r.density = 0.0123;
    r.cell_m = 20.0f;
    // Candidates: 0.0123 * 400 = 4.92 per cell on average (4 or 5).
    double total = 0.0;
    int cells = 0;
    for (int k = 0; k < 60; ++k)
        for (int i = 0; i < 60; ++i, ++cells) {
            const int n = scatterCandidates(r, {i, k});
            CHECK((n == 4 || n == 5));
            total += n;
        }
    CHECK(total / cells == doctest::Approx(4.92).epsilon(0.03));
    // Limits: height -20..10 m, grass >= 0.5, slope <= 0.15 (only the valleys pass).
    r.height_min_m = -20.0f;
    r.height_max_m = 10.0f;
    r.grass_min = 0.5f;
    r.slope_max = 0.15f;
    const auto placed = scatterRegion(r, {-20, -20}, {20, 20}, hills);
    CHECK(!placed.empty());
    for (const PlacedObject& p : placed) {
        const GroundSample g = hills(p.position.x, p.position.z);
        CHECK(p.position.y == g.height_m);
        CHECK(g.height_m >= -20.0);
        CHECK(g.height_m <= 10.0);
        CHECK(g.slope <= 0.15);
        CHECK(g.grass >= 0.5);
    }
    // Outside the terrain nothing stands.
    CHECK(scatterRegion(r, {1000, 1000}, {1004, 1004}, hills).empty());
}

TEST_CASE("scatter: placeObjects gives each list entry's instances in file order, for the drawing to load") {
    Settings s;
    REQUIRE(messages(loadIniString("[objects]\nobject.mill = data/props/house.glb 10 5 20  ground 0.5  yaw 90  scale 1.5\n"
                                   "object.hut = data/props/house.glb -10 7 -20\n"
                                   "scatter.woods = tree.glb rock.glb  density 0.01  cell 32  seed 9\n",
                                   "scene.ini", s)) == "");
    const ScatterArea area{{-128.0, -128.0}, {127.0, 127.0}};
    const std::vector<ObjectPlacement> placed = placeObjects(s.objects, hills, area);
    REQUIRE(placed.size() == 3);
    CHECK(placed[0].entry == "object.mill");
    CHECK(placed[0].files == std::vector<std::string>{"data/props/house.glb"});
    REQUIRE(placed[0].instances.size() == 1);
    const PlacedObject& mill = placed[0].instances[0];
    CHECK(mill.position == glm::dvec3(10.0, hills(10.0, 20.0).height_m + 0.5, 20.0));  // on the ground
    CHECK(mill.yaw_rad == doctest::Approx(1.5707963));
    CHECK(mill.scale == 1.5f);
    CHECK(mill.file == 0);
    REQUIRE(placed[1].instances.size() == 1);
    CHECK(placed[1].instances[0].position == glm::dvec3(-10.0, 7.0, -20.0));  // no ground: as given
    CHECK(placed[2].entry == "scatter.woods");
    CHECK(placed[2].files == std::vector<std::string>{"tree.glb", "rock.glb"});
    const ScatterRule& r = s.objects.scatters[0].rule;
    CHECK(placed[2].instances == scatterRegion(r, scatterCellOf(r, area.min), scatterCellOf(r, area.max), hills));
    CHECK(!placed[2].instances.empty());
    // Without a ground the rules place nothing but keep their files (the models still load).
    const std::vector<ObjectPlacement> bare = placeObjects(s.objects, {}, area);
    CHECK(bare[2].files.size() == 2);
    CHECK(bare[2].instances.empty());
    CHECK(bare[0].instances[0].position.y == 0.5);
    // The same lists place the same; the drawing settings do not matter.
    Settings t = s;
    t.objects.lod1_distance_m = 5.0f;
    CHECK(samePlacement(s.objects, t.objects));
    t.objects.scatters[0].rule.seed = 10;
    CHECK(!samePlacement(s.objects, t.objects));
}

TEST_CASE("scatter: the candidate budget over an area names each rule's count (beyond it the rules are placed around the camera)") {
    ObjectsSettings s;
    ScatterRule forest;
    forest.files = {"tree.glb"};
    forest.density = 0.003;  // the default scene's forest
    ScatterRule rocks = forest;
    rocks.density = 0.0003;
    s.scatters = {{"forest", forest}, {"rocks", rocks}};
    // The default island (8192 m): 0.22 M candidates.
    CHECK(scatterBudgetProblem(s, ScatterArea{{-4096.0, -4096.0}, {4096.0, 4096.0}}) == "");
    // A 131 km map: 56 M.
    const std::string why = scatterBudgetProblem(s, ScatterArea{{-65536.0, -65536.0}, {65536.0, 65536.0}});
    CHECK(why.find("5.67e+07 candidates over the terrain's 131072 x 131072 m") != std::string::npos);
    CHECK(why.find("scatter.forest 5.15e+07, scatter.rocks 5.15e+06") != std::string::npos);
    CHECK(why.find("accepted: at most 4e+06") != std::string::npos);
    // Rules without files place nothing and count nothing.
    for (NamedScatter& sc : s.scatters) sc.rule.files.clear();
    CHECK(scatterBudgetProblem(s, ScatterArea{{-65536.0, -65536.0}, {65536.0, 65536.0}}) == "");
}
