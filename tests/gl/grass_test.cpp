// Grass under OSMesa: its passes run after the terrain with finite output; off (or without a
// terrain) there is no grass pass and no buffer; the blades the GPU keeps are exactly the CPU
// mirror's (placement, bend and wind, also 10^7 s in and 10,000 km from the origin), only
// where the terrain is grass, and the same after moving away and back; the blades write their
// motion in the wind into the motion vectors (grass.velocity), as the CPU wind says.
#include "app/frame.h"
#include "app/scene.h"
#include "renderer_fixture.h"
#include "terrain/grass/grass.h"
#include "renderer/half.h"
#include "renderer/temporal.h"
#include "terrain/heightmap.h"
#include "terrain/material_weights.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <tuple>

using namespace vista;

namespace {

FrameRenderer& renderer() { return test::compiledFileRenderer(); }

constexpr int kMapSamples = 129;
constexpr float kMapSize = 512.0f;   // 4 m texels
constexpr float kHeightScale = 100.0f;

std::filesystem::path writeMap(const test::TempDir& dir, const std::string& name, const std::function<float(int, int)>& f) {
    Heightmap map{kMapSamples, kMapSamples, std::vector<float>(std::size_t(kMapSamples) * kMapSamples)};
    for (int z = 0; z < kMapSamples; ++z)
        for (int x = 0; x < kMapSamples; ++x) map.samples[std::size_t(z * kMapSamples + x)] = f(x, z);
    std::filesystem::path file = dir.path / name;
    REQUIRE(saveHeightmapPng16(file, map).empty());
    return file;
}

Settings grassScene(const std::filesystem::path& map) {
    Settings s;
    s.terrain.heightmap = map.string();
    s.terrain.size_m = kMapSize;
    s.terrain.height_scale_m = kHeightScale;
    s.terrain.band_jitter = 0.0f;  // the CPU mirror then knows the bands exactly
    s.sky.enabled = false;
    s.debug.grid = false;
    s.lights.enabled = false;
    s.grass.radius_m = 20.0f;
    s.grass.density = 8.0f;
    s.grass.gust_scale_m = 1.0f;  // many gusts in view: amplitude statistics do not depend on where they are
    return s;
}

// One culled blade as the GPU wrote it (GrassBlade in terrain/grass/shaders/grass_common.glsl).
struct Blade {
    glm::vec4 root_width;
    glm::vec4 shape;
    glm::uvec4 look;
};
static_assert(sizeof(Blade) == kGrassBladeBytes);

struct Frame {
    FrameReport report;
    std::vector<Blade> blades;
    std::uint64_t drawn = 0, nonfinite = 0;
    bool counted = false;
};

Frame render(const Settings& s, const ViewParams& view, double t) {
    FrameRenderer& r = renderer();
    REQUIRE(r.prepare(s).empty());
    r.counters().collect(true);
    std::vector<std::uint16_t> hdr;
    FrameRequest request;
    request.capture_hdr = &hdr;
    request.count_nonfinite = true;
    request.count_grass = true;
    Frame f;
    r.resetHistory();  // a first frame: no TAA jitter or history, as the test expects
    f.report = r.render(s, view, t, request);
    for (const auto& c : r.counters().collect(true)) {
        if (c.name == "grass.blades") {
            f.drawn = c.value;
            f.counted = true;
        } else {
            f.nonfinite += c.value;
        }
    }
    if (Grass* g = r.grass()) {
        std::uint32_t draws[8] = {};
        glGetNamedBufferSubData(g->drawBuffer(), 0, sizeof draws, draws);
        std::vector<Blade> near(draws[1]), far(draws[5]);
        if (!near.empty()) glGetNamedBufferSubData(g->bladeBuffer(), 0, GLsizeiptr(near.size() * sizeof(Blade)), near.data());
        if (!far.empty())
            glGetNamedBufferSubData(g->bladeBuffer(), GLintptr(g->farStart() * sizeof(Blade)), GLsizeiptr(far.size() * sizeof(Blade)),
                                    far.data());
        f.blades = near;
        f.blades.insert(f.blades.end(), far.begin(), far.end());
    }
    return f;
}

bool contains(const std::vector<std::string>& v, const std::string& name) {
    return std::find(v.begin(), v.end(), name) != v.end();
}

// The candidate a GPU blade came from, per the CPU mirror.
GrassCandidate candidateOf(const Blade& b, const GrassSettings& s, const ViewParams& view) {
    GrassLayout l = grassLayout(s);
    int id = int(b.look.z), slot_index = id / l.blades_per_cell, j = id % l.blades_per_cell;
    glm::ivec2 slot{slot_index % l.cells, slot_index / l.cells};
    glm::ivec2 box = grassBoxMin(l, {view.position.x, view.position.z}, viewMatrices(view).forward);
    return grassCandidate(l, grassWrapCell(slot, box, l.cells), j, s);
}

ViewParams meadowView(glm::dvec3 origin, double ground) {
    return ViewParams{origin + glm::dvec3(-30.0, ground + 1.7, 10.0), 80.0, -12.0, 60.0, 0.1, 160, 90};
}

}  // namespace

TEST_CASE("gl: grass passes run after the terrain with finite output, off, no pass and no buffers") {
    test::TempDir dir("grass-passes");
    auto meadow = writeMap(dir, "meadow.png", [](int, int) { return 0.3f; });
    Settings s = grassScene(meadow);
    const ViewParams view = meadowView({}, 0.3 * kHeightScale);
    Frame on = render(s, view, 3.0);
    const auto& ex = on.report.executed;
    REQUIRE(contains(ex, "grass.cull"));
    REQUIRE(contains(ex, "grass.gbuffer"));
    auto at = [&](const char* name) { return std::find(ex.begin(), ex.end(), name) - ex.begin(); };
    CHECK(at("grass.cull") < at("terrain.gbuffer"));  // culled first: the shadow passes draw the same blades
    if (contains(ex, "shadows.cascade0")) CHECK(at("grass.cull") < at("shadows.cascade0"));
    CHECK(at("terrain.gbuffer") < at("grass.gbuffer"));
    CHECK(at("grass.gbuffer") < at("lighting.sun"));
    CHECK(on.counted);
    CHECK(on.drawn == on.blades.size());
    CHECK(on.drawn > 500);
    CHECK(on.nonfinite == 0);
    CHECK(on.report.counters.at("grass.considered") == double(grassLayout(s.grass).candidates()));
    for (const Blade& b : on.blades) {
        CHECK(std::isfinite(b.root_width.x + b.root_width.y + b.root_width.z + b.root_width.w));
        CHECK(std::isfinite(b.shape.x + b.shape.y + b.shape.z + b.shape.w));
        CHECK(glm::length(glm::vec2(b.root_width.x, b.root_width.z)) < s.grass.radius_m);
    }
    CHECK(renderer().grass() != nullptr);

    // Higher above the terrain's top than the blades reach: nothing to draw, no grass pass.
    ViewParams high = view;
    high.position.y = 0.3 * kHeightScale + s.grass.radius_m + 1.0;
    Frame above = render(s, high, 3.0);
    CHECK_FALSE(contains(above.report.executed, "grass.cull"));
    CHECK_FALSE(contains(above.report.executed, "grass.gbuffer"));
    CHECK(above.report.counters.at("grass.considered") == 0.0);
    high.position.y -= 3.0;
    CHECK(contains(render(s, high, 3.0).report.executed, "grass.cull"));

    for (int variant = 0; variant < 2; ++variant) {
        Settings off = s;
        (variant == 0 ? off.grass.enabled : off.terrain.enabled) = false;
        Frame f = render(off, view, 3.0);
        for (const auto& name : f.report.executed) CHECK(name.rfind("grass.", 0) != 0);
        for (const auto& name : f.report.culled) CHECK(name.rfind("grass.", 0) != 0);
        CHECK(renderer().grass() == nullptr);
        CHECK_FALSE(f.counted);
        CHECK(f.report.counters.count("grass.considered") == 0);
    }
}

TEST_CASE("gl: the GPU keeps exactly the CPU mirror's blades: placement, bend and wind, at 10 s and 10^7 s") {
    test::TempDir dir("grass-mirror");
    auto meadow = writeMap(dir, "meadow.png", [](int, int) { return 0.3f; });
    for (glm::dvec3 origin : {glm::dvec3(0.0), glm::dvec3(1.0e7, 0.0, -1.0e7)}) {
        CAPTURE(origin.x);
        Settings s = grassScene(meadow);
        s.terrain.origin = origin;
        const ViewParams view = meadowView(origin, 0.3 * kHeightScale);
        std::vector<double> along[2];
        for (int k = 0; k < 2; ++k) {
            const double t = k == 0 ? 10.0 : 1.0e7;
            Frame f = render(s, view, t);
            REQUIRE(f.blades.size() > 500);
            const GrassWind w = grassWind(s.grass, {view.position.x, view.position.z}, t);
            double worst_pos = 0.0, worst_bend = 0.0, worst_height = 0.0;
            for (const Blade& b : f.blades) {
                GrassCandidate c = candidateOf(b, s.grass, view);
                glm::dvec2 rel = c.world_xz - glm::dvec2(view.position.x, view.position.z);
                worst_pos = std::max(worst_pos, glm::length(rel - glm::dvec2(b.root_width.x, b.root_width.z)));
                worst_height = std::max(worst_height, std::abs(double(b.root_width.y) - (origin.y + 0.3 * kHeightScale - view.position.y)));
                glm::vec2 face{-std::sin(c.facing), std::cos(c.facing)};
                glm::vec2 bend = face * (s.grass.curvature * c.curvature) +
                                 grassWindTilt(w, {b.root_width.x, b.root_width.z}, c.phase, c.frequency_step);
                worst_bend = std::max(worst_bend, double(glm::length(bend - glm::vec2(b.shape.z, b.shape.w))));
                CHECK(std::abs(b.shape.y - c.facing) < 1e-4f);
                along[k].push_back(glm::dot(glm::dvec2(b.shape.z, b.shape.w), glm::dvec2(w.dir)));
            }
            CAPTURE(t);
            CHECK(worst_pos < 2e-3);     // m
            CHECK(worst_height < 0.02);  // m (16-bit heightmap)
            CHECK(worst_bend < 2e-3);    // rad
        }
        // The wind is as strong after 10^7 s as after 10 s (mean and spread along the wind).
        auto meanSpread = [](const std::vector<double>& v) {
            double m = 0.0, m2 = 0.0;
            for (double x : v) m += x / double(v.size());
            for (double x : v) m2 += (x - m) * (x - m) / double(v.size());
            return std::pair{m, std::sqrt(m2)};
        };
        auto [m0, s0] = meanSpread(along[0]);
        auto [m1, s1] = meanSpread(along[1]);
        CHECK(m1 == doctest::Approx(m0).epsilon(0.15));
        CHECK(s1 == doctest::Approx(s0).epsilon(0.25));
    }
}

TEST_CASE("gl: grass grows only where the terrain is grass, and is the same after moving away and back") {
    test::TempDir dir("grass-material");
    Settings s = grassScene({});
    // Flat sand, snow and rock-band heights grow nothing; a meadow that turns into a steep
    // slope (1.5 m/m from x = 0) keeps its blades off the slope.
    const float sand = 0.05f, snow = 0.9f, rock_band = 0.55f;
    for (float v : {sand, snow, rock_band}) {
        auto map = writeMap(dir, "flat.png", [v](int, int) { return v; });
        Settings f = s;
        f.terrain.heightmap = map.string();
        Frame frame = render(f, meadowView({}, v * kHeightScale), 1.0);
        CAPTURE(v);
        CHECK(frame.drawn == 0);
        CHECK(frame.nonfinite == 0);
    }
    const double slope = 1.5, texel = kMapSize / (kMapSamples - 1);
    auto ramp = writeMap(dir, "ramp.png", [&](int x, int) {
        double wx = x * texel - kMapSize * 0.5;
        return float(0.3 + std::max(wx, 0.0) * slope / kHeightScale);
    });
    s.terrain.heightmap = ramp.string();
    s.terrain.grass_top = 0.95f;  // the whole ramp is in the grass band: only its slope excludes grass
    s.terrain.snow_start = 0.99f;
    const ViewParams view{{-12.0, 0.3 * kHeightScale + 3.0, 0.0}, 90.0, -10.0, 60.0, 0.1, 160, 90};
    Frame first = render(s, view, 1.0);
    int on_slope = 0, on_flat = 0;
    const double ny = 1.0 / std::sqrt(1.0 + slope * slope);
    REQUIRE(material::grassAt(0.5, ny, {0.135, 0.95, 0.99, 0.03}, s.terrain.rock_slope) == 0.0);
    for (const Blade& b : first.blades) {
        double wx = b.root_width.x + view.position.x;
        on_slope += wx > texel;  // beyond the texel where the normal map bends
        on_flat += wx < -texel;
    }
    CHECK(on_slope == 0);
    CHECK(on_flat > 200);

    // Away (other cells, other blades) and back: the same blades in the same places.
    auto places = [&](const Frame& f, const ViewParams& v) {
        std::vector<std::tuple<long, long, long>> out;
        for (const Blade& b : f.blades)
            out.emplace_back(std::lround((b.root_width.x + v.position.x) * 1000.0), std::lround((b.root_width.z + v.position.z) * 1000.0),
                             std::lround(b.shape.y * 1000.0));
        std::sort(out.begin(), out.end());
        return out;
    };
    ViewParams away = view;
    away.position += glm::dvec3(-150.0, 0.0, 120.0);
    Frame elsewhere = render(s, away, 50.0);
    Frame back = render(s, view, 99.0);
    CHECK(elsewhere.drawn > 200);
    CHECK(places(first, view) == places(back, view));
    CHECK(places(first, view) != places(elsewhere, away));
}

TEST_CASE("gl: blades cast into the sun cascades and the spot shadow atlas (cast_shadows), and not when off") {
    test::TempDir dir("grass-shadows");
    auto meadow = writeMap(dir, "meadow.png", [](int, int) { return 0.3f; });
    Settings s = grassScene(meadow);
    s.grass.blade_height_m = 1.2f;
    s.grass.density = 16.0f;
    s.sky.sun_elevation_deg = 20.0f;
    const ViewParams view = meadowView({}, 0.3 * kHeightScale);
    auto meanLuminance = [&](const Settings& settings) {
        FrameRenderer& r = renderer();
        REQUIRE(r.prepare(settings).empty());
        std::vector<std::uint16_t> hdr;
        FrameRequest request;
        request.capture_hdr = &hdr;
        r.resetHistory();  // a first frame: no TAA jitter or history, as the test expects
        FrameReport report = r.render(settings, view, 3.0, request);
        CHECK(contains(report.executed, "grass.gbuffer"));
        double sum = 0.0;
        for (std::size_t i = 0; i < hdr.size(); i += 4)
            sum += 0.2126 * halfToFloat(hdr[i]) + 0.7152 * halfToFloat(hdr[i + 1]) + 0.0722 * halfToFloat(hdr[i + 2]);
        CHECK(std::isfinite(sum));
        return std::make_pair(sum / double(hdr.size() / 4), report);
    };
    // The sun: blades shade the ground and each other.
    auto [sun_on, sun_report] = meanLuminance(s);
    CHECK(contains(sun_report.executed, "shadows.cascade0"));
    s.grass.cast_shadows = false;
    const double sun_off = meanLuminance(s).first;
    CHECK(sun_on < 0.97 * sun_off);
    // A street light over the meadow at night.
    s.sky.sun_elevation_deg = -30.0f;
    s.lights.enabled = true;
    Light l;
    l.type = LightType::Spot;
    l.position = view.position + glm::dvec3(12.0, 2.5, -4.0);
    l.direction = {0.0f, -1.0f, 0.0f};
    l.radius_m = 20.0f;
    l.intensity = 40.0f;
    l.inner_deg = 50.0f;
    l.outer_deg = 70.0f;
    s.lights.lights = {{"lamp", l}};
    const double spot_off = meanLuminance(s).first;
    s.grass.cast_shadows = true;
    auto [spot_on, spot_report] = meanLuminance(s);
    CHECK(contains(spot_report.executed, "shadows.spot_atlas"));
    CHECK(spot_on < 0.97 * spot_off);
    std::printf("grass shadows: mean luminance sun %.4g (off %.4g), spot %.4g (off %.4g)\n", sun_on, sun_off, spot_on, spot_off);
}

TEST_CASE("gl: grass writes its blades' motion in the wind into the motion vectors, as the CPU wind says") {
    // Two frames dt apart, the camera moving a little: where a blade is what a pixel shows, the
    // motion vector is that blade point's motion (wind and camera), from the CPU mirror of the
    // wind at t - dt. Wide, strongly swaying blades in a low view, so many pixels show one.
    test::TempDir dir("grass-velocity");
    auto meadow = writeMap(dir, "meadow.png", [](int, int) { return 0.3f; });
    const double dt = 0.25;  // a slow frame rate: the tips move about a pixel
    for (auto [origin, t] : {std::pair{glm::dvec3(0.0), 10.0}, std::pair{glm::dvec3(1.0e7, 0.0, -1.0e7), 1.0e7}}) {
        CAPTURE(origin.x);
        Settings s = grassScene(meadow);
        s.terrain.origin = origin;
        s.taa.enabled = false;  // no jitter: pixel centres are the unjittered positions
        s.grass.blade_width_m = 0.2f;
        s.grass.blade_height_m = 0.8f;
        s.grass.sway_strength = 0.4f;
        s.grass.sway_frequency_hz = 1.5f;
        s.grass.gust_speed_m_s = 12.0f;
        const double ground = origin.y + 0.3 * kHeightScale;
        const ViewParams before{origin + glm::dvec3(-30.0, ground + 0.9, 10.0), 80.0, -20.0, 60.0, 0.05, 160, 90};
        ViewParams view = before;
        view.position += glm::dvec3(0.02, 0.0, 0.01);
        view.yaw_deg += 0.2;
        FrameRenderer& r = renderer();
        REQUIRE(r.prepare(s).empty());
        r.resetHistory();
        r.render(s, before, t - dt, FrameRequest{});
        std::vector<float> velocity, depth;
        FrameRequest request;
        request.velocity = &velocity;
        request.depth = &depth;
        const FrameReport report = r.render(s, view, t, request);
        CHECK(contains(report.executed, "grass.velocity"));
        REQUIRE(r.grass());
        std::uint32_t draws[8] = {};
        glGetNamedBufferSubData(r.grass()->drawBuffer(), 0, sizeof draws, draws);
        std::vector<Blade> blades(draws[1]);  // the near list (s.grass.segments segments)
        REQUIRE(blades.size() > 200);
        glGetNamedBufferSubData(r.grass()->bladeBuffer(), 0, GLsizeiptr(blades.size() * sizeof(Blade)), blades.data());

        const int w = view.width, h = view.height, n = s.grass.segments;
        REQUIRE(velocity.size() == std::size_t(w * h * 4));
        REQUIRE(depth.size() == std::size_t(w * h));
        const glm::dmat4 vp(viewMatrices(view).view_proj);
        const glm::dmat4 prev_clip = previousClipFromRelative(before, view);
        const GrassWind wind_before = grassWind(s.grass, {view.position.x, view.position.z}, t - dt);
        auto ndcOf = [](const glm::dvec4& c) { return glm::dvec2(c) / c.w; };
        std::vector<double> errors, camera_only;
        double worst_bend = 0.0, motion = 0.0;
        for (const Blade& b : blades) {
            // The bend dt earlier, per the CPU mirror, against the cull's (bend + change).
            const GrassCandidate c = candidateOf(b, s.grass, view);
            const glm::vec2 face{-std::sin(c.facing), std::cos(c.facing)};
            const glm::dvec2 bend_before(face * (s.grass.curvature * c.curvature) +
                                         grassWindTilt(wind_before, {b.root_width.x, b.root_width.z}, c.phase, c.frequency_step));
            const glm::dvec2 bend_now(b.shape.z, b.shape.w);
            const glm::dvec2 change(halfToFloat(std::uint16_t(b.look.w & 0xffffu)), halfToFloat(std::uint16_t(b.look.w >> 16)));
            worst_bend = std::max(worst_bend, glm::length(bend_now + change - bend_before));
            auto spine = [&](glm::dvec2 bend, int k) {
                const double l = glm::length(bend);
                return glm::dvec3(b.root_width) +
                       grassBladePoint(b.shape.x, std::min(l, 1.4), l > 1e-6 ? bend / l : glm::dvec2(0.0, 1.0), n, k);
            };
            for (int k = 1; k < n; ++k) {  // the blade's midline at inner levels: inside its strip
                const glm::dvec3 p = spine(bend_now, k);
                const glm::dvec4 clip = vp * glm::dvec4(p, 1.0);
                if (!(clip.w > 0.0)) continue;
                const glm::dvec2 ndc = ndcOf(clip);
                const int x = int(std::floor((ndc.x * 0.5 + 0.5) * w)), row = int(std::floor((0.5 - ndc.y * 0.5) * h));
                if (x < 0 || x >= w || row < 0 || row >= h) continue;
                const std::size_t i = std::size_t(row * w + x);
                const double d = clip.z / clip.w;
                if (std::abs(depth[i] - d) > 0.01 * d) continue;  // another blade (or nothing) is seen there
                const glm::dvec2 expect = (ndc - ndcOf(prev_clip * glm::dvec4(spine(bend_before, k), 1.0))) * 0.5;
                const glm::dvec2 camera = (ndc - ndcOf(prev_clip * glm::dvec4(p, 1.0))) * 0.5;
                const glm::dvec2 got(velocity[i * 4], velocity[i * 4 + 1]);
                const glm::dvec2 px(w, h);
                errors.push_back(glm::length((got - expect) * px));
                camera_only.push_back(glm::length((camera - expect) * px));
                motion += glm::length((expect - camera) * px);
            }
        }
        REQUIRE(errors.size() > 100);
        motion /= double(errors.size());
        std::sort(errors.begin(), errors.end());
        std::sort(camera_only.begin(), camera_only.end());
        const double median = errors[errors.size() / 2], p90 = errors[errors.size() * 9 / 10];
        const double camera_median = camera_only[camera_only.size() / 2];
        MESSAGE("grass pixels " << errors.size() << ": bend dt earlier, GPU vs CPU " << worst_bend << " rad; wind motion "
                                << motion << " px; error median " << median << " px, p90 " << p90
                                << " px; camera-only vectors would be off by " << camera_median << " px (median)");
        CHECK(worst_bend < 2e-3);       // rad, as the current bend in the mirror test
        CHECK(motion > 0.3);            // the blades do move in the wind, beyond the camera's motion
        CHECK(median < 0.1 * motion);   // camera-only vectors are off by about all of it
        CHECK(p90 < 0.3 * motion);
        CHECK(camera_median > 0.3 * motion);  // camera-only vectors would fail the median check 3x over
    }
}
