// The sea under OSMesa: its passes sit between the lighting and the aerial perspective, and off
// there is no water pass and no water object; the image stays finite with the camera high above,
// at the water line, under water, at grazing angles and 10,000 km out 10^7 s in; under water the
// tint pass runs and turns the image blue-green; the reflection modes differ where the island is
// mirrored; and the GPU's waves equal the CPU's double-precision mirror.
#include "app/frame.h"
#include "app/scene.h"
#include "renderer/bindings.h"
#include "renderer/half.h"
#include "renderer_fixture.h"
#include "terrain/heightmap.h"
#include "terrain/water/shaders/water_bindings.glsl"
#include "terrain/water/water.h"
#include "terrain/water/waves.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

using namespace vista;

namespace {

FrameRenderer& renderer() { return test::compiledFileRenderer(); }

constexpr int kMapSamples = 65;

// A round island: 30 m at the centre, 10 m under water at the map's edge (water at y = 0).
Settings islandScene(const std::filesystem::path& map) {
    Settings s;
    s.terrain.heightmap = map.string();
    s.terrain.size_m = 512.0f;
    s.terrain.height_scale_m = 40.0f;
    s.terrain.height_offset_m = -10.0f;
    s.debug.grid = false;
    s.grass.enabled = false;
    s.clouds.enabled = false;
    s.lights.enabled = false;
    s.water.enabled = true;
    s.water.level_m = 0.0f;
    return s;
}

std::filesystem::path writeIsland(const test::TempDir& dir) {
    Heightmap map{kMapSamples, kMapSamples, std::vector<float>(std::size_t(kMapSamples) * kMapSamples)};
    for (int z = 0; z < kMapSamples; ++z)
        for (int x = 0; x < kMapSamples; ++x) {
            const double u = (x - 32) / 32.0, v = (z - 32) / 32.0;
            map.samples[std::size_t(z * kMapSamples + x)] = float(std::clamp(1.0 - std::sqrt(u * u + v * v), 0.0, 1.0));
        }
    std::filesystem::path file = dir.path / "island.png";
    REQUIRE(saveHeightmapPng16(file, map).empty());
    return file;
}

struct Frame {
    FrameReport report;
    std::vector<std::uint16_t> hdr;
    std::uint64_t nonfinite = 0;
    glm::dvec3 mean{0.0};
};

Frame render(const Settings& s, const ViewParams& view, double t) {
    FrameRenderer& r = renderer();
    REQUIRE(r.prepare(s).empty());
    r.counters().collect(true);
    Frame f;
    FrameRequest request;
    request.capture_hdr = &f.hdr;
    request.count_nonfinite = true;
    r.resetHistory();  // a first frame: no TAA jitter or history, as the test expects
    f.report = r.render(s, view, t, request);
    for (const auto& c : r.counters().collect(true))
        if (c.name == "nonfinite_pixels") f.nonfinite += c.value;
    for (std::size_t i = 0; i < f.hdr.size(); i += 4)
        f.mean += glm::dvec3(halfToFloat(f.hdr[i]), halfToFloat(f.hdr[i + 1]), halfToFloat(f.hdr[i + 2]));
    f.mean /= double(f.hdr.size() / 4);
    return f;
}

bool contains(const std::vector<std::string>& v, const std::string& name) {
    return std::find(v.begin(), v.end(), name) != v.end();
}

bool anyWater(const std::vector<std::string>& v) {
    return std::any_of(v.begin(), v.end(), [](const std::string& n) { return n.rfind("water.", 0) == 0; });
}

// n probe points on a spiral out from the eye, d = 0.5 + step_m * i: (x, z) offsets in m and a
// footprint (0 for every third) in z.
std::vector<glm::vec4> spiralPoints(int n, double step_m) {
    std::vector<glm::vec4> points;
    for (int i = 0; i < n; ++i) {
        const double a = 0.37 * i, d = 0.5 + step_m * i;
        const float footprint = i % 3 == 0 ? 0.0f : 0.02f * float(i % 7);
        points.emplace_back(float(d * std::cos(a)), float(d * std::sin(a)), footprint, 0.0f);
    }
    return points;
}

// The probe program (tests/gl/shaders/water_probe.glsl) at points: three vec4 per point
// (displacement, normal, previous frame's displacement).
std::vector<glm::vec4> probeWaves(const Water& water, GLuint program, const std::vector<glm::vec4>& points) {
    gl::Buffer in = gl::Buffer::create(GLsizeiptr(points.size() * sizeof(glm::vec4)), points.data(), 0, "probe points");
    gl::Buffer out = gl::Buffer::create(GLsizeiptr(points.size() * 3 * sizeof(glm::vec4)), nullptr, 0, "probe results");
    glUseProgram(program);
    glBindBufferBase(GL_UNIFORM_BUFFER, WATER_BINDING_UNIFORMS, water.uniformBuffer());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kAux, in.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kCounters, out.id());
    glDispatchCompute(GLuint((points.size() + 63) / 64), 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<glm::vec4> results(points.size() * 3);
    glGetNamedBufferSubData(out.id(), 0, GLsizeiptr(results.size() * sizeof(glm::vec4)), results.data());
    return results;
}

}  // namespace

TEST_CASE("gl: water passes run between the lighting and the aerial perspective, off, no pass and no water") {
    test::TempDir dir("water-passes");
    Settings s = islandScene(writeIsland(dir));
    const ViewParams view{{-220.0, 25.0, 220.0}, 45.0, -8.0, 60.0, 0.5, 160, 90};
    Frame on = render(s, view, 4.0);
    const auto& ex = on.report.executed;
    REQUIRE(contains(ex, "water.copy"));
    REQUIRE(contains(ex, "water.surface"));
    CHECK_FALSE(contains(ex, "water.underwater"));
    auto at = [&](const char* name) { return std::find(ex.begin(), ex.end(), name) - ex.begin(); };
    CHECK(at("lighting.sun") < at("water.copy"));
    CHECK(at("water.copy") < at("water.surface"));
    CHECK(at("water.surface") < at("sky.aerial"));
    CHECK(at("water.surface") < at("sky.atmosphere"));
    CHECK(on.nonfinite == 0);
    CHECK(renderer().water() != nullptr);
    CHECK(on.report.counters.at("water.waves") == 24.0);
    CHECK(on.report.counters.at("water.vertices") > 1000.0);
    CHECK(on.report.counters.at("water.underwater") == 0.0);

    s.water.enabled = false;
    Frame off = render(s, view, 4.0);
    CHECK_FALSE(anyWater(off.report.executed));
    CHECK_FALSE(anyWater(off.report.culled));
    CHECK(renderer().water() == nullptr);
    CHECK(off.nonfinite == 0);
    // The sea changes the picture: the map's edge and the ocean beyond it are under water.
    CHECK(glm::length(on.mean - off.mean) > 1e-3 * glm::length(off.mean));
}

TEST_CASE("gl: water output is finite at the water line, under it, at grazing angles and 10,000 km out at 10^7 s") {
    test::TempDir dir("water-finite");
    Settings s = islandScene(writeIsland(dir));
    s.lights.enabled = true;  // local lights shaded forward on the water
    NamedLight lamp{"lamp", {}};
    REQUIRE(parseLightSpec("point -150 3 150  radius 40  intensity 300", lamp.light).empty());
    s.lights.lights.push_back(lamp);
    const WaveSet waves = makeWaves(s.water);
    struct Case {
        const char* name;
        glm::dvec3 eye;
        double yaw, pitch, t;
        bool under;
    };
    const glm::dvec2 shore{-170.0, 170.0};
    const double line = evaluateWaves(waves, shore, 7.0).displacement.y;
    const Case cases[] = {
        {"high above", {-300.0, 120.0, 300.0}, 45.0, -20.0, 7.0, false},
        {"at the water line", {shore.x, line, shore.y}, 45.0, 0.0, 7.0, false},
        {"just below the line", {shore.x, line - 0.05, shore.y}, 45.0, 5.0, 7.0, true},
        {"under water looking up", {-200.0, -4.0, 200.0}, 45.0, 60.0, 7.0, true},
        {"under water looking down", {-200.0, -4.0, 200.0}, 45.0, -60.0, 7.0, true},
        {"grazing out to sea", {-200.0, 1.5, 200.0}, 225.0, 0.0, 7.0, false},
        {"grazing at the island", {-400.0, 0.8, 400.0}, 45.0, -0.5, 7.0, false},
        {"10,000 km out, 10^7 s", {1e7, 3.0, -1e7}, 30.0, -5.0, 1e7, false},
        {"10,000 km out under water", {1e7, -2.0, -1e7}, 30.0, 10.0, 1e7, true},
    };
    for (const Case& c : cases) {
        CAPTURE(c.name);
        const ViewParams view{c.eye, c.yaw, c.pitch, 60.0, 0.2, 160, 90};
        Frame f = render(s, view, c.t);
        CHECK(f.nonfinite == 0);
        CHECK(contains(f.report.executed, "water.surface"));
        CHECK(f.report.counters.at("water.underwater") == (c.under ? 1.0 : 0.0));
        if (c.under) CHECK(contains(f.report.executed, "water.underwater"));
        if (c.eye.y > 50.0) CHECK_FALSE(contains(f.report.executed, "water.underwater"));
        CHECK(f.mean.x + f.mean.y + f.mean.z > 0.0);
    }
}

TEST_CASE("gl: water seen from under the surface turns the image blue-green, above it the tint pass stays out") {
    test::TempDir dir("water-under");
    Settings s = islandScene(writeIsland(dir));
    const ViewParams below{{-200.0, -5.0, 200.0}, 45.0, 0.0, 60.0, 0.2, 160, 90};
    Frame f = render(s, below, 3.0);
    REQUIRE(contains(f.report.executed, "water.underwater"));
    CHECK(f.nonfinite == 0);
    CHECK(f.mean.y > 2.0 * f.mean.x);  // red is absorbed first
    CHECK(f.mean.z > 2.0 * f.mean.x);
    s.water.enabled = false;
    Frame dry = render(s, below, 3.0);
    CHECK_FALSE(anyWater(dry.report.executed));
}

TEST_CASE("gl: water's screen-space reflection mirrors the island where the sky reflection cannot") {
    test::TempDir dir("water-ssr");
    Settings s = islandScene(writeIsland(dir));
    const ViewParams view{{-330.0, 6.0, 330.0}, 45.0, -2.0, 60.0, 0.2, 160, 90};
    Frame ssr = render(s, view, 2.0);
    s.water.reflection = WaterReflection::Sky;
    Frame sky = render(s, view, 2.0);
    CHECK(ssr.nonfinite == 0);
    CHECK(sky.nonfinite == 0);
    double diff = 0.0;
    for (std::size_t i = 0; i < ssr.hdr.size(); ++i) diff += std::abs(halfToFloat(ssr.hdr[i]) - halfToFloat(sky.hdr[i]));
    CHECK(diff > 0.01 * double(ssr.hdr.size()) * (sky.mean.x + sky.mean.y + sky.mean.z) / 3.0 * 0.1);
}

TEST_CASE("gl: water waves on the GPU equal the CPU's double-precision mirror (also 10,000 km out at 10^7 s)") {
    test::TempDir dir("water-probe");
    Settings s = islandScene(writeIsland(dir));
    s.water.choppiness = 1.5f;
    FrameRenderer& r = renderer();
    r.shaders().addListed({"tests/gl/shaders/water_probe.glsl", {}});  // the test's own program
    auto* program = r.shaders().get("tests/gl/shaders/water_probe.glsl");
    REQUIRE(program);
    for (auto [eye, t] : {std::pair{glm::dvec3(-200.0, 10.0, 200.0), 3.0}, std::pair{glm::dvec3(1e7, 4.0, -1e7), 1e7}}) {
        CAPTURE(eye.x);
        const ViewParams view{eye, 45.0, -10.0, 60.0, 0.5, 64, 36};
        render(s, view, t);
        REQUIRE(r.water());
        const WaveSet& waves = r.water()->waves();
        const std::vector<glm::vec4> points = spiralPoints(256, 2.0);  // out to ~500 m
        const std::vector<glm::vec4> results = probeWaves(*r.water(), program->id(), points);
        double worst_d = 0.0, worst_n = 0.0, worst_j = 0.0, worst_v = 0.0;
        for (std::size_t i = 0; i < points.size(); ++i) {
            const glm::dvec2 x0 = glm::dvec2(eye.x, eye.z) + glm::dvec2(points[i].x, points[i].y);
            const WaveSample cpu = evaluateWaves(waves, x0, t, points[i].z);
            const glm::dvec3 d(results[3 * i]), n(results[3 * i + 1]);
            worst_d = std::max(worst_d, glm::length(d - cpu.displacement));
            worst_n = std::max(worst_n, glm::length(n - cpu.normal));
            worst_j = std::max(worst_j, std::abs(double(results[3 * i].w) - cpu.jacobian));
            worst_v = std::max(worst_v, std::abs(double(results[3 * i + 1].w) - cpu.lost_slope_variance));
        }
        MESSAGE("GPU vs CPU waves: displacement " << worst_d << " m, normal " << worst_n << ", jacobian " << worst_j
                                                  << ", lost slope variance " << worst_v);
        CHECK(worst_d < 1e-4);  // float sums of 24 waves, phases as small camera-relative angles
        CHECK(worst_n < 5e-4);
        CHECK(worst_j < 1e-3);
        CHECK(worst_v < 1e-6);
    }
}

TEST_CASE("gl: water is lit by the culled local lights (forward lists) at night, the same through any culling") {
    test::TempDir dir("water-lights");
    Settings s = islandScene(writeIsland(dir));
    s.sky.sun_elevation_deg = -20.0f;
    s.exposure.mode = ExposureMode::Manual;
    const ViewParams view{{-230.0, 12.0, 310.0}, -10.0, -20.0, 60.0, 0.2, 160, 90};
    // 4 m above the sea, reaching 12 m: the sea floor (10 m down) is out of its reach, so only
    // the forward-shaded surface can show it.
    NamedLight lamp{"lamp", {}};
    REQUIRE(parseLightSpec("point -240 4 270  radius 12  intensity 2000", lamp.light).empty());
    s.lights.lights.push_back(lamp);
    s.lights.enabled = false;
    const Frame dark = render(s, view, 1.0);
    const double d = dark.mean.x + dark.mean.y + dark.mean.z;
    s.lights.enabled = true;
    double first = 0.0;
    for (LightCulling method : {LightCulling::Naive, LightCulling::Tiled, LightCulling::Clustered, LightCulling::Hashed}) {
        CAPTURE(int(method));
        s.lights.culling = method;
        const Frame lit = render(s, view, 1.0);
        CHECK(lit.nonfinite == 0);
        CHECK(contains(lit.report.executed, "water.surface"));
        const double l = lit.mean.x + lit.mean.y + lit.mean.z;
        MESSAGE("mean radiance with the lamp " << l << ", without " << d);
        CHECK(l > 1.5 * d + 1e-4);
        if (method == LightCulling::Naive) first = l;
        CHECK(l == doctest::Approx(first).epsilon(0.01));
    }
}

TEST_CASE("gl: rain rings the sea near the eye (rain ripples), snow and dry weather leave it still, all finite") {
    test::TempDir dir("water-rain");
    Settings s = islandScene(writeIsland(dir));
    s.water.wind_speed_m_s = 1.0f;  // a calm sea: the rings stand out
    const ViewParams view{{-330.0, 3.0, 330.0}, 45.0, -30.0, 60.0, 0.2, 160, 90};
    auto seaOnly = [](Settings w) {  // the sea's own change: no drop drawn (all nearer than near_fade_m), no splash
        w.weather.radius_m = 2.0f;
        w.weather.near_fade_m = 10.0f;
        w.weather.splashes = false;
        w.weather.wetness = 0.0f;  // nor wet terrain
        return w;
    };
    const Frame dry = render(s, view, 2.0);
    s.weather.enabled = true;
    s.weather.intensity = 1.0f;
    const Frame rain = render(seaOnly(s), view, 2.0);
    s.weather.kind = WeatherKind::Snow;
    const Frame snow = render(seaOnly(s), view, 2.0);
    CHECK(rain.nonfinite == 0);
    CHECK(snow.nonfinite == 0);
    auto difference = [](const Frame& a, const Frame& b) {
        double d = 0.0;
        for (std::size_t i = 0; i < a.hdr.size(); i += 4) d += std::abs(halfToFloat(a.hdr[i + 1]) - halfToFloat(b.hdr[i + 1]));
        return d / double(a.hdr.size() / 4);
    };
    CHECK(difference(rain, dry) > 1e-3 * dry.mean.y);
    CHECK(difference(snow, dry) < 1e-6 + 1e-4 * dry.mean.y);
}

// Per-vertex motion (docs/temporal.md): "water.velocity" writes the waves' own motion into the
// frame's motion vectors. The previous frame's displacement on the GPU equals the CPU's waves at
// t - dt at known points (also 10,000 km out at 10^7 s), and with a still camera the sea's motion
// vectors match the CPU: each pixel's surface point (from its depth) traced back to its rest point
// and moved to its previous-frame position. Without the pass the camera's vectors are 0 there.
TEST_CASE("gl: the sea writes its waves' own motion into the motion vectors, as the CPU waves say") {
    test::TempDir dir("water-velocity");
    Settings s = islandScene(writeIsland(dir));
    s.taa.enabled = false;  // no jitter: pixel centres are the unjittered positions
    s.water.choppiness = 1.0f;
    s.water.wind_speed_m_s = 12.0f;  // higher, faster waves
    FrameRenderer& r = renderer();
    REQUIRE(r.prepare(s).empty());
    r.shaders().addListed({"tests/gl/shaders/water_probe.glsl", {}});
    auto* program = r.shaders().get("tests/gl/shaders/water_probe.glsl");
    REQUIRE(program);
    const double dt = 0.25;  // a slow frame rate: the waves move about a pixel
    for (auto [eye, t] : {std::pair{glm::dvec3(-300.0, 6.0, 300.0), 3.0}, std::pair{glm::dvec3(1e7, 6.0, -1e7), 1e7}}) {
        CAPTURE(eye.x);
        const ViewParams view{eye, 225.0, -25.0, 60.0, 0.2, 96, 54};  // away from the island, down at the sea
        r.resetHistory();
        r.render(s, view, t - dt, FrameRequest{});
        std::vector<float> velocity, depth;
        FrameRequest request;
        request.velocity = &velocity;
        request.depth = &depth;
        const FrameReport report = r.render(s, view, t, request);
        CHECK(std::find(report.executed.begin(), report.executed.end(), "water.velocity") != report.executed.end());
        REQUIRE(r.water());
        const WaveSet& waves = r.water()->waves();

        // The probe: previousDisplacement against the CPU at t - dt.
        const std::vector<glm::vec4> points = spiralPoints(128, 3.0);
        const std::vector<glm::vec4> results = probeWaves(*r.water(), program->id(), points);
        double worst_prev = 0.0, largest_step = 0.0;
        for (std::size_t i = 0; i < points.size(); ++i) {
            const glm::dvec2 x0 = glm::dvec2(eye.x, eye.z) + glm::dvec2(points[i].x, points[i].y);
            const glm::dvec3 prev = evaluateWaves(waves, x0, t - dt, points[i].z).displacement;
            const glm::dvec3 now = evaluateWaves(waves, x0, t, points[i].z).displacement;
            worst_prev = std::max(worst_prev, glm::length(glm::dvec3(results[3 * i + 2]) - prev));
            largest_step = std::max(largest_step, glm::length(now - prev));
        }
        MESSAGE("previous displacement, GPU vs CPU at t - dt: " << worst_prev << " m (largest move in dt " << largest_step << " m)");
        CHECK(worst_prev < 1e-4);
        CHECK(largest_step > 0.01);  // the waves did move

        // The motion vectors over the sea against the CPU, pixel by pixel.
        const int w = view.width, h = view.height;
        REQUIRE(velocity.size() == std::size_t(w * h * 4));
        REQUIRE(depth.size() == std::size_t(w * h));
        const ViewMatrices m = viewMatrices(view);
        const glm::dmat4 inv(m.inv_view_proj), vp(m.view_proj);
        const WaterGrid grid = waterGrid(s.water, eye.y - double(s.water.level_m));
        std::vector<double> errors;
        double motion = 0.0;
        for (int row = 0; row < h; ++row)
            for (int x = 0; x < w; ++x) {
                const std::size_t i = std::size_t(row * w + x);
                const double d = depth[i];
                if (!(d > 0.0)) continue;
                const glm::dvec2 ndc((x + 0.5) / w * 2.0 - 1.0, 1.0 - (row + 0.5) / h * 2.0);
                const glm::dvec4 q = inv * glm::dvec4(ndc, d, 1.0);
                const glm::dvec3 p = glm::dvec3(q) / q.w;  // camera-relative surface point
                if (std::abs(p.y + eye.y - double(s.water.level_m)) > waves.max_height + 0.01) continue;  // not the sea
                // Its rest point: x0 = P.xz - D.xz(x0), by fixed-point iteration (chop < 1/k).
                const glm::dvec2 world(eye.x + p.x, eye.z + p.z);
                glm::dvec2 x0 = world;
                double footprint = 0.0;
                for (int k = 0; k < 30; ++k) {
                    footprint = (glm::length(x0 - glm::dvec2(eye.x, eye.z)) + grid.ring_constant) * grid.angle;
                    const glm::dvec3 dd = evaluateWaves(waves, x0, t, footprint).displacement;
                    x0 = world - glm::dvec2(dd.x, dd.z);
                }
                const glm::dvec3 prev_d = evaluateWaves(waves, x0, t - dt, footprint).displacement;
                const glm::dvec3 prev_p(x0.x - eye.x + prev_d.x, double(s.water.level_m) - eye.y + prev_d.y, x0.y - eye.z + prev_d.z);
                const glm::dvec4 c = vp * glm::dvec4(prev_p, 1.0);
                const glm::dvec2 expect = (ndc - glm::dvec2(c) / c.w) * 0.5;  // UV now minus UV before
                const glm::dvec2 got(velocity[i * 4], velocity[i * 4 + 1]);
                const glm::dvec2 px(w, h);
                errors.push_back(glm::length((got - expect) * px));
                motion += glm::length(expect * px);
            }
        REQUIRE(errors.size() > std::size_t(w * h / 4));
        motion /= double(errors.size());
        std::sort(errors.begin(), errors.end());
        const double median = errors[errors.size() / 2], p90 = errors[errors.size() * 9 / 10];
        MESSAGE("sea pixels " << errors.size() << ": mean wave motion " << motion << " px, error median " << median
                              << " px, p90 " << p90 << " px");
        CHECK(motion > 0.3);          // the still camera sees the waves move
        CHECK(median < 0.1 * motion);  // the camera's vectors alone (0 here) would be off by all of it
        CHECK(p90 < 0.3 * motion);
    }
}
