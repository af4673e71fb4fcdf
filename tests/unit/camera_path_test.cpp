// Camera path parsing (errors located by line) and interpolation (through the keys, C1 in
// time, shortest-arc yaw, no NaN on repeated positions).
#include "app/camera_path.h"
#include "app/scene.h"
#include "terrain/heightmap.h"

#include <doctest/doctest.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

using vista::CameraKey;
using vista::CameraPath;
using vista::CameraPose;
using vista::InputErrors;
using vista::Heightmap;
using vista::loadHeightmap;

namespace {

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

CameraKey key(double t, glm::dvec3 p, double yaw, double pitch = -10.0, double fov = 60.0) {
    return {t, CameraPose{p, yaw, pitch, fov}};
}

// Uneven time spacing and uneven distances between keys, turning through the yaw seam.
CameraPath unevenPath() {
    return CameraPath({key(0.0, {0, 100, 0}, 10.0, -10.0, 60.0), key(1.0, {300, 120, -50}, 60.0, -20.0, 50.0),
                       key(4.5, {320, 90, -400}, 150.0, -5.0, 70.0), key(5.0, {900, 200, -420}, -150.0, -30.0, 65.0),
                       key(9.0, {950, 210, 600}, -100.0, 10.0, 40.0), key(10.0, {-200, 80, 650}, -60.0, -15.0, 60.0)});
}

// Second-order one-sided derivatives of f at t.
template <class F>
auto leftDerivative(const F& f, double t, double h) {
    return (3.0 * f(t) - 4.0 * f(t - h) + f(t - 2.0 * h)) / (2.0 * h);
}
template <class F>
auto rightDerivative(const F& f, double t, double h) {
    return (-3.0 * f(t) + 4.0 * f(t + h) - f(t + 2.0 * h)) / (2.0 * h);
}

bool finite(const CameraPose& p) {
    return std::isfinite(p.position.x) && std::isfinite(p.position.y) && std::isfinite(p.position.z) &&
           std::isfinite(p.yaw_deg) && std::isfinite(p.pitch_deg) && std::isfinite(p.fov_deg);
}

double angleDiff(double a, double b) { return std::remainder(a - b, 360.0); }

}  // namespace

TEST_CASE("camera path: parses a good file with comments, blank lines and fov inheritance") {
    const char* text =
        "# header comment\n"
        "\n"
        "  0  10 20 30  45 -10      # no fov: takes the default\n"
        "\t1.5\t11\t21\t31\t46\t-11\t70\r\n"
        "   \n"
        "2 +12 22 32 47 -12 # inherits 70\n"
        "3e0 13 23 -3.5e1 -170 -90";  // no final newline
    InputErrors errors;
    const CameraPath path = CameraPath::parse(text, "test.path", errors, 50.0);
    REQUIRE(errors.empty());
    REQUIRE(path.keys().size() == 4);
    const auto& k = path.keys();
    CHECK(k[0].t == 0.0);
    CHECK(k[0].pose.position == glm::dvec3(10, 20, 30));
    CHECK(k[0].pose.yaw_deg == 45.0);
    CHECK(k[0].pose.pitch_deg == -10.0);
    CHECK(k[0].pose.fov_deg == 50.0);
    CHECK(k[1].t == 1.5);
    CHECK(k[1].pose.fov_deg == 70.0);
    CHECK(k[2].pose.position.x == 12.0);
    CHECK(k[2].pose.fov_deg == 70.0);
    CHECK(k[3].t == 3.0);
    CHECK(k[3].pose.position.z == -35.0);
    CHECK(k[3].pose.pitch_deg == -90.0);
    CHECK(path.startTime() == 0.0);
    CHECK(path.endTime() == 3.0);
}

TEST_CASE("camera path: each kind of bad line is reported with its line number") {
    struct Case {
        const char* line;
        const char* expected;
    };
    const Case cases[] = {
        {"5 1 2 3 4", "expected 't x y z yaw_deg pitch_deg [fov_deg]'"},
        {"5 1 2 3 4 5 6 7", "expected 't x y z yaw_deg pitch_deg [fov_deg]'"},
        {"5 1 2 abc 4 5", "z is not a number: 'abc'"},
        {"5 1 2 3 4x 5", "yaw_deg is not a number"},
        {"5 1 2 3 4 5 6deg", "fov_deg is not a number"},
        {"5 1 inf 3 4 5", "y must be a finite number"},
        {"nan 1 2 3 4 5", "t must be a finite number"},
        {"5 1 2 3 4 5 1e999", "fov_deg must be a finite number"},
        {"1 1 2 3 4 5", "previous key's time 2"},
        {"2 1 2 3 4 5", "previous key's time 2"},
        {"5 1 2 3 4 5 0.5", "fov_deg 0.5 is outside 1..179"},
        {"5 1 2 3 4 5 180", "fov_deg 180 is outside 1..179"},
        {"5 1 2 3 4 90.5", "pitch_deg 90.5 is outside -90..90"},
        {"5 1 2 3 4 -91", "pitch_deg -91 is outside -90..90"},
        // Found by the camera-path fuzzer (tests/fuzz): these made sampled poses NaN.
        {"5 1e308 2 3 4 5", "x 1e+308 is outside -1e8..1e8 m"},
        {"5 1 2 -2e8 4 5", "z -2e+08 is outside -1e8..1e8 m"},
        {"5 1 2 3 1e308 5", "yaw_deg 1e+308 is outside -1e6..1e6"},
        {"1e300 1 2 3 4 5", "t 1e+300 is outside -1e12..1e12"},
        {"2.0001 1 2 3 4 5", "by at least 0.001 s"},
    };
    for (const Case& c : cases) {
        CAPTURE(c.line);
        const std::string text = "# comment\n0 0 0 0 0 0\n\n2 0 0 0 0 0\n" + std::string(c.line) + "\n9 0 0 0 0 0\n";
        InputErrors errors;
        CameraPath::parse(text, "bad.path", errors);
        REQUIRE(errors.size() == 1);
        CHECK(errors[0].file == "bad.path");
        CHECK(errors[0].line == 5);
        CHECK_MESSAGE(contains(errors[0].message, c.expected), errors[0].message);
        CHECK(errors[0].str().rfind("bad.path:5: ", 0) == 0);
    }
}

TEST_CASE("camera path: several bad lines are all reported") {
    const char* text =
        "0 0 0 0 0 0\n"
        "1 0 0 0 0\n"          // 2: too few fields
        "2 0 0 0 0 95\n"       // 3: pitch
        "2 0 0 0 0 0\n"        // 4: time not after 2 (line 3's time counts, it was in order)
        "3 0 0 0 0 0 200\n"    // 5: fov
        "4 0 x 0 0 0\n"        // 6: y not a number
        "5 0 0 0 0 0 # ok\n";  // 7
    InputErrors errors;
    const CameraPath path = CameraPath::parse(text, "many.path", errors);
    REQUIRE(errors.size() == 5);
    CHECK(errors[0].line == 2);
    CHECK(errors[1].line == 3);
    CHECK(contains(errors[1].message, "pitch_deg"));
    CHECK(errors[2].line == 4);
    CHECK(contains(errors[2].message, "previous key's time 2"));
    CHECK(errors[3].line == 5);
    CHECK(contains(errors[3].message, "fov_deg"));
    CHECK(errors[4].line == 6);
    CHECK(contains(errors[4].message, "y is not a number"));
    CHECK(path.keys().size() == 2);  // the good lines

    InputErrors both;
    CameraPath::parse("0 0 0 0 0 0\n1 a 0 b 0 0\n2 0 0 0 0 0\n", "two.path", both);
    REQUIRE(both.size() == 2);  // each bad field on the line
    CHECK(contains(both[0].message, "x is not a number"));
    CHECK(contains(both[1].message, "z is not a number"));
}

TEST_CASE("camera path: keys at the limits sample to finite poses everywhere") {
    // The fuzzer's finds, at the edge of what is accepted: 1e8 m apart in a millisecond, a
    // million degrees of yaw, times near 1e12 s.
    const std::string text = "-1e12 1e8 -1e8 1e8 1e6 90 179\n-999999999999.99 -1e8 1e8 -1e8 -1e6 -90 1\n"
                             "1e12 1e8 1e8 1e8 0 0 60\n";
    InputErrors errors;
    const CameraPath path = CameraPath::parse(text, "limits.path", errors);
    REQUIRE(errors.empty());
    REQUIRE(path.keys().size() == 3);
    for (double f : {0.0, 1e-16, 1e-12, 0.25, 0.5, 0.999, 1.0}) {
        const CameraPose p = path.sample(path.startTime() + (path.endTime() - path.startTime()) * f);
        CAPTURE(f);
        CHECK(std::isfinite(p.position.x));
        CHECK(std::isfinite(p.position.y));
        CHECK(std::isfinite(p.position.z));
        CHECK(std::isfinite(p.yaw_deg));
        CHECK(std::isfinite(p.pitch_deg));
        CHECK(std::isfinite(p.fov_deg));
    }
}

TEST_CASE("camera path: fewer than 2 keys is an error") {
    for (const char* text : {"", "# only a comment\n\n", "0 1 2 3 4 5\n"}) {
        CAPTURE(text);
        InputErrors errors;
        CameraPath::parse(text, "short.path", errors);
        REQUIRE(errors.size() == 1);
        CHECK(errors[0].line == 0);
        CHECK(contains(errors[0].message, "a camera path needs at least 2 keys"));
    }
}

TEST_CASE("camera path: a missing file is one error with no line") {
    InputErrors errors;
    const CameraPath path = CameraPath::load((vista::vistaRoot() / "no/such/file.path"), errors);
    REQUIRE(errors.size() == 1);
    CHECK(errors[0].line == 0);
    CHECK(errors[0].file == (vista::vistaRoot() / "no/such/file.path").string());
    CHECK_MESSAGE(contains(errors[0].message, std::strerror(ENOENT)), errors[0].message);
    CHECK(path.empty());

    InputErrors dir_errors;
    CameraPath::load(vista::vistaRoot() / "tests", dir_errors);
    REQUIRE(dir_errors.size() == 1);
    CHECK(dir_errors[0].line == 0);
    CHECK_MESSAGE(contains(dir_errors[0].message, std::strerror(EISDIR)), dir_errors[0].message);
}

TEST_CASE("camera path: passes exactly through every key") {
    const CameraPath path = unevenPath();
    for (const CameraKey& k : path.keys()) {
        CAPTURE(k.t);
        const CameraPose p = path.sample(k.t);
        CHECK(glm::length(p.position - k.pose.position) <= 1e-9);
        CHECK(std::abs(angleDiff(p.yaw_deg, k.pose.yaw_deg)) <= 1e-9);
        CHECK(std::abs(p.pitch_deg - k.pose.pitch_deg) <= 1e-9);
        CHECK(std::abs(p.fov_deg - k.pose.fov_deg) <= 1e-9);
    }
}

TEST_CASE("camera path: matches centripetal Catmull-Rom when times follow the knots") {
    // With t proportional to the centripetal knots the time mapping is uniform, so interior
    // segments must equal the Barry-Goldman pyramid evaluation, an independent formulation.
    const glm::dvec3 p[] = {{0, 0, 0}, {100, 0, 0}, {104, 0, 30}, {400, 50, 60}, {410, 60, -300}, {0, 0, -320}};
    const double seconds_per_knot = 0.3;
    std::vector<CameraKey> keys;
    std::vector<double> u{0.0};
    for (std::size_t i = 0; i < std::size(p); ++i) {
        if (i > 0) u.push_back(u.back() + std::sqrt(glm::length(p[i] - p[i - 1])));
        keys.push_back(key(u[i] * seconds_per_knot, p[i], 0.0));
    }
    const CameraPath path(keys);
    auto lerp = [](glm::dvec3 a, glm::dvec3 b, double ta, double tb, double t) {
        return (tb - t) / (tb - ta) * a + (t - ta) / (tb - ta) * b;
    };
    for (std::size_t i = 1; i + 2 < std::size(p); ++i) {
        for (double s : {0.1, 0.25, 0.5, 0.75, 0.9}) {
            const double x = u[i] + s * (u[i + 1] - u[i]);
            const glm::dvec3 a1 = lerp(p[i - 1], p[i], u[i - 1], u[i], x);
            const glm::dvec3 a2 = lerp(p[i], p[i + 1], u[i], u[i + 1], x);
            const glm::dvec3 a3 = lerp(p[i + 1], p[i + 2], u[i + 1], u[i + 2], x);
            const glm::dvec3 b1 = lerp(a1, a2, u[i - 1], u[i + 1], x);
            const glm::dvec3 b2 = lerp(a2, a3, u[i], u[i + 2], x);
            const glm::dvec3 expected = lerp(b1, b2, u[i], u[i + 1], x);
            CAPTURE(i);
            CAPTURE(s);
            CHECK(glm::length(path.sample(x * seconds_per_knot).position - expected) <= 1e-9);
        }
    }
}

TEST_CASE("camera path: C1 continuous in time at interior keys") {
    const CameraPath path = unevenPath();
    const double h = 1e-5;
    const auto& keys = path.keys();
    for (std::size_t i = 1; i + 1 < keys.size(); ++i) {
        const double t = keys[i].t;
        CAPTURE(t);
        auto position = [&](double s) { return path.sample(s).position; };
        const glm::dvec3 left = leftDerivative(position, t, h);
        const glm::dvec3 right = rightDerivative(position, t, h);
        const double scale = std::max({glm::length(left), glm::length(right), 1.0});
        CHECK(glm::length(left - right) <= 1e-4 * scale);

        // Angles too; yaw unwrapped around the sample so the seam does not show.
        const double yaw_i = keys[i].pose.yaw_deg;
        auto yaw = [&](double s) { return yaw_i + angleDiff(path.sample(s).yaw_deg, yaw_i); };
        auto pitch = [&](double s) { return path.sample(s).pitch_deg; };
        auto fov = [&](double s) { return path.sample(s).fov_deg; };
        for (auto [l, r] : {std::pair{leftDerivative(yaw, t, h), rightDerivative(yaw, t, h)},
                            std::pair{leftDerivative(pitch, t, h), rightDerivative(pitch, t, h)},
                            std::pair{leftDerivative(fov, t, h), rightDerivative(fov, t, h)}}) {
            CHECK(std::abs(l - r) <= 1e-4 * std::max({std::abs(l), std::abs(r), 1.0}));
        }
    }
}

TEST_CASE("camera path: repeated positions give no NaN") {
    const glm::dvec3 a{100, 50, 100}, b{400, 60, -200};
    const CameraPath hover({key(0, a, 0), key(1, a, 10), key(2, a, 20), key(3, b, 30), key(4, b, 40), key(6, a, 50)});
    const CameraPath still({key(0, a, 0), key(1, a, 0)});
    for (const CameraPath* path : {&hover, &still}) {
        for (double t = -1.0; t <= 7.0; t += 0.01) {
            CAPTURE(t);
            REQUIRE(finite(path->sample(t)));
        }
    }
    CHECK(glm::length(hover.sample(1.5).position - a) <= 1e-6);
    CHECK(finite(hover.sample(std::nan(""))));
}

TEST_CASE("camera path: yaw turns along the shortest arc") {
    const CameraPath path({key(0, {0, 0, 0}, 170.0), key(10, {100, 0, 0}, -170.0)});
    const double mid = path.sample(5.0).yaw_deg;
    CHECK(std::abs(angleDiff(mid, 180.0)) <= 1e-9);
    CHECK(mid > -180.0);
    CHECK(mid <= 180.0);
    for (double t = 0.0; t <= 10.0; t += 0.1) {
        const double yaw = path.sample(t).yaw_deg;
        CAPTURE(t);
        CHECK(std::abs(yaw) >= 170.0 - 1e-9);
        CHECK(yaw > -180.0);
        CHECK(yaw <= 180.0);
    }

    // Several keys across the seam: still the short way, output normalised.
    const CameraPath seam({key(0, {0, 0, 0}, 150.0), key(1, {10, 0, 0}, 175.0), key(2, {20, 0, 0}, -160.0),
                           key(3, {30, 0, 0}, -140.0)});
    for (double t = 0.0; t <= 3.0; t += 0.05) {
        const double yaw = seam.sample(t).yaw_deg;
        CAPTURE(t);
        CHECK(std::abs(yaw) >= 135.0);
    }
}

TEST_CASE("camera path: time outside the range is clamped") {
    const CameraPath path = unevenPath();
    const CameraPose before = path.sample(-100.0), first = path.sample(path.startTime());
    const CameraPose after = path.sample(1e9), last = path.sample(path.endTime());
    CHECK(before.position == first.position);
    CHECK(before.yaw_deg == first.yaw_deg);
    CHECK(after.position == last.position);
    CHECK(after.fov_deg == last.fov_deg);
    CHECK(glm::length(last.position - path.keys().back().pose.position) <= 1e-9);
}

TEST_CASE("camera path: empty and one-key paths") {
    const CameraPath empty;
    CHECK(empty.empty());
    const CameraPose d = empty.sample(3.0);
    CHECK(d.position == glm::dvec3(0.0));
    CHECK(d.fov_deg == CameraPose{}.fov_deg);

    const CameraPath one({key(2.0, {1, 2, 3}, 30.0, -5.0, 45.0)});
    for (double t : {0.0, 2.0, 9.0}) {
        const CameraPose p = one.sample(t);
        CHECK(p.position == glm::dvec3(1, 2, 3));
        CHECK(p.yaw_deg == 30.0);
        CHECK(p.pitch_deg == -5.0);
        CHECK(p.fov_deg == 45.0);
    }
    CHECK(one.startTime() == 2.0);
    CHECK(one.endTime() == 2.0);
}

TEST_CASE("camera path: the default path flies over the default island without touching it") {
    InputErrors errors;
    const CameraPath path = CameraPath::load(vista::vistaRoot() / "data/paths/default.path", errors);
    for (const auto& e : errors) MESSAGE(e.str());
    REQUIRE(errors.empty());
    CHECK(path.keys().size() >= 6);
    // The island of config/default.ini: 8192 m across, 600 m height scale, sea level at y = 0.
    const Heightmap map = loadHeightmap(vista::vistaRoot() / "data/heightmaps/island.png", 0, 0, errors);
    REQUIRE(errors.empty());
    const double size = 8192.0, texel = size / double(map.width - 1);
    for (double t = path.startTime(); t <= path.endTime(); t += 0.1) {
        const CameraPose p = path.sample(t);
        CAPTURE(t);
        REQUIRE(finite(p));
        double ground = std::max(0.0, -72.0 + 600.0 * map.sample((p.position.x + size / 2) / texel,
                                                                  (p.position.z + size / 2) / texel));
        CHECK(p.position.y - ground >= 100.0);
        CHECK(std::abs(p.position.x) <= size / 2);
        CHECK(std::abs(p.position.z) <= size / 2);
        CHECK(p.pitch_deg <= 0.0);
        CHECK(p.fov_deg >= 50.0);
        CHECK(p.fov_deg <= 70.0);
    }
}
