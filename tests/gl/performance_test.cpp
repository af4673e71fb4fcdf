// Issue 21's savings under OSMesa, checked by what they must not change: the terrain's material
// tiers draw the image the near tier draws everywhere (no seam); lights below the screen
// footprint are skipped; a frame whose lights reach no tile draws no shade pass; the sun
// cascades leave out casters whose shadows cannot reach their receivers, and the sea draws
// only the grid segments in view, both with the image they have without the cut.
#include "app/frame.h"
#include "app/scene.h"
#include "renderer/lighting/light_settings.h"
#include "renderer_fixture.h"
#include "terrain/heightmap.h"
#include "terrain/terrain.h"

#include <glm/gtc/packing.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

using namespace vista;

namespace {

FrameRenderer& renderer() { return test::fileRenderer(); }

// Rolling hills 4 km square, 0..300 m, with steep flanks (rock) and high tops (snow).
Settings hills() {
    Settings s;
    s.terrain.heightmap = "performance-test";
    s.terrain.size_m = 4000.0f;
    s.terrain.height_scale_m = 300.0f;
    s.terrain.detail_distance_m = 150.0f;
    s.terrain.far_material_m = 1200.0f;
    s.sky.enabled = false;
    s.debug.grid = false;
    return s;
}

void useHills(const Settings& s) {
    static bool adopted = false;
    if (adopted) return;
    test::adoptTerrain(renderer(), s.terrain, 129, [](int x, int z) {
        return 0.45f + 0.35f * std::sin(float(x) * 0.21f) * std::cos(float(z) * 0.17f) + 0.1f * std::sin(float(x + z) * 0.05f);
    });
    adopted = true;
}

struct Frame {
    std::vector<float> hdr;
    FrameReport report;
    std::uint64_t exact = 0, shade_draws = 0;
};

Frame render(const Settings& s, const ViewParams& view) {
    useHills(s);
    renderer().resetHistory();  // each frame as the first of a run: no TAA history or jitter to tell them apart
    FrameRequest request;
    request.count_lights = true;
    test::RenderedFrame f = test::renderFrame(renderer(), s, view, 0.0, request);
    return Frame{std::move(f.rgba), std::move(f.report), f.counter("lights.exact"), f.counter("lights.shade_draws")};
}

bool contains(const std::vector<std::string>& v, const std::string& s) {
    return std::find(v.begin(), v.end(), s) != v.end();
}

// A grazing view from the map's edge across the hills: near, mid and far quadrants.
const ViewParams kGrazing{{-1900.0, 340.0, -1900.0}, 135.0, -8.0, 60.0, 0.5, 192, 108};

// The largest difference between two HDR images relative to the brighter one's peak (alpha left out).
double relativeDifference(const Frame& a, const Frame& b) {
    double peak = 1e-6, diff = 0.0;
    for (std::size_t i = 0; i < a.hdr.size() && i < b.hdr.size(); ++i) {
        if (i % 4 == 3) continue;
        peak = std::max({peak, double(a.hdr[i]), double(b.hdr[i])});
        diff = std::max(diff, std::abs(double(a.hdr[i]) - double(b.hdr[i])));
    }
    return diff / peak;
}

}  // namespace

TEST_CASE("gl: terrain material tiers draw what the near tier draws everywhere, so no seam shows") {
    Settings s = hills();
    const Frame tiered = render(s, kGrazing);
    const auto& c = tiered.report.counters;
    CHECK(c.at("terrain.tier_near") > 0.0);
    CHECK(c.at("terrain.tier_mid") > 0.0);
    CHECK(c.at("terrain.tier_far") > 0.0);
    CHECK(c.at("terrain.draws") == 3.0);
    s.terrain.material_tiers = false;
    const Frame single = render(s, kGrazing);
    CHECK(single.report.counters.at("terrain.draws") == 1.0);
    CHECK(single.report.counters.at("terrain.tier_near") ==
          c.at("terrain.tier_near") + c.at("terrain.tier_mid") + c.at("terrain.tier_far"));
    // Lit terrain (the sun): the same radiance up to float rounding, pixel for pixel.
    double peak = 1e-6, diff = 0.0;
    for (std::size_t i = 0; i < tiered.hdr.size(); ++i) {
        if (i % 4 == 3) continue;
        peak = std::max(peak, double(single.hdr[i]));
        diff = std::max(diff, std::abs(double(single.hdr[i]) - double(tiered.hdr[i])));
    }
    CHECK(peak > 1.0);
    CHECK(diff / peak < 2e-3);
}

TEST_CASE("gl: terrain debug views and the wireframe are program variants, not branches of the shaded program") {
    TerrainSettings s;
    for (int tier = 0; tier < kMaterialTiers; ++tier)
        CHECK(terrainDefines(s, tier) == std::vector<std::string>{"MATERIAL_TIER=" + std::to_string(tier), "MATERIAL_LAYERS=8"});
    s.view = TerrainView::Error;
    s.wireframe = true;
    CHECK(terrainDefines(s, 2) == std::vector<std::string>{"TERRAIN_VIEW=4", "TERRAIN_WIREFRAME", "MATERIAL_LAYERS=8"});
    // Every variant the settings can ask for is in the up-front list (allPrograms()).
    const auto programs = terrainPrograms();
    for (TerrainView view : {TerrainView::Shaded, TerrainView::Lod, TerrainView::Morph, TerrainView::Normals, TerrainView::Error,
                             TerrainView::Material})
        for (bool wire : {false, true})
            for (int tier = 0; tier < kMaterialTiers; ++tier) {
                TerrainSettings t;
                t.view = view;
                t.wireframe = wire;
                const ProgramKey key{"terrain/shaders/terrain.glsl", terrainDefines(t, tier)};
                CHECK(std::find(programs.begin(), programs.end(), key) != programs.end());
            }
    // The near tier keeps the detail out to detail_distance_m, the far tier starts at far_material_m.
    TerrainSettings d;
    CHECK(materialTier(d, 0.0) == 0);
    CHECK(materialTier(d, double(d.detail_distance_m) - 1.0) == 0);
    CHECK(materialTier(d, double(d.detail_distance_m) + 2.0) == 1);
    CHECK(materialTier(d, double(d.far_material_m) + 2.0) == 2);
    d.far_material_m = 0.0f;
    CHECK(materialTier(d, 1.0e9) == 1);
}

TEST_CASE("gl: lights below the screen footprint are skipped, and lights that reach no tile draw no shade pass") {
    const ViewParams view{{-300.0, 420.0, -300.0}, 135.0, -40.0, 60.0, 0.5, 160, 90};
    Settings s = hills();
    s.sky.sun_illuminance = 0.0f;  // local lights only
    auto light = [](const std::string& name, const std::string& spec) {
        NamedLight l{name, {}};
        REQUIRE(parseLightSpec(spec, l.light).empty());
        return l;
    };
    // A 0.2 m light some 800 m ahead: well under half a pixel (skipping is opt-in: it is inexact).
    s.lights.min_screen_px = 0.5f;
    s.lights.lights = {light("tiny", "point 300 0 300  ground 1  radius 0.2  intensity 100")};
    Frame tiny = render(s, view);
    CHECK(tiny.report.counters.at("lights.skipped") == 1.0);
    CHECK(tiny.report.counters.at("lights.visible") == 0.0);
    CHECK_FALSE(contains(tiny.report.executed, "lights.cull"));
    CHECK_FALSE(contains(tiny.report.executed, "lights.shade"));
    s.lights.min_screen_px = 0.0f;  // 0: every light in the frustum is kept
    CHECK(render(s, view).report.counters.at("lights.skipped") == 0.0);

    // Buried under the hills (below their lowest point): in the frustum, but every tile's depth
    // range misses it.
    s.lights.lights = {light("buried", "point 0 -100 0  radius 20  intensity 1000")};
    Frame buried = render(s, view);
    CHECK(buried.report.counters.at("lights.visible") == 1.0);
    CHECK(contains(buried.report.executed, "lights.cull"));
    CHECK(buried.exact == 0);
    CHECK(buried.shade_draws == 0);
    // Raised above the ground, it lights pixels and the shade pass draws.
    s.lights.lights = {light("lamp", "point 0 0 0  ground 5  radius 60  intensity 1000")};
    Frame lamp = render(s, view);
    CHECK(lamp.exact > 0);
    CHECK(lamp.shade_draws == 1);
}

TEST_CASE("gl: sun cascades leave out casters whose shadows cannot reach their receivers, with the same image") {
    Settings s = hills();
    // Four PSSM cascades to 2 km and the far one to 5 km: the hills' 500 m quadrants near the
    // camera lie wholly before the far cascade's first view depth.
    s.shadows.max_distance_m = 2000.0f;
    s.sky.sun_elevation_deg = 25.0f;
    const ViewParams view = kGrazing;
    // The sun ahead of the view (shadows point back at the camera) and behind it (they run away).
    for (float azimuth : {135.0f, 315.0f, 45.0f}) {
        CAPTURE(azimuth);
        s.sky.sun_azimuth_deg = azimuth;
        s.shadows.caster_cull = true;
        const Frame cut = render(s, view);
        s.shadows.caster_cull = false;
        const Frame all = render(s, view);
        const auto& c = cut.report.counters;
        CHECK(c.at("shadows.drawn") >= 3.0);
        CHECK(all.report.counters.at("shadows.casters_skipped") == 0.0);
        CHECK(c.at("shadows.caster_instances") + c.at("shadows.casters_skipped") ==
              all.report.counters.at("shadows.caster_instances"));
        if (azimuth == 135.0f) CHECK(c.at("shadows.casters_skipped") > 0.0);
        CHECK(relativeDifference(cut, all) < 1e-5);
    }
}

TEST_CASE("gl: the sea draws only the grid segments that can be in view, with the image of the whole circle") {
    Settings s = hills();
    s.water.enabled = true;
    s.water.level_m = 110.0f;  // floods the valleys between the hills
    for (double pitch : {-8.0, -89.0}) {
        CAPTURE(pitch);
        ViewParams view = kGrazing;
        view.pitch_deg = pitch;
        s.water.sector_cull = true;
        const Frame cut = render(s, view);
        s.water.sector_cull = false;
        const Frame whole = render(s, view);
        const double segments = double(s.water.grid_segments);
        CHECK(whole.report.counters.at("water.segments") == segments);
        if (pitch > -80.0) {
            CHECK(cut.report.counters.at("water.segments") < segments / 2.0);
            CHECK(cut.report.counters.at("water.triangles") < whole.report.counters.at("water.triangles") / 2.0);
        } else {
            CHECK(cut.report.counters.at("water.segments") == segments);  // looking down: every direction is in view
        }
        CHECK(relativeDifference(cut, whole) < 1e-5);
    }
}
