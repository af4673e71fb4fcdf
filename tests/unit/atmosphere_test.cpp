// Atmosphere CPU reference: optical depth against the closed form of exponential layers,
// convergence with step count (including the stiff near-horizon and sun-below-horizon cases),
// symmetries, ray geometry from the ground to geostationary orbit, finite non-negative radiance
// for extreme views, sunset colour, sun and sky light, and the solar position.
#include "renderer/camera.h"
#include "sky/atmosphere.h"
#include "sky/atmosphere_model.h"
#include "sky/atmosphere_reference.h"

#include <doctest/doctest.h>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

using namespace vista;

namespace {

constexpr double kPi = std::numbers::pi;

glm::dvec3 dirFromAngles(double azimuth_deg, double elevation_deg) {
    double az = azimuth_deg * kPi / 180.0, el = elevation_deg * kPi / 180.0;
    return {std::sin(az) * std::cos(el), std::sin(el), -std::cos(az) * std::cos(el)};
}

double maxRelDiff(glm::dvec3 a, glm::dvec3 b) {
    double m = 0.0;
    for (int i = 0; i < 3; ++i) m = std::max(m, std::abs(a[i] - b[i]) / std::max(std::abs(b[i]), 1e-300));
    return m;
}

bool finiteNonNegative(glm::dvec3 v) {
    for (int i = 0; i < 3; ++i)
        if (!std::isfinite(v[i]) || v[i] < 0.0) return false;
    return true;
}

// Cheaper psi_ms quadrature than the defaults, for tests that compare configurations rather
// than absolute values; a coarse table built once per test process.
IntegrationSteps testSteps() {
    IntegrationSteps s;
    s.ms_polar = 6;
    s.ms_azimuth = 4;
    s.ms_ray = 16;
    s.ms_transmittance = 16;
    return s;
}

const MultipleScatteringTable& testTable() {
    static const MultipleScatteringTable table(AtmosphereParams{}, testSteps(), 24, 128);
    return table;
}

}  // namespace

TEST_CASE("atmosphere: zenith optical depth from the ground matches the closed form of exponential layers") {
    AtmosphereParams p;
    const double top = p.top_radius - p.bottom_radius;
    // Seen vertically, an exponential layer of scale height H up to the top has optical depth
    // beta H (1 - exp(-top / H)); the ozone tent (peak 1, half-width w) integrates to w.
    glm::dvec3 exact = p.rayleigh_scattering * p.rayleigh_scale_height * (1.0 - std::exp(-top / p.rayleigh_scale_height)) +
                       p.mie_extinction * p.mie_scale_height * (1.0 - std::exp(-top / p.mie_scale_height)) +
                       p.ozone_absorption * p.ozone_half_width;
    CHECK(maxRelDiff(opticalDepth(p, p.bottom_radius, 1.0, 64), exact) < 2e-5);
    CHECK(maxRelDiff(opticalDepth(p, p.bottom_radius, 1.0, 256), exact) < 1e-7);
    glm::dvec3 t = transmittance(p, p.bottom_radius, 1.0, 256);
    for (int i = 0; i < 3; ++i) CHECK(t[i] == doctest::Approx(std::exp(-exact[i])).epsilon(1e-7));

    // One layer alone, with the others switched off.
    AtmosphereParams rayleigh_only = p;
    rayleigh_only.mie_scattering = rayleigh_only.mie_extinction = rayleigh_only.ozone_absorption = glm::dvec3(0.0);
    glm::dvec3 od = opticalDepth(rayleigh_only, p.bottom_radius, 1.0, 128);
    CHECK(od.z == doctest::Approx(33.1e-6 * 8000.0 * (1.0 - std::exp(-12.5))).epsilon(1e-6));
    // Earth's textbook values: zenith transmittance ~0.94 red, ~0.75 blue.
    CHECK(t.x > 0.9);
    CHECK(t.z < t.y);
    CHECK(t.y < t.x);
}

TEST_CASE("atmosphere: optical depth converges with step count at the horizon and for grazing rays") {
    AtmosphereParams p;
    const double R = p.bottom_radius;
    // Horizontal from the ground (about 1,130 km of path, density falling by e^-140 along it),
    // grazing from 30 km with the perigee 50 m above the ground, and a steep ray from 100 km.
    double r30 = R + 30e3;
    double mu_graze = -std::sqrt(1.0 - std::pow((R + 50.0) / r30, 2.0));
    struct Ray {
        double r, mu;
    } rays[] = {{R, 0.0}, {R + 1.0, 0.001}, {r30, mu_graze}, {p.top_radius, -0.9}};
    for (const Ray& ray : rays) {
        CAPTURE(ray.r - R);
        CAPTURE(ray.mu);
        glm::dvec3 ref = opticalDepth(p, ray.r, ray.mu, 2048);
        double e32 = maxRelDiff(opticalDepth(p, ray.r, ray.mu, 32), ref);
        double e64 = maxRelDiff(opticalDepth(p, ray.r, ray.mu, 64), ref);
        double e128 = maxRelDiff(opticalDepth(p, ray.r, ray.mu, 128), ref);
        CHECK(e64 < 2e-4);
        CHECK(e128 < 2e-5);
        CHECK(e128 < e32);
        CHECK(finiteNonNegative(ref));
    }
    // The grazing ray passes the dense air twice: more than the horizontal ray from the ground.
    CHECK(opticalDepth(p, r30, mu_graze, 256).z > opticalDepth(p, R, 0.0, 256).z);
}

TEST_CASE("atmosphere: optical depth is the same in both directions along a path") {
    AtmosphereParams p;
    const double R = p.bottom_radius;
    for (double mu : {1.0, 0.5, 0.1, 0.01}) {
        // From the ground to the top along mu, and back from the exit point towards the ground.
        double d = distanceToTop(p, R, mu);
        double r_top = std::sqrt(R * R + 2.0 * R * mu * d + d * d);
        double mu_back = -(R * mu + d) / r_top;
        CAPTURE(mu);
        CHECK(rayIntersectsGround(p, r_top, mu_back));
        CHECK(distanceToGround(p, r_top, mu_back) == doctest::Approx(d).epsilon(1e-9));
        CHECK(maxRelDiff(opticalDepth(p, r_top, mu_back, 256), opticalDepth(p, R, mu, 256)) < 1e-6);
    }
}

TEST_CASE("atmosphere: phase functions are normalised, and Rayleigh is symmetric") {
    // Integrate over the sphere: 2 pi int_{-1}^{1} P(mu) d mu, by fine midpoint steps in theta.
    auto sphereIntegral = [](auto phase) {
        const int n = 20000;
        double sum = 0.0;
        for (int i = 0; i < n; ++i) {
            double theta = (i + 0.5) * kPi / n;
            sum += phase(std::cos(theta)) * std::sin(theta) * (kPi / n);
        }
        return 2.0 * kPi * sum;
    };
    CHECK(sphereIntegral(rayleighPhase) == doctest::Approx(1.0).epsilon(1e-6));
    for (double g : {0.0, 0.5, 0.8}) {
        CAPTURE(g);
        CHECK(sphereIntegral([g](double c) { return cornetteShanksPhase(g, c); }) == doctest::Approx(1.0).epsilon(1e-4));
        CHECK(sphereIntegral([g](double c) { return henyeyGreensteinPhase(g, c); }) == doctest::Approx(1.0).epsilon(1e-4));
    }
    CHECK(rayleighPhase(0.3) == doctest::Approx(rayleighPhase(-0.3)));
    CHECK(cornetteShanksPhase(0.0, 0.3) == doctest::Approx(rayleighPhase(0.3)));  // g = 0 is Rayleigh
    CHECK(henyeyGreensteinPhase(0.0, 0.3) == doctest::Approx(kIsotropicPhase));
    AtmosphereParams p;
    CHECK(miePhase(p, 1.0) > 100.0 * miePhase(p, -1.0));  // forward peak towards the sun
}

TEST_CASE("atmosphere: ray segments from the ground, 100 km, orbit and below the ground") {
    AtmosphereParams p;
    const double R = p.bottom_radius, Rt = p.top_radius;
    auto seg = [&](glm::dvec3 world, glm::dvec3 dir) { return atmosphereSegment(p, planetFromWorld(p, world), glm::normalize(dir)); };

    AtmosphereSegment up = seg({0, 0, 0}, {0, 1, 0});
    CHECK(up.hit);
    CHECK_FALSE(up.ends_on_ground);
    CHECK(up.t_enter == 0.0);
    CHECK(up.t_exit == doctest::Approx(Rt - R));
    AtmosphereSegment horizon = seg({0, 0, 0}, {1, 0, 0});
    CHECK(horizon.t_exit == doctest::Approx(std::sqrt(Rt * Rt - R * R)).epsilon(1e-12));

    AtmosphereSegment from100 = seg({0, 100e3 - 1.0, 0}, {0, -1, 0});
    CHECK(from100.ends_on_ground);
    CHECK(from100.t_exit == doctest::Approx(100e3 - 1.0).epsilon(1e-12));

    // Geostationary altitude: straight down enters at the top and ends on the ground.
    const double h = 35786e3;
    AtmosphereSegment orbit_down = seg({0, h, 0}, {0, -1, 0});
    CHECK(orbit_down.hit);
    CHECK(orbit_down.t_enter == doctest::Approx(h - (Rt - R)).epsilon(1e-12));
    CHECK(orbit_down.t_exit == doctest::Approx(h).epsilon(1e-12));
    CHECK(orbit_down.ends_on_ground);
    // Towards the limb: a ray tangent to the sphere 50 km up crosses the atmosphere and leaves it.
    double r_cam = R + h, r_tan = R + 50e3;
    double sin_a = r_tan / r_cam;
    AtmosphereSegment limb = seg({0, h, 0}, {sin_a, -std::sqrt(1.0 - sin_a * sin_a), 0});
    CHECK(limb.hit);
    CHECK_FALSE(limb.ends_on_ground);
    double half_chord = std::sqrt(Rt * Rt - r_tan * r_tan);
    CHECK(limb.t_exit - limb.t_enter == doctest::Approx(2.0 * half_chord).epsilon(1e-9));
    // Missing the atmosphere, and looking away from it.
    CHECK_FALSE(seg({0, h, 0}, {1, -0.01, 0}).hit);
    CHECK_FALSE(seg({0, h, 0}, {0, 1, 0}).hit);

    // Below the ground: lifted onto it.
    glm::dvec3 lifted = planetFromWorld(p, {0, -500, 0});
    CHECK(glm::length(lifted) == doctest::Approx(R));
    AtmosphereSegment under = seg({0, -500, 0}, {0, 1, 0});
    CHECK(under.t_exit == doctest::Approx(Rt - R));
    CHECK(seg({0, -500, 0}, {0, -1, 0}).t_exit < 1e-6);
}

TEST_CASE("atmosphere: sky radiance converges when the step counts double") {
    AtmosphereParams p;
    const MultipleScatteringTable& table = testTable();
    struct View {
        const char* name;
        glm::dvec3 camera, view, sun;
    } views[] = {
        {"noon zenith", {0, 2, 0}, {0, 1, 0}, dirFromAngles(180, 60)},
        {"noon horizon", {0, 2, 0}, dirFromAngles(0, 1), dirFromAngles(180, 60)},
        {"sunset towards the sun", {0, 2, 0}, dirFromAngles(270, 2), dirFromAngles(270, 0)},
        {"twilight -6 zenith", {0, 2, 0}, {0, 1, 0}, dirFromAngles(270, -6)},
        {"twilight -6 sunwards", {0, 2, 0}, dirFromAngles(270, 5), dirFromAngles(270, -6)},
        {"from 100 km down", {0, 100e3, 0}, dirFromAngles(0, -30), dirFromAngles(180, 40)},
    };
    for (const View& v : views) {
        CAPTURE(v.name);
        IntegrationSteps s = testSteps();
        s.view = 64;
        s.transmittance = 64;
        glm::dvec3 l64 = skyRadiance(p, v.camera, v.view, v.sun, s, &table);
        s.view = s.transmittance = 128;
        glm::dvec3 l128 = skyRadiance(p, v.camera, v.view, v.sun, s, &table);
        s.view = s.transmittance = 32;
        glm::dvec3 l32 = skyRadiance(p, v.camera, v.view, v.sun, s, &table);
        CHECK(maxRelDiff(l64, l128) < 2e-3);
        CHECK(maxRelDiff(l32, l128) < 2e-2);
        CHECK(finiteNonNegative(l128));
    }
    // psi_ms itself: doubling every multiple-scattering count moves it by well under 1%.
    IntegrationSteps fine;
    fine.ms_polar *= 2;
    fine.ms_azimuth *= 2;
    fine.ms_ray *= 2;
    fine.ms_transmittance *= 2;
    for (double mu_s : {1.0, 0.2}) {
        CAPTURE(mu_s);
        CHECK(maxRelDiff(multipleScattering(p, p.bottom_radius + 1e3, mu_s), multipleScattering(p, p.bottom_radius + 1e3, mu_s, fine)) <
              5e-3);
    }
}

TEST_CASE("atmosphere: the multiple-scattering table matches direct evaluation") {
    AtmosphereParams p;
    const MultipleScatteringTable& table = testTable();
    const double R = p.bottom_radius;
    for (double h : {0.0, 1.3e3, 7e3, 33e3}) {
        for (double mu_s : {0.93, 0.41, 0.07}) {
            CAPTURE(h);
            CAPTURE(mu_s);
            CHECK(maxRelDiff(table(R + h, mu_s), multipleScattering(p, R + h, mu_s, testSteps())) < 1e-2);
        }
    }
    // Multiple scattering grows relative to single scattering as the sun sets, then fades.
    CHECK(table(R, 0.5).z > table(R, -0.2).z);
    CHECK(table(R, -0.2).z > table(R, -0.6).z);
}

TEST_CASE("atmosphere: symmetric configurations give the same radiance") {
    AtmosphereParams p;
    const MultipleScatteringTable& table = testTable();
    IntegrationSteps s = testSteps();
    glm::dvec3 cam{0, 300, 0};
    // Mirror the view about the sun's vertical plane.
    glm::dvec3 a = skyRadiance(p, cam, dirFromAngles(200, 10), dirFromAngles(180, 20), s, &table);
    glm::dvec3 b = skyRadiance(p, cam, dirFromAngles(160, 10), dirFromAngles(180, 20), s, &table);
    CHECK(maxRelDiff(a, b) < 1e-9);
    // Turn the whole scene about the vertical.
    glm::dvec3 c = skyRadiance(p, cam, dirFromAngles(200 + 77, 10), dirFromAngles(180 + 77, 20), s, &table);
    CHECK(maxRelDiff(a, c) < 1e-9);
    // With the sun at the zenith the sky depends on the view's elevation only.
    glm::dvec3 zenith_sun{0, 1, 0};
    glm::dvec3 d = skyRadiance(p, cam, dirFromAngles(10, 30), zenith_sun, s, &table);
    glm::dvec3 e = skyRadiance(p, cam, dirFromAngles(190, 30), zenith_sun, s, &table);
    CHECK(maxRelDiff(d, e) < 1e-9);
}

TEST_CASE("atmosphere: finite non-negative radiance for extreme views") {
    AtmosphereParams p;
    const MultipleScatteringTable& table = testTable();
    IntegrationSteps s = testSteps();
    const double geo = 35786e3;
    std::vector<glm::dvec3> cameras = {{0, 0, 0}, {0, 2, 0}, {0, 8848, 0}, {0, 100e3, 0}, {0, 99999, 0},
                                       {0, 400e3, 0}, {0, geo, 0}, {0, -1000, 0}, {1e7, 5, -3e6}};
    std::vector<glm::dvec3> views = {{0, 1, 0}, {0, -1, 0}, {1, 0, 0}, {0, 0, -1}, dirFromAngles(90, -0.01),
                                     dirFromAngles(30, 0.01), dirFromAngles(270, 3), dirFromAngles(45, -8.5)};
    // The limb of the atmosphere from geostationary orbit.
    double sin_a = (p.bottom_radius + 30e3) / (p.bottom_radius + geo);
    views.push_back({sin_a, -std::sqrt(1.0 - sin_a * sin_a), 0.0});
    std::vector<glm::dvec3> suns = {dirFromAngles(180, 90), dirFromAngles(180, 45), dirFromAngles(270, 0),
                                    dirFromAngles(270, -0.27), dirFromAngles(270, -6), dirFromAngles(270, -18),
                                    dirFromAngles(270, -90), {1, 0, 0}};
    for (const glm::dvec3& cam : cameras)
        for (const glm::dvec3& v : views)
            for (const glm::dvec3& sun : suns) {
                ViewRayResult r = integrateViewRay(p, cam, v, sun, 1e300, s, &table);
                bool ok = finiteNonNegative(r.radiance) && finiteNonNegative(r.transmittance) &&
                          r.transmittance.x <= 1.0 && std::isfinite(r.distance);
                if (!ok) {
                    CAPTURE(cam.y);
                    CAPTURE(v.y);
                    CAPTURE(sun.y);
                    CHECK(ok);
                }
            }
    // Direct psi_ms (no table) at the same extremes of the sun.
    for (double mu_s : {1.0, 0.0, -0.1, -0.3, -1.0})
        for (double h : {0.0, 50e3, 100e3}) CHECK(finiteNonNegative(multipleScattering(p, p.bottom_radius + h, mu_s, testSteps())));
    // Seen from orbit, the day side is bright and the atmosphere glows at the limb.
    glm::dvec3 limb = skyRadiance(p, {0, geo, 0}, views.back(), {1, 0, 0}, s, &table);
    CHECK(limb.z > 0.0);
    CHECK(skyRadiance(p, {0, geo, 0}, {0, 1, 0}, {1, 0, 0}, s, &table) == glm::dvec3(0.0));
}

TEST_CASE("atmosphere: the sunset sky and sunlight are redder than at noon") {
    AtmosphereParams p;
    const MultipleScatteringTable& table = testTable();
    IntegrationSteps s = testSteps();
    glm::dvec3 cam{0, 2, 0};
    glm::dvec3 noon = skyRadiance(p, cam, dirFromAngles(250, 5), dirFromAngles(180, 60), s, &table);
    glm::dvec3 sunset = skyRadiance(p, cam, dirFromAngles(250, 5), dirFromAngles(270, 1), s, &table);
    CHECK(sunset.x / sunset.z > 2.0 * noon.x / noon.z);
    CHECK(noon.z > noon.x);  // blue sky
    glm::dvec3 sun_noon = sunTransmittance(p, cam, dirFromAngles(180, 60));
    glm::dvec3 sun_low = sunTransmittance(p, cam, dirFromAngles(270, 2));
    CHECK(sun_low.x / sun_low.z > 5.0 * sun_noon.x / sun_noon.z);
    CHECK(sun_noon.x < 1.0);
    CHECK(sun_noon.z > 0.5);
}

TEST_CASE("atmosphere: sun transmittance fades over the disk and sky irradiance follows the sun") {
    AtmosphereParams p;
    glm::dvec3 ground{0, 0, 0};
    // Zenith sun: the zenith transmittance.
    glm::dvec3 zenith = sunTransmittance(p, ground, {0, 1, 0}, 128);
    CHECK(maxRelDiff(zenith, transmittance(p, p.bottom_radius, 1.0, 128)) < 1e-9);
    // The disk sets over its angular radius (0.268 deg): half visible with its centre on the horizon.
    double radius_deg = p.sun_angular_radius * 180.0 / kPi;
    glm::dvec3 centre = sunTransmittance(p, ground, dirFromAngles(270, 0));
    glm::dvec3 below = sunTransmittance(p, ground, dirFromAngles(270, -0.5 * radius_deg));
    CHECK(below.x > 0.0);
    CHECK(below.x < centre.x);
    CHECK(sunTransmittance(p, ground, dirFromAngles(270, -1.01 * radius_deg)) == glm::dvec3(0.0));
    CHECK(maxRelDiff(centre, 0.5 * transmittance(p, p.bottom_radius, 0.0)) < 1e-9);
    // From above the atmosphere the sun is unattenuated unless the planet is in the way.
    CHECK(sunTransmittance(p, {0, 1e6, 0}, {0, 1, 0}) == glm::dvec3(1.0));
    CHECK(sunTransmittance(p, {0, 1e6, 0}, {0, -1, 0}) == glm::dvec3(0.0));
    CHECK(sunIrradiance(p, ground, {0, 1, 0}, 128) == zenith * p.solar_irradiance);

    const MultipleScatteringTable& table = testTable();
    IntegrationSteps s = testSteps();
    s.view = 32;
    s.transmittance = 32;
    glm::dvec3 e_noon = skyIrradianceUp(p, ground, dirFromAngles(180, 60), s, &table, 6, 6);
    glm::dvec3 e_low = skyIrradianceUp(p, ground, dirFromAngles(180, 5), s, &table, 6, 6);
    glm::dvec3 e_night = skyIrradianceUp(p, ground, dirFromAngles(180, -18), s, &table, 6, 6);
    CHECK(finiteNonNegative(e_noon));
    CHECK(e_noon.z > e_noon.x);
    CHECK(e_low.z < e_noon.z);
    CHECK(e_night.z < 1e-3 * e_noon.z);
    // Sky against direct sun on a horizontal surface at 60 deg: blue sky light is a good share of
    // the sun's (clear-sky diffuse fractions are ~10-30% overall, more in blue).
    glm::dvec3 direct = sunIrradiance(p, ground, dirFromAngles(180, 60)) * std::sin(60.0 * kPi / 180.0);
    CHECK(e_noon.z / direct.z > 0.1);
    CHECK(e_noon.z / direct.z < 1.0);
    CHECK(e_noon.x / direct.x < e_noon.z / direct.z);
}

TEST_CASE("sun position: equinox noon at the equator is at the zenith") {
    // Around the March equinox (day 79-80) the declination is within a few tenths of a degree of 0.
    SunPosition s = sunPosition(0.0, 80.0, 12.0);
    CHECK(s.elevation_deg > 89.0);
    CHECK(std::abs(solarDeclinationRad(80.0)) * 180.0 / kPi < 0.5);
    // Solstice declinations: +-23.44 deg.
    CHECK(solarDeclinationRad(172.0) * 180.0 / kPi == doctest::Approx(23.44).epsilon(0.01));
    CHECK(solarDeclinationRad(355.0) * 180.0 / kPi == doctest::Approx(-23.44).epsilon(0.01));
    // Equation of time: about +16.4 min early November, -14.2 min mid-February.
    CHECK(equationOfTimeMinutes(307.0) == doctest::Approx(16.4).epsilon(0.05));
    CHECK(equationOfTimeMinutes(42.0) == doctest::Approx(-14.2).epsilon(0.05));
}

TEST_CASE("sun position: sunrise azimuth, noon elevation and vista's axes") {
    // Bisection for the morning moment the sun's centre crosses the geometric horizon.
    auto sunrise = [](double lat, double day) {
        double lo = 0.0, hi = 12.0;
        for (int i = 0; i < 60; ++i) {
            double mid = 0.5 * (lo + hi);
            (sunPosition(lat, day, mid).elevation_deg < 0.0 ? lo : hi) = mid;
        }
        return sunPosition(lat, day, hi);
    };
    // Equinox: the sun rises due east everywhere (within the day's declination change).
    CHECK(sunrise(45.0, 80.0).azimuth_deg == doctest::Approx(90.0).epsilon(0.01));
    // June solstice at 52 N: azimuth acos(sin 23.44 / cos 52) = 49.8 deg; noon elevation 61.4 deg.
    SunPosition rise = sunrise(52.0, 172.0);
    CHECK(rise.azimuth_deg == doctest::Approx(49.8).epsilon(0.02));
    CHECK(sunPosition(52.0, 172.0, 12.0).elevation_deg == doctest::Approx(61.44).epsilon(0.01));
    // Southern hemisphere in June: the noon sun is in the north.
    SunPosition south = sunPosition(-40.0, 172.0, 12.0);
    CHECK((south.azimuth_deg < 1.0 || south.azimuth_deg > 359.0));
    CHECK(south.elevation_deg == doctest::Approx(90.0 - 40.0 - 23.44).epsilon(0.01));
    // Afternoon sun in the west (-x), morning sun in the east (+x); the direction matches the angles.
    CHECK(sunPosition(45.0, 80.0, 16.0).direction.x < 0.0);
    CHECK(sunPosition(45.0, 80.0, 8.0).direction.x > 0.0);
    SunPosition any = sunPosition(30.0, 200.0, 9.5);
    glm::dvec3 d = dirFromAngles(any.azimuth_deg, any.elevation_deg);
    CHECK(glm::length(d - any.direction) < 1e-12);
    CHECK(glm::length(any.direction) == doctest::Approx(1.0));
}

TEST_CASE("atmosphere: the moon's direction follows its age from the sun, the celestial pole stands at the latitude") {
    SkySettings s;
    s.sun_mode = SunMode::Time;
    s.latitude_deg = 45.0f;
    s.day_of_year = 100.0f;
    s.time_of_day_h = 21.0f;
    s.moon_age_days = 0.0f;  // new moon: with the sun
    CHECK(glm::dot(moonDirection(s), sunDirection(s)) > std::cos(glm::radians(3.0)));
    s.moon_age_days = 14.765f;  // full: opposite
    CHECK(glm::dot(moonDirection(s), sunDirection(s)) < -std::cos(glm::radians(3.0)));
    s.moon_age_days = 7.38f;  // quarter: 90 deg away
    CHECK(std::abs(glm::dot(moonDirection(s), sunDirection(s))) < std::sin(glm::radians(3.0)));
    // The pole: 45 deg up in the north (-z), at any time.
    for (float t : {0.0f, 7.0f, 18.5f}) {
        s.time_of_day_h = t;
        glm::dvec3 pole = celestialFromWorld(s) * glm::normalize(glm::dvec3(0.0, 1.0, -1.0));
        CHECK(pole.z == doctest::Approx(1.0).epsilon(1e-9));
    }
}

TEST_CASE("sky: the sky pass's variants leave out the sun disk, moon and stars only where a view cannot show them") {
    // Looking north (-z), level, 60 deg vertical at 16:9: the frustum's corners lie 56 deg off the axis.
    const ViewParams view{{0.0, 2.0, 0.0}, 0.0, 0.0, 60.0, 0.5, 160, 90};
    const ViewMatrices m = viewMatrices(view);
    SkySettings sky;
    const glm::dvec3 ahead = directionFromAngles(0.0, 10.0), beside = directionFromAngles(40.0, 10.0), behind = directionFromAngles(180.0, 30.0);
    const glm::dvec3 below = directionFromAngles(180.0, -20.0);
    auto shows = [&](const glm::dvec3& sun, const glm::dvec3& moon, double altitude_m = 2.0) {
        return skyShows(view, m, sky, sun, moon, altitude_m);
    };
    CHECK(shows(ahead, behind).sun_disk);
    CHECK(shows(beside, behind).sun_disk);  // inside the corners' cone
    CHECK_FALSE(shows(behind, behind).sun_disk);
    CHECK(shows(behind, ahead).moon);
    CHECK_FALSE(shows(ahead, behind).moon);
    // By day no star shows below 20 km, unless the moon covers the sun; at night, from near space
    // or in an eclipse they may.
    CHECK_FALSE(shows(behind, ahead).stars);
    CHECK(shows(below, ahead).stars);
    CHECK(shows(behind, ahead, 30000.0).stars);
    CHECK(shows(ahead, ahead).stars);
    sky.moon = false;
    sky.stars = false;
    CHECK_FALSE(shows(behind, ahead).moon);
    CHECK_FALSE(shows(below, ahead).stars);
    // The defines name exactly what is shown, the ground and the part of the screen.
    CHECK(skyDefines({true, false, true}, false, 1) ==
          std::vector<std::string>{"SKY_NO_GROUND", "SKY_CLIP=1", "SKY_SUN_DISK", "SKY_STARS"});
    CHECK(skyDefines({false, true, false}, true, 0) == std::vector<std::string>{"SKY_MOON"});
}
