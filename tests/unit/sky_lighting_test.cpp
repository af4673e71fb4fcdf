// The sky's CPU outputs for the lighting: sun direction from the settings, and the cached
// sun/sky light against the full-quality reference.
#include "sky/atmosphere.h"
#include "sky/atmosphere_spectral.h"
#include "sky/night_light.h"
#include "sky/sky_lighting.h"

#include <doctest/doctest.h>
#include <glm/geometric.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>

using namespace vista;

TEST_CASE("sky: sunDirection follows sun_mode (angles, or latitude, day and solar time)") {
    SkySettings s;
    s.sun_mode = SunMode::Angles;
    s.sun_azimuth_deg = 90.0f;
    s.sun_elevation_deg = 30.0f;
    glm::dvec3 d = sunDirection(s);
    CHECK(glm::length(d) == doctest::Approx(1.0));
    CHECK(d.y == doctest::Approx(0.5).epsilon(1e-6));
    CHECK(d.x == doctest::Approx(std::sqrt(0.75)).epsilon(1e-6));  // azimuth 90 = east = +x

    // 45 deg N at the March equinox, 09:00 solar time: elevation ~30 deg, azimuth ~125 deg
    // (declination ~0: sin(el) = cos(45) cos(45); the sun is south-east).
    s.sun_mode = SunMode::Time;
    s.latitude_deg = 45.0f;
    s.day_of_year = 80.0f;
    s.time_of_day_h = 9.0f;
    d = sunDirection(s);
    double elevation = std::asin(d.y) * 180.0 / 3.14159265358979;
    double azimuth = std::atan2(d.x, -d.z) * 180.0 / 3.14159265358979;
    CHECK(elevation == doctest::Approx(30.0).epsilon(0.02));
    CHECK(azimuth == doctest::Approx(125.3).epsilon(0.01));
    // Solar noon at the June solstice at 52 deg N: 90 - 52 + 23.44.
    s.latitude_deg = 52.0f;
    s.day_of_year = 172.0f;
    s.time_of_day_h = 12.0f;
    CHECK(std::asin(sunDirection(s).y) * 180.0 / 3.14159265358979 == doctest::Approx(61.44).epsilon(0.01));
}

TEST_CASE("sky: skyLighting is close to the full reference and cached") {
    SkySettings s;
    s.sun_illuminance = 2.0f;
    const AtmosphereParams p = atmosphereParams(s);
    const MultipleScatteringTable table(p);
    SkyLightingCache cache;
    struct Case {
        float elevation;
        double altitude;
    } cases[] = {{60.0f, 2.0}, {10.0f, 2.0}, {2.0f, 500.0}, {-3.0f, 2.0}, {30.0f, 20000.0}};
    for (const Case& c : cases) {
        CAPTURE(c.elevation);
        CAPTURE(c.altitude);
        s.sun_elevation_deg = c.elevation;
        glm::dvec3 cam{1234.0, c.altitude, -5678.0};  // only the altitude counts
        auto t0 = std::chrono::steady_clock::now();
        SkyLighting l = cache.get(s, cam);
        double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
        glm::dvec3 sun = sunDirection(s);
        glm::dvec3 at{0.0, c.altitude, 0.0};
        // In linear sRGB as the sky pass draws them: the sun through sunlightRgb(), the sky
        // through its colour matrix.
        glm::dvec3 e_sun = 2.0 * sunlightRgb(sunlightConversion(p), sunIrradiance(p, at, sun));
        glm::dvec3 e_sky = 2.0 * (skyColourMatrix(sun.y) * skyIrradianceUp(p, at, sun, {}, &table));
        std::printf("sky lighting el %5.1f alt %7.0f: sun %.4g %.4g %.4g (ref %.4g), sky %.4g %.4g %.4g (ref %.4g %.4g %.4g), %.2f ms\n",
                    double(c.elevation), c.altitude, l.sun_illuminance.x, l.sun_illuminance.y, l.sun_illuminance.z,
                    e_sun.z, l.sky_irradiance_up.x, l.sky_irradiance_up.y, l.sky_irradiance_up.z, e_sky.x, e_sky.y,
                    e_sky.z, ms);
        CHECK(glm::length(l.sun_direction - sun) < 1e-12);
        for (int i = 0; i < 3; ++i) {
            CHECK(l.sun_illuminance[i] == doctest::Approx(e_sun[i]).epsilon(0.01).scale(1e-6));
            CHECK(l.sky_irradiance_up[i] == doctest::Approx(e_sky[i]).epsilon(0.03));
            CHECK(std::isfinite(l.sky_irradiance_up[i]));
        }
        // The sun's colour is the spectral reference's (the solar spectrum through the air).
        if (c.elevation > 0.0f) {
            const SkyColour spectral = spectralSunColour(p, c.altitude, sun);
            const ColourError e = colourError(l.sun_illuminance * (kSolarIlluminanceLux / 2.0), spectral);
            CHECK(e.r_over_g < 2e-3);
            CHECK(e.b_over_g < 2e-3);
            CHECK(e.luminance < 0.01);
        }
    }
    CHECK(cache.tableBuilds() == 1);
    int evaluations = cache.evaluations();
    cache.get(s, {0.0, 20000.0, 0.0});  // nothing changed
    CHECK(cache.evaluations() == evaluations);
    s.mie_g = 0.7f;
    cache.get(s, {0.0, 20000.0, 0.0});
    CHECK(cache.tableBuilds() == 2);
}
