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
        CHECK(terrainDefines(s, tier) == std::vector<std::string>{"MATERIAL_TIER=" + std::to_string(tier)});
    s.view = TerrainView::Error;
    s.wireframe = true;
    CHECK(terrainDefines(s, 2) == std::vector<std::string>{"TERRAIN_VIEW=4", "TERRAIN_WIREFRAME"});
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

// A run of frames without a history reset between them (what a window or a capture renders):
// frame k at path frame k, the cascades fitted to fits[k] (the view itself when empty).
std::vector<test::RenderedFrame> sequence(const Settings& s, const std::vector<ViewParams>& views,
                                          const std::vector<ViewParams>& fits = {}) {
    useHills(s);
    renderer().resetHistory();
    std::vector<test::RenderedFrame> frames;
    for (std::size_t k = 0; k < views.size(); ++k) {
        FrameRequest request;
        request.sequence_frame = std::int64_t(k);
        request.shadow_fit_view = fits.empty() ? nullptr : &fits[k];
        frames.push_back(test::renderFrame(renderer(), s, views[k], 0.1 * double(k), request));
    }
    return frames;
}

// Share of pixels whose sun visibility ([debug] view = shadow, red) differs by more than 0.05.
double visibilityChange(const std::vector<float>& a, const std::vector<float>& b) {
    double changed = 0.0;
    for (std::size_t i = 0; i < a.size() && i < b.size(); i += 4) changed += std::abs(a[i] - b[i]) > 0.05f;
    return changed / double(std::max<std::size_t>(a.size() / 4, 1));
}

bool executed(const test::RenderedFrame& f, const std::string& pass) { return contains(f.report.executed, pass); }

TEST_CASE("gl: a kept far cascade shows what drawing it again shows, and is drawn again when its box moves and every cache_frames frames") {
    Settings s = hills();
    s.shadows.max_distance_m = 2000.0f;  // the far cascade from 2 km to 5 km: the hills' far half
    s.sky.sun_elevation_deg = 25.0f;
    s.sky.sun_azimuth_deg = 135.0f;
    s.shadows.cache_cascades = 1;
    s.shadows.cache_frames = 4;
    const std::string far = "shadows.cascade4";
    // The view stays put while the cascades' camera creeps (far under a far-cascade texel, about
    // 7 m) and at frame 6 jumps 300 m: every change of the image is the shadow map's.
    std::vector<ViewParams> views(9, kGrazing), fits(9, kGrazing);
    for (std::size_t k = 0; k < fits.size(); ++k) fits[k].position += glm::dvec3(0.01, 0.0, 0.006) * double(k);
    for (std::size_t k = 6; k < fits.size(); ++k) fits[k].position.x += 300.0;
    const auto kept = sequence(s, views, fits);
    s.shadows.cache_frames = 1;
    const auto drawn = sequence(s, views, fits);
    // Frame 0 follows a reset, 4 and 8 are the periodic redraws, 6 the jump.
    const std::vector<double> expected{0, 1, 1, 1, 0, 1, 0, 1, 0};
    for (std::size_t k = 0; k < kept.size(); ++k) {
        CAPTURE(k);
        CHECK(drawn[k].report.counters.at("shadows.cascades_cached") == 0.0);
        CHECK(executed(drawn[k], far));
        CHECK(kept[k].report.counters.at("shadows.cascades_cached") == expected[k]);
        CHECK(executed(kept[k], far) == (expected[k] == 0.0));
        CHECK(kept[k].report.counters.at("shadows.drawn") == drawn[k].report.counters.at("shadows.drawn"));
        Frame a{kept[k].rgba, kept[k].report}, b{drawn[k].rgba, drawn[k].report};
        CHECK(relativeDifference(a, b) < 1e-6);
    }
    // A change to what the casters are drawn with (here the slope bias) draws it again at once.
    s.shadows.cache_frames = 4;
    useHills(s);
    renderer().resetHistory();
    FrameRequest request;
    request.sequence_frame = 1;
    test::renderFrame(renderer(), s, kGrazing, 0.0, request);
    request.sequence_frame = 2;
    CHECK(test::renderFrame(renderer(), s, kGrazing, 0.1, request).report.counters.at("shadows.cascades_cached") == 1.0);
    s.shadows.slope_bias += 0.5f;
    request.sequence_frame = 3;
    CHECK(test::renderFrame(renderer(), s, kGrazing, 0.2, request).report.counters.at("shadows.cascades_cached") == 0.0);
}

TEST_CASE("gl: a slowly moving camera's far-cascade shadows do not flicker more with the cascade kept") {
    Settings s = hills();
    s.shadows.max_distance_m = 2000.0f;
    s.sky.sun_elevation_deg = 25.0f;
    s.sky.sun_azimuth_deg = 135.0f;
    s.debug.view = DebugView::Shadow;  // the sun's visibility per pixel
    s.shadows.cache_cascades = 1;
    // Walking pace at 30 fps along the view: the far cascade's box stays put for dozens of
    // frames, the casters' morph and LOD follow the camera.
    std::vector<ViewParams> views(10, kGrazing);
    for (std::size_t k = 0; k < views.size(); ++k) views[k].position += glm::dvec3(0.12, 0.0, 0.12) * double(k);
    s.shadows.cache_frames = 8;
    const auto kept = sequence(s, views);
    s.shadows.cache_frames = 1;
    const auto drawn = sequence(s, views);
    double flicker_kept = 0.0, flicker_drawn = 0.0, apart = 0.0, cached = 0.0;
    for (std::size_t k = 1; k < views.size(); ++k) {
        flicker_kept += visibilityChange(kept[k].rgba, kept[k - 1].rgba) / double(views.size() - 1);
        flicker_drawn += visibilityChange(drawn[k].rgba, drawn[k - 1].rgba) / double(views.size() - 1);
        apart = std::max(apart, visibilityChange(kept[k].rgba, drawn[k].rgba));
        cached += kept[k].report.counters.at("shadows.cascades_cached");
    }
    MESSAGE("far cascade kept: flicker (pixels whose visibility changes by > 0.05 per frame) " << flicker_kept
            << " kept, " << flicker_drawn << " drawn every frame; largest share apart " << apart << "; frames kept " << cached);
    CHECK(cached >= 5.0);  // frame 8 is the periodic redraw; the box may move once
    CHECK(flicker_kept <= flicker_drawn + 0.002);
    CHECK(apart < 0.005);
}

TEST_CASE("gl: sun cascades draw casters finer than their texels coarser, with the same shadows") {
    Settings s = hills();
    s.shadows.max_distance_m = 2000.0f;
    s.sky.sun_elevation_deg = 12.0f;  // long shadows: much of the view lies in them
    s.sky.sun_azimuth_deg = 135.0f;
    s.debug.view = DebugView::Shadow;  // the sun's visibility per pixel
    s.shadows.caster_step_texels = 0.0f;
    const Frame full = render(s, kGrazing);
    // The hills' finest grid (31 m) is coarser than two texels of every cascade (6 m and finer at
    // 1024^2): the default draws every caster as the view does.
    s.shadows.caster_step_texels = 1.0f;
    const Frame same = render(s, kGrazing);
    // 16 texels: the finest quadrants take every 2nd vertex (62 m) in the far cascade.
    s.shadows.caster_step_texels = 16.0f;
    const Frame coarse = render(s, kGrazing);
    const auto& c = coarse.report.counters;
    const double apart = visibilityChange(coarse.hdr, full.hdr);
    MESSAGE("caster triangles: " << full.report.counters.at("shadows.caster_triangles") << " full, "
            << c.at("shadows.caster_triangles") << " at 16 texels; pixels whose visibility changes by > 0.05: " << apart);
    CHECK(same.report.counters.at("shadows.caster_triangles") == full.report.counters.at("shadows.caster_triangles"));
    CHECK(relativeDifference(same, full) == 0.0);
    CHECK(c.at("shadows.caster_instances") == full.report.counters.at("shadows.caster_instances"));
    CHECK(c.at("shadows.caster_triangles") < 0.8 * full.report.counters.at("shadows.caster_triangles"));
    // Coarser casters move a shadow's edge by under a texel: a few edge pixels change. A crack
    // between quadrants would let light through in lines across the shadows.
    CHECK(apart < 0.005);
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
