// The sun's visibility for the lens flare (sky/clouds/sun_visibility.h): its transmittance
// through the atmosphere against the closed form of a vertical ray, a horizon sun and an
// overcast sky far below a clear noon, and the cloud march converged in its step count.
#include "sky/clouds/sun_visibility.h"
#include "sky/atmosphere_spectral.h"

#include "sky/atmosphere.h"

#include <doctest/doctest.h>

#include <cmath>

using namespace vista;

namespace {

SkySettings sunAt(double elevation_deg) {
    SkySettings sky;
    sky.sun_mode = SunMode::Angles;
    sky.sun_azimuth_deg = 135.0f;
    sky.sun_elevation_deg = float(elevation_deg);
    return sky;
}

CloudsSettings clear() {
    CloudsSettings c;
    c.enabled = false;  // the default scene has clouds
    return c;
}

CloudsSettings overcast() {
    CloudsSettings c;
    c.enabled = true;
    c.low.enabled = true;
    c.low.coverage = 1.0f;
    c.high.enabled = false;
    return c;
}

}  // namespace

TEST_CASE("sun visibility: a zenith sun's transmittance is the closed form of the vertical optical depth") {
    const SkySettings sky = sunAt(90.0);
    const AtmosphereParams p = atmosphereParams(sky);
    // Exponential profiles integrate to beta H (1 - exp(-top / H)); the ozone tent to its peak
    // times its half-width (the tent lies wholly below the top).
    const double top = p.top_radius - p.bottom_radius;
    const glm::dvec3 tau = p.rayleigh_scattering * p.rayleigh_scale_height * (1.0 - std::exp(-top / p.rayleigh_scale_height)) +
                           p.mie_extinction * p.mie_scale_height * (1.0 - std::exp(-top / p.mie_scale_height)) +
                           p.ozone_absorption * p.ozone_half_width;
    const glm::dvec3 t(std::exp(-tau.r), std::exp(-tau.g), std::exp(-tau.b));
    // The three samples' transmittance become the sun's colour as the renderer converts them
    // (sunlightRgb: the spectral reference's sum over the path's columns).
    const glm::dvec3 rgb = sunlightRgb(sunlightConversion(p), t);
    const double expected = 0.2126 * rgb.r + 0.7152 * rgb.g + 0.0722 * rgb.b;
    MESSAGE("zenith sun transmittance (luminance) " << expected);
    SkyLightingCache cache;
    const glm::dvec3 camera(0.0, 0.0, 0.0);
    const SunVisibility v = sunVisibility(cache.get(sky, camera), sky, clear(), camera, 0.0);
    CHECK(v.atmosphere == doctest::Approx(expected).epsilon(2e-3));
    CHECK(v.clouds == 1.0);  // no clouds
    CHECK(v.share() == doctest::Approx(v.atmosphere));
    // In lux: kSolarIlluminanceLux times it, ~100 klx on the ground at noon.
    CHECK(expected > 0.75);
    CHECK(expected < 0.9);
}

TEST_CASE("sun visibility: a sun at the horizon and one behind an overcast layer are far below a clear noon") {
    SkyLightingCache cache;
    const glm::dvec3 camera(0.0, 50.0, 0.0);
    const SkySettings noon = sunAt(60.0), low = sunAt(1.0), set = sunAt(-1.0);
    const SunVisibility noon_clear = sunVisibility(cache.get(noon, camera), noon, clear(), camera, 0.0);
    const SunVisibility horizon = sunVisibility(cache.get(low, camera), low, clear(), camera, 0.0);
    const SunVisibility below = sunVisibility(cache.get(set, camera), set, clear(), camera, 0.0);
    const SunVisibility cloudy = sunVisibility(cache.get(noon, camera), noon, overcast(), camera, 0.0);
    MESSAGE("share: noon " << noon_clear.share() << ", 1 deg " << horizon.share() << ", overcast noon " << cloudy.share());
    CHECK(noon_clear.share() > 0.7);
    CHECK(horizon.share() < 0.25 * noon_clear.share());  // ~30 air masses at 1 deg
    CHECK(below.share() == 0.0);
    CHECK(cloudy.atmosphere == doctest::Approx(noon_clear.atmosphere));
    CHECK(cloudy.clouds < 0.05);
    CHECK(cloudy.share() < 0.05 * noon_clear.share());
    // The clouds drift: a broken layer lets some suns through and hides others, always in [0, 1].
    CloudsSettings broken = overcast();
    broken.low.coverage = 0.5f;
    int hidden = 0, seen = 0;
    for (int i = 0; i < 24; ++i) {
        const double t = 30.0 * i;
        const double c = sunVisibility(cache.get(noon, camera), noon, broken, camera, t).clouds;
        CHECK(c >= 0.0);
        CHECK(c <= 1.0);
        hidden += c < 0.1;
        seen += c > 0.9;
    }
    CHECK(hidden > 0);
    CHECK(seen > 0);
}

TEST_CASE("sun visibility: the cloud march is converged at its default step count") {
    const SkySettings sky = sunAt(20.0);
    CloudsSettings c = overcast();
    c.low.coverage = 0.6f;
    const glm::dvec3 dir = sunDirection(sky);
    for (int i = 0; i < 8; ++i) {
        const glm::dvec3 camera(700.0 * i, 30.0, -400.0 * i);
        const double fine = cloudTransmittanceAlong(c, sky, camera, dir, 0.0, 2048);
        const double standard = cloudTransmittanceAlong(c, sky, camera, dir, 0.0);
        CHECK(standard == doctest::Approx(fine).epsilon(0.02).scale(1.0));
    }
}
