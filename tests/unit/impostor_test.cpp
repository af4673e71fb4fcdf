// The impostor's hemi-octahedral frame grid and bake projection (renderer/meshes/impostor.h):
// encode and decode invert each other, every frame's direction rounds back to that frame, the
// grid's edge is the horizon, and the bake matrix fits the bounding sphere into the frame with
// the nearer points deeper (reversed-Z).
#include "renderer/meshes/impostor.h"

#include <doctest/doctest.h>
#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <cmath>

using namespace vista;

TEST_CASE("impostor: hemi-octahedral map round trip, frame grid and horizon") {
    for (int a = 0; a <= 36; ++a)
        for (int b = 0; b <= 9; ++b) {
            const double az = a * 10.0 * M_PI / 180.0, el = b * 10.0 * M_PI / 180.0;
            const glm::vec3 d(float(std::cos(el) * std::sin(az)), float(std::sin(el)), float(std::cos(el) * std::cos(az)));
            const glm::vec2 e = hemiOctEncode(d);
            CHECK(std::abs(e.x) <= 1.0f + 1e-6f);
            CHECK(std::abs(e.y) <= 1.0f + 1e-6f);
            CHECK(glm::length(hemiOctDecode(e) - d) < 1e-5f);
        }
    for (int j = 0; j < kImpostorFrames; ++j)
        for (int i = 0; i < kImpostorFrames; ++i) {
            const glm::vec3 d = impostorFrameDirection(i, j);
            CHECK(std::abs(glm::length(d) - 1.0f) < 1e-5f);
            CHECK(d.y >= -1e-6f);
            CHECK(impostorFrameOf(d) == glm::ivec2(i, j));
            const bool edge = i == 0 || j == 0 || i == kImpostorFrames - 1 || j == kImpostorFrames - 1;
            if (edge) CHECK(std::abs(d.y) < 1e-6f);  // the grid's edge: seen from the horizon
        }
    // Below the horizon folds onto it; a view from straight above picks the centre frame.
    CHECK(impostorFrameOf({0.3f, -0.9f, 0.2f}) == impostorFrameOf({0.3f, 0.0f, 0.2f}));
    const glm::vec3 top = impostorFrameDirection(impostorFrameOf({0, 1, 0}).x, impostorFrameOf({0, 1, 0}).y);
    CHECK(top.y > 0.9f);
    // The nearest frame is within 19 degrees of any view from the upper hemisphere (the grid is
    // coarsest in elevation just above the horizon, at the middle of its edges).
    double worst = 0.0;
    for (int a = 0; a < 360; a += 2)
        for (int b = 0; b <= 90; b += 2) {
            const double az = a * M_PI / 180.0, el = b * M_PI / 180.0;
            const glm::vec3 d(float(std::cos(el) * std::sin(az)), float(std::sin(el)), float(std::cos(el) * std::cos(az)));
            const glm::ivec2 f = impostorFrameOf(d);
            const double c = std::clamp(double(glm::dot(d, impostorFrameDirection(f.x, f.y))), -1.0, 1.0);
            worst = std::max(worst, std::acos(c) * 180.0 / M_PI);
        }
    CHECK(worst < 19.0);
}

TEST_CASE("impostor: the bake matrix fits the bounding sphere into the frame, nearer points deeper") {
    const glm::vec3 centre(0.5f, 4.0f, -1.0f);
    const float radius = 5.0f;
    for (int j = 0; j < kImpostorFrames; j += 3)
        for (int i = 0; i < kImpostorFrames; i += 2) {
            const glm::vec3 d = impostorFrameDirection(i, j);
            glm::vec3 right, up;
            impostorBasis(d, right, up);
            CHECK(std::abs(glm::dot(right, up)) < 1e-5f);
            CHECK(std::abs(glm::dot(right, d)) < 1e-5f);
            CHECK(glm::length(glm::cross(right, up) - d) < 1e-5f);  // counter-clockwise seen from d
            const glm::mat4 m = impostorBakeMatrix(d, centre, radius);
            const glm::vec4 c = m * glm::vec4(centre, 1.0f);
            CHECK(glm::length(glm::vec3(c) - glm::vec3(0.0f, 0.0f, 0.5f)) < 1e-5f);
            const glm::vec4 r = m * glm::vec4(centre + right * radius, 1.0f), u = m * glm::vec4(centre + up * radius, 1.0f);
            CHECK(r.x == doctest::Approx(1.0f).epsilon(1e-5));
            CHECK(u.y == doctest::Approx(1.0f).epsilon(1e-5));
            const glm::vec4 near = m * glm::vec4(centre + d * radius, 1.0f), far = m * glm::vec4(centre - d * radius, 1.0f);
            CHECK(near.z == doctest::Approx(1.0f).epsilon(1e-5));
            CHECK(far.z == doctest::Approx(0.0f).epsilon(1e-5));
        }
}
