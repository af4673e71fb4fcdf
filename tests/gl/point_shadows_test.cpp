// Point-light shadows under OSMesa: a lamp beside a pillar leaves the ground behind the pillar
// dark and beside it lit, and every ground point agrees with a CPU ray test of whether it sees
// the lamp (for every filter); more shadowed lamps than cubes count the unshadowed ones, the
// debug view shows the cubes, and off (or no shadowed lamp) is absent: no pass, no memory.
#include "app/frame.h"
#include "renderer_fixture.h"

#include <algorithm>
#include <cmath>
#include <string>

using namespace vista;

namespace {

FrameRenderer& renderer() { return test::fileRenderer(); }

const std::filesystem::path& pillarMap() { return test::pillarHeightmap("point_shadows"); }

const glm::dvec3 kLamp{14.0, 8.0, 3.0};

// Night (the sun 30 deg down), one lamp 14 m east of the pillar, 8 m up, point shadows on.
Settings lampScene() {
    Settings s;
    s.terrain.heightmap = pillarMap().string();
    s.terrain.size_m = 256.0f;
    s.terrain.height_scale_m = 40.0f;
    s.terrain.max_error_px = 0.25f;
    s.debug.grid = false;
    s.ssao.enabled = false;
    s.clouds.enabled = false;
    s.grass.enabled = false;
    s.water.enabled = false;
    s.taa.enabled = false;
    s.sky.sun_elevation_deg = -30.0f;
    s.shadows.point_enabled = true;
    s.shadows.point_resolution = 512;
    Light l;
    l.type = LightType::Point;
    l.position = kLamp;
    l.radius_m = 60.0f;
    l.intensity = 400.0f;
    s.lights = {};
    s.lights.lights = {{"lamp", l}};
    return s;
}

const ViewParams kAbove{{0.0, 150.0, 0.0}, 0.0, -89.9, 70.0, 0.5, 160, 160};

struct Frame {
    std::vector<std::uint16_t> hdr;
    FrameReport report;
    float luminanceAt(const glm::dvec3& world) const {  // mean over the 3x3 pixels around world's projection
        const ViewMatrices m = viewMatrices(kAbove);
        const glm::vec4 c = m.view_proj * glm::vec4(glm::vec3(world - kAbove.position), 1.0f);
        const int px = int((c.x / c.w * 0.5f + 0.5f) * float(kAbove.width));
        const int py = kAbove.height - 1 - int((c.y / c.w * 0.5f + 0.5f) * float(kAbove.height));  // rows top first
        float sum = 0.0f;
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                const std::size_t i = (std::size_t(std::clamp(py + dy, 0, kAbove.height - 1)) * std::size_t(kAbove.width) +
                                       std::size_t(std::clamp(px + dx, 0, kAbove.width - 1))) * 4;
                sum += 0.2126f * halfToFloat(hdr[i]) + 0.7152f * halfToFloat(hdr[i + 1]) + 0.0722f * halfToFloat(hdr[i + 2]);
            }
        return sum / 9.0f;
    }
};

Frame render(const Settings& s, const ViewParams& view = kAbove, std::vector<std::uint8_t>* ldr = nullptr) {
    FrameRenderer& r = renderer();
    REQUIRE(r.prepare(s).empty());
    Frame f;
    FrameRequest request;
    request.capture_hdr = &f.hdr;
    request.capture_ldr = ldr;
    request.count_nonfinite = true;
    r.resetHistory();
    f.report = r.render(s, view, 0.0, request);
    std::uint64_t nonfinite = 0;
    for (const auto& c : r.counters().collect(true)) nonfinite += c.value;
    CHECK(nonfinite == 0);
    return f;
}

bool has(const std::vector<std::string>& passes, const std::string& prefix) {
    return std::ranges::any_of(passes, [&](const std::string& p) { return p.rfind(prefix, 0) == 0; });
}

// The CPU's answer: does the segment from the lamp to the ground at (x, z) stay above the terrain?
bool seesLamp(const Terrain& t, double x, double z) {
    const glm::dvec3 p(x, t.heightAt(x, z) + 0.05, z);
    for (int i = 1; i < 400; ++i) {
        const glm::dvec3 q = glm::mix(kLamp, p, double(i) / 400.0);
        if (t.heightAt(q.x, q.z) > q.y) return false;
    }
    return true;
}

}  // namespace

TEST_CASE("point shadows GL: a pillar hides the ground behind it from a lamp, as a CPU ray test says, for every filter") {
    Settings off = lampScene();
    off.shadows.point_enabled = false;
    const Frame unshadowed = render(off);
    CHECK_FALSE(has(unshadowed.report.executed, "shadows.point"));
    CHECK(renderer().pointShadows() == nullptr);
    const Terrain& terrain = *renderer().terrain();
    for (ShadowFilter filter : {ShadowFilter::Hard, ShadowFilter::Pcf, ShadowFilter::Pcss}) {
        CAPTURE(int(filter));
        Settings s = lampScene();
        s.shadows.spot_filter = filter;
        const Frame f = render(s);
        CHECK(has(f.report.executed, "shadows.point_cubes"));
        CHECK(f.report.counters.at("shadows.point_shadowed") == 1.0);
        CHECK(f.report.counters.at("shadows.point_unshadowed") == 0.0);
        CHECK(f.report.counters.at("shadows.point_memory_bytes") > 0.0);
        // Behind the pillar (west of it): dark; beside it and on the lamp's side: as lit as without shadows.
        for (const glm::dvec3 p : {glm::dvec3(-12.0, 0.0, -2.0), glm::dvec3(-20.0, 0.0, -4.0)}) {
            CAPTURE(p.x);
            REQUIRE(unshadowed.luminanceAt(p) > 0.0f);
            CHECK(f.luminanceAt(p) < 0.15f * unshadowed.luminanceAt(p));
        }
        for (const glm::dvec3 p : {glm::dvec3(-12.0, 0.0, 20.0), glm::dvec3(24.0, 0.0, 0.0), glm::dvec3(10.0, 0.0, -18.0)}) {
            CAPTURE(p.x);
            CAPTURE(p.z);
            CHECK(f.luminanceAt(p) == doctest::Approx(unshadowed.luminanceAt(p)).epsilon(0.05));
        }
        // Every ground point within 36 m of the lamp whose neighbours 3 m around agree with it
        // (away from the shadow's edge and the filter's penumbra): the image says what the ray says.
        int dark = 0, lit = 0;
        for (double x = -40.0; x <= 40.0; x += 4.0)
            for (double z = -40.0; z <= 40.0; z += 4.0) {
                if (std::abs(x) < 9.0 && std::abs(z) < 9.0) continue;  // the pillar and its walls
                if (std::hypot(x - kLamp.x, z - kLamp.z) > 36.0) continue;
                const bool sees = seesLamp(terrain, x, z);
                bool decisive = true;
                for (double dx : {-3.0, 0.0, 3.0})
                    for (double dz : {-3.0, 0.0, 3.0}) decisive = decisive && seesLamp(terrain, x + dx, z + dz) == sees;
                if (!decisive) continue;
                CAPTURE(x);
                CAPTURE(z);
                const float without = unshadowed.luminanceAt({x, 0.0, z});
                REQUIRE(without > 0.0f);
                const float with = f.luminanceAt({x, 0.0, z});
                if (sees) {
                    CHECK(with == doctest::Approx(without).epsilon(0.05));
                    ++lit;
                } else {
                    CHECK(with < 0.15f * without);
                    ++dark;
                }
            }
        CHECK(dark >= 6);
        CHECK(lit >= 30);
    }
}

TEST_CASE("point shadows GL: more shadowed lamps than cubes: the largest get cubes, the rest are counted") {
    Settings s = lampScene();
    Light l = s.lights.lights[0].light;
    s.lights.lights.clear();
    for (int i = 0; i < 6; ++i) {
        l.position = {-50.0 + 20.0 * i, 5.0 + 2.0 * i, 30.0};
        l.radius_m = 20.0f + 4.0f * float(i);
        s.lights.lights.push_back({"lamp" + std::to_string(i), l});
    }
    s.shadows.point_max_lights = 4;
    s.shadows.point_resolution = 128;
    s.shadows.point_min_screen_px = 0.0f;
    Frame f = render(s);
    CHECK(f.report.counters.at("shadows.point_candidates") == 6.0);
    CHECK(f.report.counters.at("shadows.point_shadowed") == 4.0);
    CHECK(f.report.counters.at("shadows.point_unshadowed") == 2.0);
    REQUIRE(renderer().pointShadows() != nullptr);
    const auto& picks = renderer().pointShadows()->picks();
    REQUIRE(picks.size() == 4);
    for (std::size_t k = 0; k < picks.size(); ++k) CHECK(picks[k].light == 5 - k);  // the widest lamps
    // The debug view shows the cubes (and needs no lighting).
    s.debug.view = DebugView::PointShadows;
    std::vector<std::uint8_t> ldr;
    Frame view = render(s, kAbove, &ldr);
    CHECK(has(view.report.executed, "shadows.point_view"));
    CHECK(has(view.report.executed, "shadows.point_cubes"));
    // Row 0 (the first cube, 15 m above the ground): its -Y face (the fourth) sees the ground,
    // its +Y face (the third) nothing (black), not the flat grey of a frame without cubes.
    const std::size_t row = std::size_t(kAbove.height) / 8;
    auto red = [&](std::size_t col) { return int(ldr[(row * std::size_t(kAbove.width) + col) * 4]); };
    CHECK(red(std::size_t(kAbove.width) * 5 / 12) < 10);
    CHECK(red(std::size_t(kAbove.width) * 7 / 12) > red(std::size_t(kAbove.width) * 5 / 12) + 30);
}

TEST_CASE("point shadows GL: off, shadows off, lamps with shadow off or too small: no pass and no cubes") {
    auto absent = [](const Settings& s) {
        const Frame f = render(s);
        CHECK_FALSE(has(f.report.executed, "shadows.point"));
        CHECK(f.report.counters.count("shadows.point_memory_bytes") == 0);
        CHECK(renderer().pointShadows() == nullptr);
    };
    Settings s = lampScene();
    s.shadows.point_enabled = false;
    absent(s);
    s = lampScene();
    s.shadows.enabled = false;
    absent(s);
    s = lampScene();
    s.lights.lights[0].light.shadow = false;
    absent(s);
    s = lampScene();
    s.shadows.point_min_screen_px = 10000.0f;
    absent(s);
    // Back on, with a shadowed spot and the sun up too: every kind of shadow at once stays finite.
    s = lampScene();
    s.sky.sun_elevation_deg = 30.0f;
    Light spot = s.lights.lights[0].light;
    spot.type = LightType::Spot;
    spot.position = {-14.0, 10.0, 0.0};
    s.lights.lights.push_back({"spot", spot});
    const Frame f = render(s);
    CHECK(has(f.report.executed, "shadows.point_cubes"));
    CHECK(has(f.report.executed, "shadows.spot_atlas"));
    CHECK(has(f.report.executed, "shadows.cascade"));
}
