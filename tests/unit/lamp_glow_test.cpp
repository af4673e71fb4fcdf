// Lamp glow in fog (renderer/lighting/lamp_glow.h): the closed form of single scattering around a
// point light against the integral it solves, marched numerically; the table against the exact
// F; the medium and the selection of the lights that glow.
#include "renderer/lighting/lamp_glow.h"

#include "renderer/camera.h"
#include "sky/atmosphere.h"
#include "sky/atmosphere_model.h"

#include <doctest/doctest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>
#include <random>

using namespace vista;

namespace {

auto exactF = [](double u, double x) { return glowF(u, x); };

}  // namespace

TEST_CASE("lamp glow: F(u, x) = integral of exp(-u tan xi) over [0, x]") {
    // u = 0: the integrand is 1.
    CHECK(glowF(0.0, 0.7) == doctest::Approx(0.7).epsilon(1e-12));
    CHECK(glowF(0.0, std::numbers::pi / 2) == doctest::Approx(std::numbers::pi / 2).epsilon(1e-12));
    // Small x: tan xi ~ xi, F ~ (1 - exp(-u x)) / u.
    CHECK(glowF(3.0, 1e-3) == doctest::Approx((1.0 - std::exp(-3e-3)) / 3.0).epsilon(1e-6));
    // x = pi/2: substituting s = tan xi gives the integral of exp(-u s) / (1 + s^2) over s >= 0,
    // the auxiliary function f(u) = Ci(u) sin u - (Si(u) - pi/2) cos u; f(1) = 0.6214496.
    CHECK(glowF(1.0, std::numbers::pi / 2) == doctest::Approx(0.6214496).epsilon(1e-6));
    // Increasing in x, decreasing in u.
    CHECK(glowF(0.5, 1.0) < glowF(0.5, 1.2));
    CHECK(glowF(0.6, 1.0) < glowF(0.5, 1.0));
}

TEST_CASE("lamp glow: the table read as the GPU filters it stays within 0.2 % of pi/2 of F") {
    const std::vector<float> table = glowTable();
    REQUIRE(table.size() == std::size_t(kGlowTableU) * kGlowTableV);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> a(0.0, 0.999), x(0.0, std::numbers::pi / 2);
    double worst = 0.0;
    for (int k = 0; k < 2000; ++k) {
        const double share = a(rng);
        // Spread evenly over the table's axis u / (1 + u) and over decades of u.
        const double uu = k % 2 ? share / (1.0 - share) : std::pow(10.0, -4.0 + 6.0 * share);
        const double xx = x(rng);
        worst = std::max(worst, std::abs(glowTableF(table, uu, xx) - glowF(uu, xx)));
    }
    MESSAGE("largest table error: " << worst);
    CHECK(worst < 0.002 * std::numbers::pi / 2);
}

TEST_CASE("lamp glow: the closed form equals the single-scattering integral it solves") {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> unit(-1.0, 1.0), pos(0.0, 1.0);
    for (double extinction : {0.0, 1e-3, 0.02, 0.3}) {
        double worst = 0.0;
        for (int k = 0; k < 60; ++k) {
            // Lights around the camera, in front and behind, rays near and far from them, some
            // stopped by a surface before, inside or after the light's sphere.
            const glm::dvec3 p(unit(rng) * 30.0, unit(rng) * 10.0, -5.0 - pos(rng) * 40.0 + (k % 7 == 0 ? 45.0 : 0.0));
            glm::dvec3 dir = glm::normalize(p + glm::dvec3(unit(rng), unit(rng), unit(rng)) * 6.0 * pos(rng));
            const double t_end = k % 3 == 0 ? 1e30 : glm::length(p) * (0.5 + pos(rng));
            const double radius = 10.0 + 20.0 * pos(rng);
            const double closed = glowTransfer(p, dir, t_end, radius, extinction, exactF, false);
            const double marched = glowTransferReference(p, dir, t_end, radius, extinction, false);
            if (marched > 0.0) worst = std::max(worst, std::abs(closed - marched) / marched);
            else CHECK(closed == doctest::Approx(0.0));
        }
        MESSAGE("extinction " << extinction << " 1/m: largest relative error " << worst);
        // At 0.3 per m (13 m visibility) a lamp behind the ray's closest approach multiplies F's
        // quadrature tolerance (1e-12) by exp(0.3 t_c) up to e^13: a faint glow, still 0.2 %.
        CHECK(worst < (extinction < 0.1 ? 1e-6 : 5e-3));
    }
}

TEST_CASE("lamp glow: with the falloff's window and the table, against the march with the window") {
    const std::vector<float> table = glowTable();
    auto tableF = [&table](double u, double x) { return glowTableF(table, u, x); };
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> unit(-1.0, 1.0), pos(0.0, 1.0);
    for (double extinction : {0.0, 1e-3, 0.02, 0.1}) {
        // Rays over the whole halo (out to the radius), over the sky, stopped by a surface, and
        // from a camera inside the halo.
        double worst_window = 0.0, worst_table = 0.0;
        for (int k = 0; k < 200; ++k) {
            const double radius = 25.0;
            const glm::dvec3 p(0.0, 0.0, k % 5 == 0 ? -10.0 : -40.0);
            const glm::dvec3 dir = glm::normalize(p + glm::dvec3(unit(rng), unit(rng), 0.0) * radius);
            const double t_end = k % 3 == 0 ? glm::length(p) * (0.6 + 0.8 * pos(rng)) : 1e30;
            const double marched = glowTransferReference(p, dir, t_end, radius, extinction, true);
            const double peak = glowTransferReference(p, glm::normalize(p), 1e30, radius, extinction, true);
            const double closed = glowTransfer(p, dir, t_end, radius, extinction, exactF);
            worst_window = std::max(worst_window, std::abs(closed - marched) / peak);
            worst_table = std::max(worst_table, std::abs(glowTransfer(p, dir, t_end, radius, extinction, tableF) - closed) / peak);
            if (extinction == 0.0) CHECK(closed == doctest::Approx(marched).epsilon(1e-6));  // exact in clear air
        }
        MESSAGE("extinction " << extinction << " 1/m: window error " << worst_window << ", table error " << worst_table
                              << " of the peak");
        CHECK(worst_window < 1e-3);
        CHECK(worst_table < 1e-4);
    }
}

TEST_CASE("lamp glow: a sphere's screen rectangle holds its image") {
    ViewParams view;
    view.width = 320;
    view.height = 180;
    const ViewMatrices m = viewMatrices(view);
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (int k = 0; k < 100; ++k) {
        const glm::dvec3 c(unit(rng) * 40.0, unit(rng) * 20.0, -60.0 + unit(rng) * 20.0);
        const double r = 5.0 + 5.0 * (unit(rng) + 1.0);
        const glm::vec4 rect = sphereScreenRect(c, r, view, m);
        for (int i = 0; i < 200; ++i) {  // points of the sphere project inside
            const glm::dvec3 s = c + glm::normalize(glm::dvec3(unit(rng), unit(rng), unit(rng))) * r;
            const glm::vec4 clip = m.view_proj * glm::vec4(glm::vec3(s), 1.0f);
            const double x = clip.x / clip.w, y = clip.y / clip.w;
            if (std::abs(x) > 1.0 || std::abs(y) > 1.0) continue;
            CHECK(x >= rect.x - 1e-5);
            CHECK(x <= rect.z + 1e-5);
            CHECK(y >= rect.y - 1e-5);
            CHECK(y <= rect.w + 1e-5);
        }
    }
    // Reaching the near plane: the whole screen.
    CHECK(sphereScreenRect(glm::dvec3(0.0, 0.0, -3.0), 5.0, view, m) == glm::vec4(-1.0f, -1.0f, 1.0f, 1.0f));
}

TEST_CASE("lamp glow: the medium is the sky's, with the height fog as the shaders add it") {
    SkySettings sky;
    sky.height_fog = false;
    const AtmosphereParams params = atmosphereParams(sky);
    const GlowMedium clear = glowMedium(sky, 10.0);
    const MediumSample m = sampleMedium(params, 10.0);
    CHECK(clear.scattering.y == doctest::Approx(m.scattering().y));
    CHECK(clear.extinction == doctest::Approx((m.extinction.x + m.extinction.y + m.extinction.z) / 3.0));
    sky.height_fog = true;
    sky.fog_density_per_km = 5.0f;
    sky.fog_base_m = 0.0f;
    sky.fog_falloff_m = 200.0f;
    SkySettings no_fog = sky;
    no_fog.height_fog = false;
    // 5 per km at the base, e times less 200 m up: grey, pure scattering.
    const GlowMedium fog = glowMedium(sky, 200.0), air = glowMedium(no_fog, 200.0);
    CHECK(fog.scattering.x - air.scattering.x == doctest::Approx(5e-3 / std::exp(1.0)).epsilon(1e-6));
    CHECK(fog.scattering.z - air.scattering.z == doctest::Approx(5e-3 / std::exp(1.0)).epsilon(1e-6));
    CHECK(fog.extinction - air.extinction == doctest::Approx(5e-3 / std::exp(1.0)).epsilon(1e-6));
}

TEST_CASE("lamp glow: which lights glow") {
    ViewParams view;
    view.position = glm::dvec3(0.0, 5.0, 0.0);
    view.width = 320;
    view.height = 180;
    const ViewMatrices m = viewMatrices(view);  // looks along -z
    auto lamp = [](double z, float intensity) {
        Light l;
        l.position = glm::dvec3(0.0, 5.0, z);
        l.radius_m = 14.0f;
        l.intensity = intensity;
        return l;
    };
    const std::vector<Light> lights = {lamp(-50.0, 3.0f), lamp(-30.0, 3.0f), lamp(60.0, 3.0f), lamp(-40.0, 30.0f)};
    GlowStats stats;
    SkySettings sky;  // clear air: sigma_s r ~ 2e-4, below kGlowMinOpticalDepth
    sky.height_fog = false;
    CHECK(selectGlowLights(lights, sky, view, m, 32, 1.0, stats).empty());
    sky.height_fog = true;
    sky.fog_density_per_km = 1.0f;
    std::vector<GlowLight> picked = selectGlowLights(lights, sky, view, m, 32, 1.0, stats);
    CHECK(picked.size() == 3);  // the one 60 m behind the camera does not
    CHECK(stats.glowing == 3);
    CHECK(stats.dropped == 0);
    picked = selectGlowLights(lights, sky, view, m, 2, 2.0, stats);
    REQUIRE(picked.size() == 2);
    CHECK(stats.dropped == 1);
    CHECK(picked[0].position_radius.z == doctest::Approx(-40.0));  // the brightest first
    CHECK(picked[1].position_radius.z == doctest::Approx(-30.0));  // then the nearer of the two equal ones
    // sigma_s * I * colour / (2 pi), times the radiance scale.
    const GlowMedium medium = glowMedium(sky, 5.0);
    CHECK(picked[1].scatter_extinction.y == doctest::Approx(medium.scattering.y * 3.0 * 2.0 / (2.0 * std::numbers::pi)).epsilon(1e-5));
    CHECK(picked[1].scatter_extinction.w == doctest::Approx(medium.extinction).epsilon(1e-5));
}

TEST_CASE("lamp glow: a spot glows with the share of the flux its cone lets out") {
    Light spot;
    spot.type = LightType::Spot;
    spot.inner_deg = 90.0f;
    spot.outer_deg = 90.0f;
    CHECK(glowConeFraction(spot) == doctest::Approx(0.5));
    spot.inner_deg = 40.0f;
    spot.outer_deg = 60.0f;
    CHECK(glowConeFraction(spot) == doctest::Approx(0.5 * (1.0 - std::cos(50.0 * std::numbers::pi / 180.0))));
    CHECK(glowConeFraction(Light{}) == 1.0);
}
