// Sun shadows under OSMesa: a pillar on a flat plane casts its shadow where geometry says (for
// every filter), the images stay finite, and a sun at or below the horizon or shadows off
// leave no shadow pass and no shadow map. Spot lights: a street light beside the pillar leaves
// the ground behind it dark, a full atlas counts the lights it leaves out, and off is absent.
#include "app/frame.h"
#include "app/scene.h"
#include "renderer_fixture.h"
#include "renderer/half.h"
#include "terrain/heightmap.h"

#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

using namespace vista;

namespace {

FrameRenderer& renderer() { return test::fileRenderer(); }

const std::filesystem::path& pillarMap() { return test::pillarHeightmap("shadows"); }

Settings pillarScene() {
    Settings s;
    s.terrain.heightmap = pillarMap().string();
    s.terrain.size_m = 256.0f;
    s.terrain.height_scale_m = 40.0f;
    s.terrain.max_error_px = 0.25f;
    s.debug.grid = false;
    s.lights = {};
    s.sky.sun_azimuth_deg = 90.0f;  // east (+x): shadows fall towards -x
    s.sky.sun_elevation_deg = 45.0f;
    s.ssao.enabled = false;
    s.clouds.enabled = false;  // the cascades alone: no cloud shadow over the probes
    return s;
}

struct Frame {
    std::vector<std::uint16_t> hdr;
    FrameReport report;
    std::uint64_t nonfinite = 0;
    ViewParams view;
    float luminanceAt(const glm::dvec3& world) const {  // mean over the 3x3 pixels around world's projection
        ViewMatrices m = viewMatrices(view);
        glm::vec4 c = m.view_proj * glm::vec4(glm::vec3(world - view.position), 1.0f);
        int px = int((c.x / c.w * 0.5f + 0.5f) * float(view.width));
        int py = view.height - 1 - int((c.y / c.w * 0.5f + 0.5f) * float(view.height));  // rows top first
        float sum = 0.0f;
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                std::size_t i = (std::size_t(std::clamp(py + dy, 0, view.height - 1)) * std::size_t(view.width) +
                                 std::size_t(std::clamp(px + dx, 0, view.width - 1))) * 4;
                sum += 0.2126f * halfToFloat(hdr[i]) + 0.7152f * halfToFloat(hdr[i + 1]) + 0.0722f * halfToFloat(hdr[i + 2]);
            }
        return sum / 9.0f;
    }
};

Frame render(const Settings& s, const ViewParams& view) {
    FrameRenderer& r = renderer();
    REQUIRE(r.prepare(s).empty());
    Frame f;
    f.view = view;
    FrameRequest request;
    request.capture_hdr = &f.hdr;
    request.count_nonfinite = true;
    r.resetHistory();  // a first frame: no TAA jitter or history, as the test expects
    f.report = r.render(s, view, 0.0, request);
    for (const auto& c : r.counters().collect(true)) f.nonfinite += c.value;
    return f;
}

bool has(const std::vector<std::string>& passes, const std::string& prefix) {
    return std::ranges::any_of(passes, [&](const std::string& p) { return p.rfind(prefix, 0) == 0; });
}

const ViewParams kAbove{{-20.0, 160.0, 0.0}, 0.0, -89.9, 70.0, 0.5, 160, 160};

}  // namespace

TEST_CASE("shadows GL: a pillar's shadow falls where the sun's direction puts it, for every filter") {
    for (ShadowFilter filter : {ShadowFilter::Hard, ShadowFilter::Pcf, ShadowFilter::Pcss}) {
        CAPTURE(int(filter));
        Settings s = pillarScene();
        s.shadows.filter = filter;
        Frame f = render(s, kAbove);
        CHECK(f.nonfinite == 0);
        CHECK(has(f.report.executed, "shadows.cascade"));
        // The pillar top (40 m, x in [-4, 4]) under a 45 deg sun from +x shades the ground from
        // x = -4 to x = -44 for |z| < 4; the ground elsewhere is lit.
        const float lit = f.luminanceAt({-25.0, 0.0, 25.0});
        CHECK(lit > 0.0f);
        CHECK(f.luminanceAt({25.0, 0.0, 0.0}) == doctest::Approx(lit).epsilon(0.05));  // sun side
        for (double x : {-12.0, -25.0, -38.0}) {
            CAPTURE(x);
            CHECK(f.luminanceAt({x, 0.0, 0.0}) < 0.35f * lit);  // in the shadow: sky light only
        }
        CHECK(f.luminanceAt({-52.0, 0.0, 0.0}) > 0.9f * lit);  // past the shadow's tip
        CHECK(f.luminanceAt({-25.0, 0.0, 10.0}) > 0.9f * lit);  // beside it
    }
}

TEST_CASE("shadows GL: a lower sun makes a longer shadow in the opposite direction") {
    Settings s = pillarScene();
    s.sky.sun_azimuth_deg = 270.0f;  // west: shadows towards +x
    s.sky.sun_elevation_deg = 60.0f;  // 40 / tan(60) = 23 m long
    ViewParams v = kAbove;
    v.position.x = 20.0;
    Frame f = render(s, v);
    const float lit = f.luminanceAt({25.0, 0.0, 25.0});
    CHECK(f.luminanceAt({15.0, 0.0, 0.0}) < 0.35f * lit);
    CHECK(f.luminanceAt({36.0, 0.0, 0.0}) > 0.9f * lit);
    CHECK(f.luminanceAt({-15.0, 0.0, 0.0}) > 0.9f * lit);
}

TEST_CASE("shadows GL: sun at and below the horizon, or shadows off: no shadow pass and no shadow map") {
    for (float elevation : {0.0f, -3.0f, -18.0f}) {
        Settings s = pillarScene();
        s.sky.sun_elevation_deg = elevation;
        Frame f = render(s, kAbove);
        CHECK(f.nonfinite == 0);
        CHECK_FALSE(has(f.report.executed, "shadows."));
        CHECK(renderer().sunShadows() == nullptr);
    }
    Settings s = pillarScene();
    s.shadows.enabled = false;
    Frame f = render(s, kAbove);
    CHECK_FALSE(has(f.report.executed, "shadows."));
    CHECK(renderer().sunShadows() == nullptr);
    // And back on: the passes return.
    s.shadows.enabled = true;
    CHECK(has(render(s, kAbove).report.executed, "shadows.cascade"));
    CHECK(renderer().sunShadows() != nullptr);
}

TEST_CASE("shadows GL: the debug views (cascade colours, shadow map) and grazing sun stay finite") {
    Settings s = pillarScene();
    s.sky.sun_elevation_deg = 2.0f;
    for (DebugView view : {DebugView::Final, DebugView::Cascades, DebugView::ShadowMap}) {
        s.debug.view = view;
        Frame f = render(s, kAbove);
        CHECK(f.nonfinite == 0);
    }
    s.debug.view = DebugView::ShadowMap;  // the display image (LDR) is the shadow-map view
    REQUIRE(renderer().prepare(s).empty());
    std::vector<std::uint8_t> ldr;
    FrameRequest request;
    request.capture_ldr = &ldr;
    renderer().resetHistory();  // a first frame: no TAA jitter or history, as the test expects
    FrameReport report = renderer().render(s, kAbove, 0.0, request);
    CHECK(has(report.executed, "shadows.view"));
    CHECK(has(report.executed, "shadows.cascade"));
    CHECK_FALSE(has(report.executed, "lighting.sun"));  // the final image is not needed
}

TEST_CASE("shadows GL: frozen cascades stay where they were while the camera moves") {
    Settings s = pillarScene();
    s.shadows.freeze = true;
    render(s, kAbove);
    REQUIRE(renderer().sunShadows() != nullptr);
    const std::vector<ShadowCascade> before = renderer().sunShadows()->cascades();
    ViewParams moved = kAbove;
    moved.position += glm::dvec3(30.0, 10.0, -20.0);
    moved.yaw_deg += 40.0;
    Frame f = render(s, moved);
    CHECK(f.nonfinite == 0);
    const std::vector<ShadowCascade>& after = renderer().sunShadows()->cascades();
    REQUIRE(after.size() == before.size());
    for (std::size_t i = 0; i < after.size(); ++i) {
        CHECK(after[i].center_world == before[i].center_world);
        CHECK(after[i].radius_m == before[i].radius_m);
    }
    s.shadows.freeze = false;  // thawed: the cascades follow the camera again
    render(s, moved);
    CHECK(renderer().sunShadows()->cascades()[0].center_world != before[0].center_world);
}

namespace {

// Night (the sun's 30 deg down) and one street light 25 m up beside the pillar, pointing down:
// the pillar (40 m high, its walls slope to the ground from |x| = 4 to 6 m) hides the ground on
// the far side (-x) from the light.
Settings spotScene() {
    Settings s = pillarScene();
    s.sky.sun_elevation_deg = -30.0f;
    Light l;
    l.type = LightType::Spot;
    l.position = {12.0, 25.0, 0.0};
    l.direction = {0.0f, -1.0f, 0.0f};
    l.radius_m = 80.0f;
    l.intensity = 400.0f;
    l.inner_deg = 50.0f;
    l.outer_deg = 60.0f;
    s.lights.lights = {{"street", l}};
    return s;
}

}  // namespace

TEST_CASE("spot shadows GL: a pillar hides the ground behind it from a street light, for every filter") {
    Settings off = spotScene();
    off.shadows.spot_enabled = false;
    const Frame unshadowed = render(off, kAbove);
    CHECK_FALSE(has(unshadowed.report.executed, "shadows.spot_atlas"));
    CHECK(renderer().spotShadows() == nullptr);
    for (ShadowFilter filter : {ShadowFilter::Hard, ShadowFilter::Pcf, ShadowFilter::Pcss}) {
        CAPTURE(int(filter));
        Settings s = spotScene();
        s.shadows.spot_filter = filter;
        const Frame f = render(s, kAbove);
        CHECK(f.nonfinite == 0);
        CHECK(has(f.report.executed, "shadows.spot_atlas"));
        CHECK(f.report.counters.at("shadows.spot_shadowed") == 1.0);
        CHECK(f.report.counters.at("shadows.spot_unshadowed") == 0.0);
        // Behind the pillar: in its shadow (only what little sky is left at night).
        for (const glm::dvec3 p : {glm::dvec3(-10.0, 0.0, 0.0), glm::dvec3(-16.0, 0.0, 0.0)}) {
            CAPTURE(p.x);
            REQUIRE(unshadowed.luminanceAt(p) > 0.0f);
            CHECK(f.luminanceAt(p) < 0.15f * unshadowed.luminanceAt(p));
        }
        // On the light's side and beside the shadow: as lit as without shadows.
        for (const glm::dvec3 p : {glm::dvec3(20.0, 0.0, 0.0), glm::dvec3(-10.0, 0.0, 18.0), glm::dvec3(12.0, 0.0, -20.0)}) {
            CAPTURE(p.x);
            CAPTURE(p.z);
            CHECK(f.luminanceAt(p) == doctest::Approx(unshadowed.luminanceAt(p)).epsilon(0.05));
        }
    }
}

TEST_CASE("spot shadows GL: a full atlas leaves the smallest lights unshadowed and says how many") {
    Settings s = spotScene();
    Light l = s.lights.lights[0].light;
    s.lights.lights.clear();
    for (int i = 0; i < 20; ++i) {
        l.position = {-60.0 + 6.0 * i, 10.0 + i, 30.0};
        s.lights.lights.push_back({"l" + std::to_string(i), l});
    }
    s.shadows.spot_max_lights = 16;
    Frame f = render(s, kAbove);
    CHECK(f.nonfinite == 0);
    CHECK(f.report.counters.at("shadows.spot_candidates") == 20.0);
    CHECK(f.report.counters.at("shadows.spot_shadowed") == 16.0);
    CHECK(f.report.counters.at("shadows.spot_unshadowed") == 4.0);
    REQUIRE(renderer().spotShadows() != nullptr);
    // The tiles went to the 16 largest on screen.
    std::vector<Light> lights;
    for (const NamedLight& n : s.lights.lights) lights.push_back(n.light);
    std::uint64_t candidates = 0;
    const auto all = pickShadowedSpots(lights, kAbove, viewMatrices(kAbove), 64, 0.0f, candidates);
    const auto& picks = renderer().spotShadows()->picks();
    REQUIRE(picks.size() == 16);
    for (std::size_t k = 0; k < picks.size(); ++k) CHECK(picks[k].light == all[k].light);
    CHECK(all[16].screen_px <= picks.back().screen_px);
    // The debug view shows the atlas.
    s.debug.view = DebugView::SpotAtlas;
    std::vector<std::uint8_t> ldr;
    FrameRequest request;
    request.capture_ldr = &ldr;
    renderer().resetHistory();  // a first frame: no TAA jitter or history, as the test expects
    FrameReport report = renderer().render(s, kAbove, 0.0, request);
    CHECK(has(report.executed, "shadows.spot_view"));
    CHECK(has(report.executed, "shadows.spot_atlas"));
}

TEST_CASE("spot shadows GL: no spot light, shadows off or spot shadows off: no atlas pass and no atlas") {
    Settings s = spotScene();
    s.lights.lights[0].light.type = LightType::Point;
    CHECK_FALSE(has(render(s, kAbove).report.executed, "shadows.spot"));
    CHECK(renderer().spotShadows() == nullptr);
    s = spotScene();
    s.shadows.enabled = false;
    CHECK_FALSE(has(render(s, kAbove).report.executed, "shadows.spot"));
    CHECK(renderer().spotShadows() == nullptr);
    s = spotScene();
    s.lights.lights[0].light.shadow = false;
    CHECK_FALSE(has(render(s, kAbove).report.executed, "shadows.spot"));
    s = spotScene();  // back on, with the sun up too: both kinds of shadow at once stay finite
    s.sky.sun_elevation_deg = 30.0f;
    Frame f = render(s, kAbove);
    CHECK(f.nonfinite == 0);
    CHECK(has(f.report.executed, "shadows.spot_atlas"));
    CHECK(has(f.report.executed, "shadows.cascade"));
}
