// Weather under OSMesa: off there is no weather pass and no Weather object, and switching it on
// and off between frames works; on, weather.rain (and weather.splash) run after the sky with
// finite HDR output at the origin, 10,000 km out and at t = 10^7 s, for rain and snow; drops
// show against the sky and are hidden behind nearer terrain (depth test); splashes land on the
// ground; rain darkens the terrain's albedo; rainRippleNormal on the GPU matches its CPU mirror;
// near drops write their fall into the motion vectors (weather.velocity).
#include "app/frame.h"
#include "renderer/half.h"
#include "renderer/temporal.h"
#include "renderer_fixture.h"
#include "sky/weather/weather_model.h"
#include "terrain/heightmap.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <glm/geometric.hpp>

using namespace vista;

namespace {

FrameRenderer& renderer() { return test::compiledFileRenderer(); }

constexpr int kMapSamples = 65;
constexpr float kMapSize = 256.0f;
constexpr float kHeightScale = 100.0f;
constexpr float kGround = 0.3f * kHeightScale;  // the flat map's height (m)

std::filesystem::path flatMap(const test::TempDir& dir) {
    Heightmap map{kMapSamples, kMapSamples, std::vector<float>(std::size_t(kMapSamples) * kMapSamples, 0.3f)};
    std::filesystem::path file = dir.path / "flat.png";
    REQUIRE(saveHeightmapPng16(file, map).empty());
    return file;
}

Settings weatherScene(const std::filesystem::path& map, const glm::dvec3& origin = glm::dvec3(0.0)) {
    Settings s;
    s.terrain.heightmap = map.string();
    s.terrain.size_m = kMapSize;
    s.terrain.height_scale_m = kHeightScale;
    s.terrain.origin = origin;
    s.grass.enabled = false;
    s.clouds.enabled = false;
    s.debug.grid = false;
    s.lights.enabled = false;
    // No TAA jitter or history, as the image checks expect; not resetHistory() per frame, which
    // would also forget weather's previous camera (the streak velocity the tests check).
    s.taa.enabled = false;
    s.weather.enabled = true;
    s.weather.intensity = 1.0f;
    return s;
}

struct Frame {
    FrameReport report;
    std::vector<float> hdr;  // RGB, top row first
    std::uint64_t drops = 0, splashes = 0, nonfinite = 0;
};

Frame render(const Settings& s, const ViewParams& view, double t, bool ldr = false) {
    FrameRenderer& r = renderer();
    REQUIRE(r.prepare(s).empty());
    FrameRequest request;
    request.count_weather = true;
    request.count_nonfinite = true;
    test::RenderedFrame rendered = test::renderFrame(r, s, view, t, request, ldr);
    Frame f{std::move(rendered.report), {}, rendered.counter("weather.drops"), rendered.counter("weather.splashes"),
            rendered.counter("nonfinite_pixels")};
    const std::size_t n = rendered.rgba.size() / 4;
    f.hdr.resize(n * 3);
    for (std::size_t i = 0; i < n; ++i)
        for (int c = 0; c < 3; ++c) f.hdr[i * 3 + std::size_t(c)] = rendered.rgba[i * 4 + std::size_t(c)];
    return f;
}

bool has(const std::vector<std::string>& v, const std::string& name) {
    return std::find(v.begin(), v.end(), name) != v.end();
}

bool anyWeather(const FrameReport& r) {
    auto weather = [](const std::string& n) { return n.rfind("weather.", 0) == 0; };
    return std::any_of(r.executed.begin(), r.executed.end(), weather) || std::any_of(r.culled.begin(), r.culled.end(), weather);
}

// Pixels whose RGB differ by more than a relative tolerance, and the largest difference.
int differing(const Frame& a, const Frame& b, float& worst) {
    int n = 0;
    worst = 0.0f;
    for (std::size_t i = 0; i < a.hdr.size(); i += 3) {
        float d = 0.0f;
        for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(a.hdr[i + std::size_t(c)] - b.hdr[i + std::size_t(c)]));
        worst = std::max(worst, d);
        n += d > 1e-3f * (1.0f + a.hdr[i + 1]);
    }
    return n;
}

ViewParams view(glm::dvec3 at, double yaw, double pitch) { return ViewParams{at, yaw, pitch, 60.0, 0.1, 160, 90}; }

}  // namespace

TEST_CASE("gl: weather off adds no pass and no object and follows being switched on and off between frames") {
    test::TempDir dir("weather-switch");
    Settings s = weatherScene(flatMap(dir));
    s.weather.enabled = false;
    const ViewParams v = view({0.0, kGround + 1.7, 0.0}, 0.0, 10.0);
    Frame off = render(s, v, 1.0);
    CHECK_FALSE(anyWeather(off.report));
    CHECK(renderer().weather() == nullptr);
    CHECK(off.report.counters.count("weather.drop_candidates") == 0);

    s.weather.enabled = true;  // as the panel does: the next frame rains
    Frame on = render(s, v, 1.1);
    CHECK(has(on.report.executed, "weather.rain"));
    CHECK(has(on.report.executed, "weather.splash"));
    CHECK(renderer().weather() != nullptr);
    CHECK(on.drops > 100);
    CHECK(on.nonfinite == 0);
    const auto& ex = on.report.executed;
    auto at = [&](const char* name) { return std::find(ex.begin(), ex.end(), name) - ex.begin(); };
    CHECK(at("sky.atmosphere") < at("weather.rain"));
    CHECK(at("weather.rain") < at("weather.splash"));
    CHECK(on.report.counters.at("weather.drop_candidates") >= double(on.drops));

    s.weather.enabled = false;
    Frame again = render(s, v, 1.2);
    CHECK_FALSE(anyWeather(again.report));
    CHECK(renderer().weather() == nullptr);
    float worst = 0.0f;
    CHECK(differing(off, again, worst) == 0);  // dry again: the frame is as before

    // Snow has no splashes; without terrain there is nothing to splash on either.
    s.weather.enabled = true;
    s.weather.kind = WeatherKind::Snow;
    s.weather.drop_speed_m_s = 1.0f;
    Frame snow = render(s, v, 1.3);
    CHECK(has(snow.report.executed, "weather.rain"));
    CHECK_FALSE(has(snow.report.executed, "weather.splash"));
    CHECK(snow.drops > 100);
    CHECK(snow.nonfinite == 0);
    s.weather.kind = WeatherKind::Rain;
    s.terrain.enabled = false;
    Frame bare = render(s, v, 1.4);
    CHECK(has(bare.report.executed, "weather.rain"));
    CHECK_FALSE(has(bare.report.executed, "weather.splash"));
}

TEST_CASE("gl: rain and snow give finite HDR images at the origin, 10,000 km out and at t = 10^7 s, also moving fast") {
    test::TempDir dir("weather-extreme");
    const auto map = flatMap(dir);
    struct Case {
        glm::dvec3 origin;
        double t;
        WeatherKind kind;
        double pitch;
    } cases[] = {
        {{0.0, 0.0, 0.0}, 5.0, WeatherKind::Rain, 0.0},
        {{1.0e7, 0.0, -1.0e7}, 5.0, WeatherKind::Rain, -20.0},
        {{0.0, 0.0, 0.0}, 1.0e7, WeatherKind::Rain, 30.0},
        {{1.0e7, 0.0, -1.0e7}, 1.0e7, WeatherKind::Rain, 89.0},    // straight up into the rain
        {{1.0e7, 0.0, -1.0e7}, 1.0e7, WeatherKind::Snow, -89.0},   // straight down
        {{-1.0e7, 0.0, 1.0e7}, 1.0e7 + 0.37, WeatherKind::Snow, 5.0},
    };
    for (const Case& c : cases) {
        Settings s = weatherScene(map, c.origin);
        s.weather.kind = c.kind;
        INFO("origin " << c.origin.x << " t " << c.t << " pitch " << c.pitch);
        const ViewParams v = view(c.origin + glm::dvec3(3.0, kGround + 1.7, -2.0), 30.0, c.pitch);
        render(s, v, c.t - 0.05);
        // The camera moved 2 m in 50 ms (40 m/s): streaks lean into the motion, still finite.
        const ViewParams moved = view(v.position + glm::dvec3(2.0, 0.0, 0.0), 30.0, c.pitch);
        Frame f = render(s, moved, c.t);
        CHECK(has(f.report.executed, "weather.rain"));
        CHECK(f.nonfinite == 0);
        CHECK(f.drops > 50);
        const glm::dvec3 velocity = renderer().weather()->stats().camera_velocity;
        CHECK(velocity.x == doctest::Approx(40.0).epsilon(1e-3));
        for (float x : f.hdr) REQUIRE(std::isfinite(x));
    }
}

TEST_CASE("gl: drops show against the sky and are hidden behind nearer terrain") {
    test::TempDir dir("weather-depth");
    Settings s = weatherScene(flatMap(dir));
    s.weather.splashes = false;
    s.weather.wetness = 0.0f;
    s.weather.near_fade_m = 3.0f;  // drops start 3 m out
    Settings dry = s;
    dry.weather.enabled = false;

    // Looking up: only sky behind the drops.
    const ViewParams up = view({0.0, kGround + 1.7, 0.0}, 0.0, 35.0);
    Frame sky_dry = render(dry, up, 2.0), sky_rain = render(s, up, 2.0);
    float worst = 0.0f;
    const int changed = differing(sky_dry, sky_rain, worst);
    std::printf("weather: %d of %d sky pixels changed by rain (largest %.3g)\n", changed, 160 * 90, worst);
    CHECK(changed > 160 * 90 / 50);
    CHECK(sky_rain.drops > 100);

    // Looking down from 1 m: the ground is nearer than any drop, so none may show.
    const ViewParams down = view({0.0, kGround + 1.0, 0.0}, 0.0, -60.0);
    Frame ground_dry = render(dry, down, 2.0), ground_rain = render(s, down, 2.0);
    CHECK(has(ground_rain.report.executed, "weather.rain"));
    CHECK(ground_rain.drops > 100);  // drawn (in front of the camera) ...
    CHECK(differing(ground_dry, ground_rain, worst) == 0);  // ... and all behind the ground
    CHECK(worst == 0.0f);
}

TEST_CASE("gl: splashes land on the ground and rain darkens the terrain") {
    test::TempDir dir("weather-ground");
    Settings s = weatherScene(flatMap(dir));
    s.weather.near_fade_m = 10.0f;  // no drop nearer than 10 m ...
    s.weather.radius_m = 8.0f;      // ... and none farther than 8 m: splashes alone
    s.weather.wetness = 0.0f;
    s.sky.aerial_perspective = false;
    Settings no_splash = s;
    no_splash.weather.splashes = false;
    const ViewParams down = view({0.0, kGround + 1.7, 0.0}, 0.0, -45.0);
    Frame plain = render(no_splash, down, 3.0), splashed = render(s, down, 3.0);
    CHECK(has(splashed.report.executed, "weather.splash"));
    CHECK(splashed.splashes > 20);
    CHECK(plain.drops == 0);
    float worst = 0.0f;
    const int changed = differing(plain, splashed, worst);
    std::printf("weather: %d pixels changed by splashes (largest %.3g)\n", changed, worst);
    CHECK(changed > 10);
    CHECK(splashed.nonfinite == 0);

    // Wet ground: the G-buffer albedo (debug view) is darker.
    no_splash.debug.view = DebugView::Albedo;
    Settings wet = no_splash;
    wet.weather.wetness = 1.0f;
    Frame albedo_dry = render(no_splash, down, 3.0, true), albedo_wet = render(wet, down, 3.0, true);
    double sum_dry = 0.0, sum_wet = 0.0;
    for (float x : albedo_dry.hdr) sum_dry += x;
    for (float x : albedo_wet.hdr) sum_wet += x;
    std::printf("weather: wet/dry albedo (display) %.3f\n", sum_wet / sum_dry);
    CHECK(sum_wet < 0.9 * sum_dry);
    CHECK(sum_wet > 0.3 * sum_dry);
}

TEST_CASE("gl: rainRippleNormal on the GPU matches the double-precision CPU mirror") {
    FrameRenderer& r = renderer();
    const int w = 96, h = 64;
    const std::vector<float> texels = test::drawProbe(r.shaders(), "tests/gl/shaders/rain_ripples_probe.glsl", w, h);
    double worst = 0.0, tilted = 0.0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            // As the probe computes its inputs, in float.
            const glm::dvec2 xz(float(x) * 0.0131f + 0.003f, float(y) * 0.0173f + 0.007f);
            const double t = double(float(x + y) * 0.0371f);
            const float* px = &texels[(std::size_t(y) * std::size_t(w) + std::size_t(x)) * 4];
            const glm::dvec3 cpu = rainRippleNormal(xz, t, 0.8);
            worst = std::max(worst, glm::length(glm::dvec3(px[0], px[1], px[2]) - cpu));
            tilted = std::max(tilted, std::sqrt(cpu.x * cpu.x + cpu.z * cpu.z));
            CHECK(px[3] == 1.0f);  // intensity 0: exactly flat
        }
    std::printf("rain ripple probe: worst |GPU - CPU| %.2e, largest tilt %.2f\n", worst, tilted);
    CHECK(tilted > 0.1);
    CHECK(worst < 2e-3);
}

TEST_CASE("gl: rain writes its drops' fall into the motion vectors, as the CPU placement and wind say") {
    // Two frames dt apart, the camera moving a little: where a near drop is what a pixel shows,
    // the motion vector is that drop point's motion (its fall and the wind, and the camera's),
    // from the CPU mirror of the placement; camera-only vectors would miss the fall. Wide drops
    // against the sky, so many pass the opacity weather.velocity asks for.
    test::TempDir dir("weather-velocity");
    const auto map = flatMap(dir);
    const double dt = 0.1;
    for (auto [origin, t] : {std::pair{glm::dvec3(0.0), 10.0}, std::pair{glm::dvec3(1.0e7, 0.0, -1.0e7), 1.0e7}}) {
        CAPTURE(origin.x);
        Settings s = weatherScene(map, origin);
        s.weather.splashes = false;
        s.weather.drop_width_m = 0.03f;
        s.weather.near_fade_m = 0.5f;
        const ViewParams before = view(origin + glm::dvec3(0.0, kGround + 1.7, 0.0), 20.0, 35.0);
        ViewParams now = before;
        now.position += glm::dvec3(0.05, 0.0, 0.02);
        now.yaw_deg += 0.3;
        FrameRenderer& r = renderer();
        REQUIRE(r.prepare(s).empty());
        r.resetHistory();
        r.render(s, before, t - dt, FrameRequest{});
        std::vector<float> velocity;
        FrameRequest request;
        request.velocity = &velocity;
        const FrameReport report = r.render(s, now, t, request);
        CHECK(has(report.executed, "weather.velocity"));
        const int w = now.width, h = now.height;
        REQUIRE(velocity.size() == std::size_t(w * h * 4));

        const DropLayout layout = dropLayout(s.weather);
        const DropFrame frame = dropFrame(layout, now.position, dropFieldOffset(s.weather, s.clouds, t), t);
        const int per_cell = dropsDrawnPerCell(layout, s.weather.intensity);
        const double keep_below = double(s.weather.intensity) * layout.drops_per_cell;
        const glm::dvec2 wind = weatherWindVelocity(s.weather, s.clouds, t);
        const glm::dvec3 fall(wind.x, -double(s.weather.drop_speed_m_s), wind.y);
        const glm::dmat4 vp(viewMatrices(now).view_proj);
        const glm::dmat4 prev_clip = previousClipFromRelative(before, now);
        auto ndcOf = [](const glm::dvec4& c) { return glm::dvec2(c) / c.w; };
        std::vector<double> errors, camera_only;
        double motion = 0.0;
        for (int z = 0; z < layout.cells; ++z)
            for (int y = 0; y < layout.cells; ++y)
                for (int x = 0; x < layout.cells; ++x)
                    for (int j = 0; j < per_cell; ++j) {
                        const Drop drop = dropAt(layout, frame, {x, y, z}, j);
                        const double d = glm::length(drop.rel);
                        if (double(j) + drop.keep >= keep_below || d < 1.5 || d > 6.0) continue;  // not drawn, or faint
                        const glm::dvec4 clip = vp * glm::dvec4(drop.rel, 1.0);
                        if (!(clip.w > 0.0)) continue;
                        const glm::dvec2 ndc = ndcOf(clip);
                        const int px = int(std::floor((ndc.x * 0.5 + 0.5) * w)), row = int(std::floor((0.5 - ndc.y * 0.5) * h));
                        if (px < 0 || px >= w || row < 0 || row >= h) continue;
                        const std::size_t i = std::size_t(row * w + px);
                        const glm::dvec2 expect = (ndc - ndcOf(prev_clip * glm::dvec4(drop.rel - fall * dt, 1.0))) * 0.5;
                        const glm::dvec2 camera = (ndc - ndcOf(prev_clip * glm::dvec4(drop.rel, 1.0))) * 0.5;
                        const glm::dvec2 got(velocity[i * 4], velocity[i * 4 + 1]);
                        const glm::dvec2 size(w, h);
                        errors.push_back(glm::length((got - expect) * size));
                        camera_only.push_back(glm::length((camera - expect) * size));
                        motion += glm::length((expect - camera) * size);
                    }
        REQUIRE(errors.size() > 20);
        motion /= double(errors.size());
        std::sort(errors.begin(), errors.end());
        std::sort(camera_only.begin(), camera_only.end());
        const double median = errors[errors.size() / 2], camera_median = camera_only[camera_only.size() / 2];
        MESSAGE("drops " << errors.size() << ": fall motion " << motion << " px; error median " << median
                         << " px, p75 " << errors[errors.size() * 3 / 4] << " px; camera-only vectors off by "
                         << camera_median << " px (median)");
        CHECK(motion > 1.0);                   // the drops fall well beyond the camera's motion
        CHECK(median < 0.05 * motion);         // each head pixel follows its drop
        CHECK(camera_median > 0.5 * motion);   // the camera's vectors alone would not
    }
}
