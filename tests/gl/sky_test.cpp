// The GPU atmosphere under OSMesa: sky radiance from the LUTs against the double-precision CPU
// reference (PSNR over linear radiance normalised by the reference's maximum), finite output
// for extreme views, LUTs cached across frames, and the sun's position from the time of day.
#include "app/frame.h"
#include "app/scene.h"
#include "renderer_fixture.h"
#include "sky/atmosphere.h"
#include "sky/atmosphere_spectral.h"
#include "sky/sky_reference_image.h"
#include "terrain/heightmap.h"

#include <glm/geometric.hpp>
#include <glm/gtc/packing.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

using namespace vista;

namespace {

FrameRenderer& renderer() { return test::fileRenderer(); }

Settings skyOnly(float sun_elevation_deg, float sun_azimuth_deg = 180.0f) {
    Settings s;
    s.terrain.enabled = false;
    s.debug.grid = false;
    s.sky.sun_mode = SunMode::Angles;
    s.sky.sun_elevation_deg = sun_elevation_deg;
    s.sky.sun_azimuth_deg = sun_azimuth_deg;
    s.sky.sun_illuminance = 1.0f;
    s.sky.moon = false;  // the reference has neither moon nor stars
    s.sky.stars = false;
    s.clouds.enabled = false;  // nor clouds
    return s;
}

struct Rendered {
    std::vector<std::uint16_t> hdr;
    std::uint64_t nonfinite = 0;
    double pre_exposure = 1.0;  // the frame's (sky/night_light.h): hdr holds radiance times this
    bool shows_stars = false;   // the sky pass's variant has the star field (counter sky.shows_stars)
};

Rendered render(const Settings& s, const ViewParams& view) {
    FrameRenderer& r = renderer();
    REQUIRE(r.prepare(s).empty());
    Rendered out;
    FrameRequest request;
    request.capture_hdr = &out.hdr;
    request.count_nonfinite = true;
    r.resetHistory();  // a first frame: no TAA jitter or history, as the test expects
    const FrameReport report = r.render(s, view, 0.0, request);
    out.pre_exposure = report.counters.at("sky.pre_exposure");
    out.shows_stars = report.counters.at("sky.shows_stars") != 0.0;
    for (const auto& c : r.counters().collect(true)) out.nonfinite += c.value;
    return out;
}

const MultipleScatteringTable& referenceTable() {
    static const MultipleScatteringTable table(atmosphereParams(SkySettings{}));
    return table;
}

ViewParams view(double altitude_m, double yaw_deg, double pitch_deg, int width = 64, int height = 36) {
    return ViewParams{{0.0, altitude_m, 0.0}, yaw_deg, pitch_deg, 60.0, 0.5, width, height};
}

}  // namespace

TEST_CASE("gl: sky radiance from the GPU LUTs matches the CPU reference (noon, sunset, twilight)") {
    struct Case {
        const char* name;
        float sun_elevation;
        ViewParams view;
        double min_psnr;
    } cases[] = {
        {"noon, horizon away from the sun", 60.0f, view(2.0, 0.0, 10.0), 40.0},
        {"noon, towards the sun", 60.0f, view(2.0, 180.0, 40.0), 40.0},
        {"sunset, towards the sun at the horizon", 2.0f, view(2.0, 180.0, 5.0), 40.0},
        // Row 41 of 72 looks 0.005 deg above the horizon (2 m up, 0.045 deg dip), where the sky
        // is brightest and the ground 500x darker one row below: the horizon must stay sharp.
        {"sunset 128x72, a row 0.005 deg above the horizon", 2.0f, view(2.0, 180.0, 5.0, 128, 72), 40.0},
        {"sunset 160x90, towards the sun", 2.0f, view(2.0, 170.0, 8.0, 160, 90), 40.0},
        {"noon 160x90, horizon across the middle", 60.0f, view(2.0, 30.0, 0.0, 160, 90), 40.0},
        {"sunset, away from the sun", 2.0f, view(2.0, 0.0, 20.0), 40.0},
        {"twilight -6 deg, towards the sun", -6.0f, view(2.0, 180.0, 10.0), 40.0},
        {"twilight -6 deg, zenith", -6.0f, view(2.0, 90.0, 70.0), 40.0},
        {"noon from a mountain (4 km), looking down", 45.0f, view(4000.0, 90.0, -10.0), 40.0},
        {"sunset from 100 km, limb", 5.0f, view(99000.0, 150.0, -5.0), 35.0},
        {"orbit 400 km, limb", 20.0f, view(400000.0, 120.0, -15.0), 35.0},
    };
    for (const Case& c : cases) {
        CAPTURE(std::string(c.name));
        Settings s = skyOnly(c.sun_elevation);
        Rendered r = render(s, c.view);
        CHECK(r.nonfinite == 0);
        // The target holds radiance times the frame's pre-exposure (twilight is pre-exposed since
        // the night work); the reference is the radiance itself.
        if (r.pre_exposure != 1.0)
            for (std::uint16_t& h : r.hdr)
                h = std::uint16_t(glm::packHalf1x16(float(glm::unpackHalf1x16(h) / r.pre_exposure)));
        double psnr = skyPsnrDb(r.hdr, referenceSkyImage(s.sky, c.view, referenceTable()));
        MESSAGE(std::string(c.name) << ": " << psnr << " dB");
        CAPTURE(psnr);
        CHECK(psnr >= c.min_psnr);
    }
}

TEST_CASE("gl: extreme sky views give finite images") {
    struct Case {
        float sun_elevation;
        ViewParams view;
    } cases[] = {
        {90.0f, view(2.0, 0.0, 89.9)},        // straight up at the sun
        {30.0f, view(2.0, 0.0, -89.9)},       // straight down
        {-18.0f, view(2.0, 180.0, 5.0)},      // astronomical twilight
        {-18.0f, view(2.0, 0.0, 89.0)},
        {10.0f, view(400000.0, 0.0, -89.0)},  // orbit, looking down
        {-18.0f, view(400000.0, 180.0, -19.0)},
        {0.0f, view(1.0e7, 180.0, -30.0)},    // far beyond the atmosphere
        {0.0f, view(100000.0, 0.0, 0.0)},     // exactly at the top
        {-90.0f, view(-50.0, 0.0, 0.0)},      // below the ground, sun at the nadir
    };
    for (const Case& c : cases) {
        CAPTURE(c.sun_elevation);
        CAPTURE(c.view.position.y);
        CAPTURE(c.view.pitch_deg);
        Rendered r = render(skyOnly(c.sun_elevation), c.view);
        CHECK(r.nonfinite == 0);
        // With the moon, the stars and a dense fog whose base is far above the camera.
        Settings night = skyOnly(c.sun_elevation);
        night.sky.moon = night.sky.stars = night.sky.height_fog = true;
        night.sky.fog_density_per_km = 1000.0f;
        night.sky.fog_base_m = 100000.0f;
        night.sky.fog_falloff_m = 1.0f;
        CHECK(render(night, c.view).nonfinite == 0);
    }
}

TEST_CASE("gl: sky LUTs are built once and the sky view only when the sun moves") {
    FrameRenderer& r = renderer();
    Settings s = skyOnly(30.0f);
    s.sky.planet_radius_km = 6000.0f;  // a new atmosphere: every LUT is built
    render(s, view(2.0, 0.0, 10.0));
    REQUIRE(r.sky());
    SkyLutStats first = r.sky()->stats();
    render(s, view(2.0, 45.0, 10.0));  // turning the camera rebuilds nothing
    CHECK(r.sky()->stats().transmittance_builds == first.transmittance_builds);
    CHECK(r.sky()->stats().sky_view_builds == first.sky_view_builds);
    s.sky.sun_elevation_deg = 31.0f;  // the sun moves: only the sky view
    render(s, view(2.0, 45.0, 10.0));
    CHECK(r.sky()->stats().transmittance_builds == first.transmittance_builds);
    CHECK(r.sky()->stats().multiscatter_builds == first.multiscatter_builds);
    CHECK(r.sky()->stats().sky_view_builds == first.sky_view_builds + 1);
    s.sky.mie_g = 0.7f;  // the atmosphere changes: everything
    render(s, view(2.0, 45.0, 10.0));
    CHECK(r.sky()->stats().transmittance_builds == first.transmittance_builds + 1);
    CHECK(r.sky()->stats().sky_view_builds == first.sky_view_builds + 2);
}

TEST_CASE("gl: a sky frame does not depend on the frames drawn before it") {
    // The sky-view LUT is reused while the sun and the camera move less than a grid step; the
    // grid (not the last rebuild) decides what it holds, so the history cannot show.
    Settings s = skyOnly(12.345f);
    Settings before_a = skyOnly(12.36f), before_b = skyOnly(12.33f);
    render(before_a, view(2.4, 180.0, 5.0));
    Rendered a = render(s, view(2.0, 180.0, 5.0));
    render(before_b, view(1.7, 180.0, 5.0));
    Rendered b = render(s, view(2.0, 180.0, 5.0));
    CHECK(a.hdr == b.hdr);
}

namespace {

// A flat map 1000 km wide with its ground at 50 m (heightmap 0.5 x 100 m) and a sky-only scene.
Settings flatGround(const test::TempDir& dir, float sun_elevation, float sun_azimuth) {
    Heightmap map{65, 65, std::vector<float>(65 * 65, 0.5f)};
    REQUIRE(saveHeightmapPng16(dir.path / "flat.png", map).empty());
    Settings s = skyOnly(sun_elevation, sun_azimuth);
    s.terrain.enabled = true;
    s.terrain.heightmap = (dir.path / "flat.png").string();
    s.terrain.size_m = 1.0e6f;
    s.terrain.height_scale_m = 100.0f;
    return s;
}
constexpr double kFlatGroundM = 100.0 * (32768.0 / 65535.0);

struct AerialError {
    int ground = 0, sky_changed = 0;
    double psnr = 0.0, worst = 0.0;  // relative to the largest change the haze makes
};

// Renders v without and with aerial perspective. Each ground pixel's distance is known, so the
// haze must turn plain into plain * T + S, with T and S integrated on the CPU from the camera to
// the ground along the same ray (pixels near the horizon or beyond max_t_m are left out).
AerialError aerialError(Settings s, const ViewParams& v, double max_t_m) {
    s.sky.aerial_perspective = false;
    Rendered plain = render(s, v);
    s.sky.aerial_perspective = true;
    Rendered hazy = render(s, v);
    CHECK(hazy.nonfinite == 0);

    const AtmosphereParams p = atmosphereParams(s.sky);
    const glm::dvec3 sun = sunDirection(s.sky);
    const glm::dmat3 colour = skyColourMatrix(sun.y);
    const glm::dmat4 inv(viewMatrices(v).inv_view_proj);
    const double camera_m = v.position.y;
    AerialError out;
    std::vector<glm::dvec3> expected, got, before;
    for (int y = 0; y < v.height; ++y)
        for (int x = 0; x < v.width; ++x) {
            std::size_t i = std::size_t(y * v.width + x);
            glm::dvec2 uv((x + 0.5) / v.width, 1.0 - (y + 0.5) / v.height);
            glm::dvec4 q = inv * glm::dvec4(uv * 2.0 - 1.0, 0.5, 1.0);
            glm::dvec3 d = glm::normalize(glm::dvec3(q) / q.w);
            glm::dvec3 b, a;
            for (int c = 0; c < 3; ++c) {
                b[c] = glm::unpackHalf1x16(plain.hdr[i * 4 + std::size_t(c)]);
                a[c] = glm::unpackHalf1x16(hazy.hdr[i * 4 + std::size_t(c)]);
            }
            const double t = d.y < 0.0 ? (camera_m - kFlatGroundM) / -d.y : 0.0;
            if (d.y > -0.02 || t > max_t_m) {
                if (d.y > 0.0 && a != b) ++out.sky_changed;
                continue;
            }
            ViewRayResult r = integrateViewRay(p, {0.0, camera_m, 0.0}, d, sun, t, {64, 64}, &referenceTable());
            // The volume holds in-scatter in HDR RGB: the samples through the frame's colour matrix.
            expected.push_back(b * r.transmittance + colour * r.radiance * double(s.sky.sun_illuminance));
            got.push_back(a);
            before.push_back(b);
        }
    out.ground = int(expected.size());
    double peak = 0.0, sum = 0.0;
    for (std::size_t i = 0; i < expected.size(); ++i) {
        const glm::dvec3 change = glm::abs(expected[i] - before[i]);
        peak = std::max({peak, change.x, change.y, change.z});
    }
    for (std::size_t i = 0; i < expected.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            double e = (got[i][c] - expected[i][c]) / peak;
            sum += e * e;
            out.worst = std::max(out.worst, std::abs(e));
        }
    out.psnr = out.ground > 0 ? 10.0 * std::log10(1.0 / (sum / (3.0 * out.ground))) : 0.0;
    return out;
}

}  // namespace

TEST_CASE("gl: aerial perspective on the ground matches the CPU reference along the same segment") {
    test::TempDir dir("aerial");
    Settings s = flatGround(dir, 10.0f, 200.0f);
    // 200 m above the ground looking down 12 deg, the sun 50 deg to the right: ground from
    // 250 m to the volume's reach.
    AerialError e = aerialError(s, ViewParams{{0.0, 250.0, 0.0}, 150.0, -12.0, 60.0, 0.5, 96, 54},
                                0.9 * s.sky.aerial_distance_km * 1e3);
    MESSAGE("aerial perspective near the ground: " << e.ground << " pixels, " << e.psnr << " dB, worst " << e.worst);
    REQUIRE(e.ground > 1000);
    CHECK(e.psnr >= 40.0);
    CHECK(e.worst < 0.05);
    CHECK(e.sky_changed == 0);  // the sky is the sky pass's alone

    // From orbit the volume starts at the top of the atmosphere and reaches the ground through it.
    AerialError orbit = aerialError(s, ViewParams{{0.0, 400000.0, 0.0}, 150.0, -60.0, 40.0, 0.5, 64, 36}, 1e9);
    MESSAGE("aerial perspective from 400 km: " << orbit.ground << " pixels, " << orbit.psnr << " dB, worst " << orbit.worst);
    REQUIRE(orbit.ground > 1000);
    CHECK(orbit.psnr >= 30.0);
}

TEST_CASE("gl: height fog thickens the haze, reaches the sky view, and aerial perspective off adds no pass") {
    test::TempDir dir("fog");
    Settings s = flatGround(dir, 10.0f, 200.0f);
    const ViewParams v{{0.0, 250.0, 0.0}, 150.0, -12.0, 60.0, 0.5, 96, 54};
    FrameRenderer& r = renderer();
    REQUIRE(r.prepare(s).empty());
    std::vector<std::uint16_t> hdr;
    FrameRequest request;
    request.capture_hdr = &hdr;
    r.resetHistory();  // a first frame: no TAA jitter or history, as the test expects
    FrameReport clear = r.render(s, v, 0.0, request);
    auto has = [](const FrameReport& rep, const char* pass) {
        return std::find(rep.executed.begin(), rep.executed.end(), pass) != rep.executed.end();
    };
    CHECK(has(clear, "sky.aerial_volume"));
    CHECK(has(clear, "sky.aerial"));
    std::vector<std::uint16_t> clear_hdr = hdr;

    s.sky.height_fog = true;
    s.sky.fog_density_per_km = 2.0f;
    s.sky.fog_base_m = 50.0f;
    s.sky.fog_falloff_m = 300.0f;
    Rendered fog = render(s, v);
    CHECK(fog.nonfinite == 0);
    // Far ground (top ground rows) loses its own colour: closer to the fogged horizon sky above it.
    auto pixel = [&](const std::vector<std::uint16_t>& img, int x, int y) {
        std::size_t i = std::size_t(y * v.width + x) * 4;
        return glm::vec3(glm::unpackHalf1x16(img[i]), glm::unpackHalf1x16(img[i + 1]), glm::unpackHalf1x16(img[i + 2]));
    };
    const int x = v.width / 2, horizon_y = 19, far_ground_y = 24, near_ground_y = 50;
    auto contrast = [&](const std::vector<std::uint16_t>& img) {
        glm::vec3 a = pixel(img, x, far_ground_y), b = pixel(img, x, horizon_y);
        return glm::length(a - b) / std::max(glm::length(b), 1e-6f);
    };
    CHECK(contrast(fog.hdr) < contrast(clear_hdr));
    CHECK(pixel(fog.hdr, x, near_ground_y) != pixel(clear_hdr, x, near_ground_y));
    CHECK(pixel(fog.hdr, x, 2) != pixel(clear_hdr, x, 2));  // the sky view sees the fog too

    s.sky.aerial_perspective = false;
    r.resetHistory();  // a first frame: no TAA jitter or history, as the test expects
    FrameReport off = r.render(s, v, 0.0, request);
    CHECK_FALSE(has(off, "sky.aerial_volume"));
    CHECK_FALSE(has(off, "sky.aerial"));
    CHECK(has(off, "sky.atmosphere"));
}

TEST_CASE("gl: the moon's lit fraction and side follow the sun (full, quarter, crescent, eclipse)") {
    // The moon fills the middle of a 2 deg view (8 px radius); the lit part of its disk is
    // compared with the illuminated fraction (1 - cos elongation) / 2.
    const ViewParams v{{0.0, 2.0, 0.0}, 0.0, 30.0, 2.0, 0.5, 64, 64};
    const glm::dvec3 moon = glm::normalize(directionFromAngles(0.0, 30.0));
    struct Case {
        const char* name;
        float sun_azimuth, sun_elevation;
    } cases[] = {
        {"full (sun opposite, below the horizon)", 180.0f, -30.0f},
        {"first quarter (sun 90 deg east)", 90.0f, 0.0f},
        {"crescent (sun 60 deg away, below the moon)", 0.0f, -30.0f},
    };
    const glm::dmat4 inv(viewMatrices(v).inv_view_proj);
    for (const Case& c : cases) {
        CAPTURE(std::string(c.name));
        Settings s = skyOnly(c.sun_elevation, c.sun_azimuth);
        Rendered without = render(s, v);
        s.sky.moon = true;
        s.sky.moon_azimuth_deg = 0.0f;
        s.sky.moon_elevation_deg = 30.0f;
        Rendered with = render(s, v);
        CHECK(with.nonfinite == 0);
        const glm::dvec3 sun = sunDirection(s.sky);
        const double expected = (1.0 - glm::dot(moon, sun)) / 2.0;
        int disk = 0, lit = 0;
        double lit_x = 0.0;
        double peak = 0.0;
        for (std::size_t i = 0; i < std::size_t(v.width * v.height); ++i)
            peak = std::max(peak, double(glm::unpackHalf1x16(with.hdr[i * 4])) - glm::unpackHalf1x16(without.hdr[i * 4]));
        for (int y = 0; y < v.height; ++y)
            for (int x = 0; x < v.width; ++x) {
                glm::dvec2 uv((x + 0.5) / v.width, 1.0 - (y + 0.5) / v.height);
                glm::dvec4 q = inv * glm::dvec4(uv * 2.0 - 1.0, 0.5, 1.0);
                glm::dvec3 d = glm::normalize(glm::dvec3(q) / q.w);
                if (std::acos(std::clamp(glm::dot(d, moon), -1.0, 1.0)) > glm::radians(0.2587 - 2.0 / 64.0))
                    continue;  // inside the disk, a pixel from its edge
                ++disk;
                std::size_t i = std::size_t(y * v.width + x) * 4;
                if (glm::unpackHalf1x16(with.hdr[i]) - glm::unpackHalf1x16(without.hdr[i]) > 0.02 * peak) {
                    ++lit;
                    lit_x += x - (v.width - 1) * 0.5;
                }
            }
        REQUIRE(disk > 100);
        const double fraction = double(lit) / disk;
        MESSAGE(std::string(c.name) << ": lit " << fraction << " of the disk, expected " << expected);
        CHECK(std::abs(fraction - expected) < 0.12);
        if (c.sun_azimuth == 90.0f) CHECK(lit_x > 0.0);  // the sun to the right (east) lights the right half
    }

    // A solar eclipse: the moon in front of the sun shows its dark side and hides the disk.
    Settings s = skyOnly(30.0f, 0.0f);
    s.sky.moon = true;
    s.sky.moon_azimuth_deg = 0.0f;
    s.sky.moon_elevation_deg = 30.0f;
    Rendered eclipse = render(s, v);
    s.sky.moon = false;
    Rendered sun = render(s, v);
    const std::size_t centre = std::size_t((v.height / 2) * v.width + v.width / 2) * 4;
    CHECK(glm::unpackHalf1x16(eclipse.hdr[centre]) < 0.01f * glm::unpackHalf1x16(sun.hdr[centre]));
}

TEST_CASE("gl: stars show at night, fade at dusk and are gone by day") {
    const ViewParams v{{0.0, 2.0, 0.0}, 0.0, 60.0, 60.0, 0.5, 96, 54};
    auto starPixels = [&](float sun_elevation) {
        Settings s = skyOnly(sun_elevation, 180.0f);
        Rendered off = render(s, v);
        s.sky.stars = true;
        Rendered on = render(s, v);
        CHECK(on.nonfinite == 0);
        // The star field is in the program only when a sky dark enough for it is possible.
        CHECK(on.shows_stars == (sun_elevation < 0.0f));
        CHECK_FALSE(off.shows_stars);
        std::pair<int, double> stars{0, 0.0};  // pixels well above the sky, and the starlight added
        for (std::size_t i = 0; i < std::size_t(v.width * v.height); ++i) {
            const float a = glm::unpackHalf1x16(off.hdr[i * 4 + 1]), b = glm::unpackHalf1x16(on.hdr[i * 4 + 1]);
            stars.first += b > 2.0f * a + 1e-9f;
            stars.second += std::max(double(b - a), 0.0);
        }
        return stars;
    };
    const auto night = starPixels(-18.0f), dusk = starPixels(-4.0f), day = starPixels(30.0f);
    MESSAGE("star pixels (starlight): night " << night.first << " (" << night.second << "), dusk " << dusk.first << " ("
                                             << dusk.second << "), day " << day.first << " (" << day.second << ")");
    CHECK(night.first > 50);
    CHECK(dusk.second < 0.8 * night.second);
    CHECK(day.first == 0);
    CHECK(day.second < 1e-3 * night.second);  // the dither alone
}
