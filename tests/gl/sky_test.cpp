// The GPU atmosphere under OSMesa: sky radiance from the LUTs against the double-precision CPU
// reference (PSNR over linear radiance normalised by the reference's maximum), finite output
// for extreme views, LUTs cached across frames, and the sun's position from the time of day.
#include "app/frame.h"
#include "app/scene.h"
#include "gl_fixture.h"
#include "sky/atmosphere.h"
#include "sky/sky_reference_image.h"

#include <string>

using namespace vista;

namespace {

FrameRenderer& renderer() {
    test::glContext();
    static FrameRenderer r(vistaRoot());
    return r;
}

Settings skyOnly(float sun_elevation_deg, float sun_azimuth_deg = 180.0f) {
    Settings s;
    s.terrain.enabled = false;
    s.debug.grid = false;
    s.sky.sun_mode = SunMode::Angles;
    s.sky.sun_elevation_deg = sun_elevation_deg;
    s.sky.sun_azimuth_deg = sun_azimuth_deg;
    s.sky.sun_illuminance = 1.0f;
    return s;
}

struct Rendered {
    std::vector<std::uint16_t> hdr;
    std::uint64_t nonfinite = 0;
};

Rendered render(const Settings& s, const ViewParams& view) {
    FrameRenderer& r = renderer();
    REQUIRE(r.prepare(s).empty());
    Rendered out;
    FrameRequest request;
    request.capture_hdr = &out.hdr;
    request.count_nonfinite = true;
    r.render(s, view, 0.0, request);
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
        CAPTURE(c.name);
        Settings s = skyOnly(c.sun_elevation);
        Rendered r = render(s, c.view);
        CHECK(r.nonfinite == 0);
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
