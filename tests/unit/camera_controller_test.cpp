// Free-fly camera maths: direction conventions, speed modifiers, frame-rate independence.
#include "app/camera_controller.h"
#include "renderer/camera.h"

#include <doctest/doctest.h>

#include <cmath>

using namespace vista;

TEST_CASE("camera: yaw 0 looks along -z, yaw 90 along +x, pitch up is +y") {
    auto f = directionFromAngles(0.0, 0.0);
    CHECK(f.z == doctest::Approx(-1.0));
    f = directionFromAngles(90.0, 0.0);
    CHECK(f.x == doctest::Approx(1.0));
    f = directionFromAngles(0.0, 90.0);
    CHECK(f.y == doctest::Approx(1.0));
}

TEST_CASE("camera: reversed-Z infinite projection maps near to 1 and far to 0") {
    ViewParams v;
    v.near_m = 0.5;
    v.width = 16;
    v.height = 9;
    ViewMatrices m = viewMatrices(v);
    auto depth = [&](double distance) {
        glm::vec4 clip = m.view_proj * glm::vec4(0.0f, 0.0f, float(-distance), 1.0f);
        return double(clip.z / clip.w);
    };
    CHECK(depth(0.5) == doctest::Approx(1.0));
    CHECK(depth(5.0) == doctest::Approx(0.1));
    CHECK(depth(1e9) < 1e-8);
    // Looking straight down keeps a well-defined right vector (no NaN).
    v.pitch_deg = -90.0;
    m = viewMatrices(v);
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) CHECK(std::isfinite(m.inv_view_proj[i][j]));
}

TEST_CASE("camera: W moves forward at move_speed, Shift and Ctrl scale it, Q/E move vertically") {
    CameraSettings s;
    s.position = {0.0, 10.0, 0.0};
    s.yaw_deg = 0.0f;
    s.pitch_deg = 0.0f;
    s.move_speed = 10.0f;
    CameraController c(s);
    CameraInput in;
    in.forward = 1.0f;
    for (int i = 0; i < 200; ++i) c.update(in, 0.01, s);  // 2 s, long past the 0.1 s ramp
    CHECK(c.velocity.z == doctest::Approx(-10.0).epsilon(1e-3));
    CHECK(c.position.x == doctest::Approx(0.0));
    in.fast = true;
    for (int i = 0; i < 200; ++i) c.update(in, 0.01, s);
    CHECK(-c.velocity.z == doctest::Approx(10.0 * s.fast_multiplier).epsilon(1e-3));
    in = CameraInput{};
    in.up = 1.0f;
    for (int i = 0; i < 200; ++i) c.update(in, 0.01, s);
    CHECK(c.velocity.y == doctest::Approx(10.0 * s.updown_speed).epsilon(1e-3));
    CHECK(std::abs(c.velocity.z) < 1e-3);
}

TEST_CASE("camera: the glide is frame-rate independent and looking clamps pitch") {
    CameraSettings s;
    s.move_speed = 10.0f;
    CameraController a(s), b(s);
    CameraInput in;
    in.forward = 1.0f;
    for (int i = 0; i < 10; ++i) a.update(in, 0.02, s);
    for (int i = 0; i < 40; ++i) b.update(in, 0.005, s);
    CHECK(glm::length(a.velocity - b.velocity) < 1e-9);
    CHECK(glm::length(a.position - b.position) < 1e-9);

    in = CameraInput{};
    in.look_dy = -1e6;  // mouse far up
    a.update(in, 0.01, s);
    CHECK(a.pitch_deg == doctest::Approx(89.0));
    in.scroll = 1000.0;
    a.update(in, 0.01, s);
    CHECK(a.fov_deg == doctest::Approx(5.0));
}

TEST_CASE("camera: terrain following keeps the eye height, the free camera stays above ground") {
    CameraSettings s;
    s.near_m = 0.1f;
    CameraController c(s);
    c.position = {10.0, 5.0, 20.0};
    c.velocity = {1.0, -3.0, 0.0};

    keepAboveGround(c, 12.0, s);  // free camera below a 12 m surface: lifted to just above it
    CHECK(c.position.y == doctest::Approx(12.2));
    CHECK(c.velocity.y == 0.0);
    keepAboveGround(c, 3.0, s);  // above the ground: untouched
    CHECK(c.position.y == doctest::Approx(12.2));

    s.allow_below_ground = true;
    c.position.y = -50.0;
    keepAboveGround(c, 3.0, s);
    CHECK(c.position.y == -50.0);

    s.follow_terrain = true;
    s.eye_height_m = 1.7f;
    keepAboveGround(c, 3.0, s);
    CHECK(c.position.y == doctest::Approx(4.7));
    keepAboveGround(c, 100.0, s);  // walking up a slope
    CHECK(c.position.y == doctest::Approx(101.7));
    CHECK(c.velocity.y == 0.0);
}
