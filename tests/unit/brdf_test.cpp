// The lighting BRDF (renderer/lighting/brdf.h): energy conservation by Monte Carlo integration of the
// directional albedo, reciprocity, and the white-furnace lower bound of the Lambert part.
#include "renderer/lighting/brdf.h"

#include <doctest/doctest.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <cstdint>
#include <initializer_list>

using namespace vista;

namespace {

// Directional albedo: integral over the hemisphere of f(l, v) n.l dl, by stratified cosine-free
// uniform sampling of the hemisphere (pdf 1 / 2 pi), n = +y.
glm::dvec3 directionalAlbedo(const glm::dvec3& albedo, double roughness, double f0, double view_deg) {
    const glm::dvec3 n{0.0, 1.0, 0.0};
    const double t = view_deg * M_PI / 180.0;
    const glm::dvec3 v{std::sin(t), std::cos(t), 0.0};
    const int N = 512;
    glm::dvec3 sum{0.0};
    for (int i = 0; i < N; ++i)
        for (int j = 0; j < N; ++j) {
            const double u1 = (i + 0.5) / N, u2 = (j + 0.5) / N;
            const double cos_t = u1, sin_t = std::sqrt(1.0 - u1 * u1), phi = 2.0 * M_PI * u2;
            const glm::dvec3 l{sin_t * std::cos(phi), cos_t, sin_t * std::sin(phi)};
            sum += evalBrdf(albedo, roughness, f0, n, l, v) * cos_t;
        }
    return sum * (2.0 * M_PI / (double(N) * N));
}

}  // namespace

TEST_CASE("brdf: directional albedo of a white surface stays at or below 1 for every roughness and view") {
    for (double roughness : {0.045, 0.2, 0.5, 0.8, 1.0})
        for (double view : {0.0, 30.0, 60.0, 80.0, 89.0}) {
            CAPTURE(roughness);
            CAPTURE(view);
            const glm::dvec3 a = directionalAlbedo(glm::dvec3(1.0), roughness, 0.04, view);
            CHECK(a.x <= 1.0 + 2e-3);  // 2e-3: quadrature error of the sharpest lobes
            // Lambert with (1 - F) keeps most of the energy: a rough white dielectric reflects > 85 %.
            if (roughness >= 0.5 && view <= 60.0) CHECK(a.x > 0.85);
        }
}

TEST_CASE("brdf: a black dielectric reflects only its Fresnel part, about F0 at normal view") {
    const glm::dvec3 a = directionalAlbedo(glm::dvec3(0.0), 0.5, 0.04, 0.0);
    CHECK(a.x > 0.03);
    CHECK(a.x < 0.06);
}

TEST_CASE("brdf: reciprocal, zero below the horizon, finite at grazing angles") {
    const glm::dvec3 n{0.0, 1.0, 0.0};
    const glm::dvec3 l = glm::normalize(glm::dvec3(0.3, 0.8, -0.2)), v = glm::normalize(glm::dvec3(-0.5, 0.4, 0.6));
    for (double r : {0.045, 0.3, 1.0}) {
        const glm::dvec3 a = evalBrdf(glm::dvec3(0.5), r, 0.04, n, l, v), b = evalBrdf(glm::dvec3(0.5), r, 0.04, n, v, l);
        CHECK(a.x == doctest::Approx(b.x).epsilon(1e-12));
    }
    CHECK(evalBrdf(glm::dvec3(1.0), 0.5, 0.04, n, glm::dvec3(0.0, -0.1, 0.995), v).x == 0.0);
    const glm::dvec3 g = evalBrdf(glm::dvec3(1.0), 0.045, 0.04, n, glm::normalize(glm::dvec3(1.0, 1e-6, 0.0)),
                                  glm::normalize(glm::dvec3(-1.0, 1e-6, 0.0)));
    CHECK(std::isfinite(g.x));
}
