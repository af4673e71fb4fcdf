// The sun disk's colour as the sky pass draws it, against the spectral reference's transmitted
// sun (sky/atmosphere_spectral.h spectralSunColour(): the solar spectrum times the transmittance
// at 21 wavelengths, CIE 1931, linear sRGB) at sun zeniths from noon to the horizon. The disk,
// the moon, the clouds' sunlight and the sunlit ground at a ray's end share sunlightRgb().
#include "renderer_fixture.h"

#include "sky/atmosphere.h"
#include "sky/atmosphere_spectral.h"
#include "sky/night_light.h"

#include <glm/common.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cstdio>
#include <numbers>
#include <string>

using namespace vista;

namespace {

// The sky alone (as `vista sky` renders it), the sun at azimuth 0 and the given zenith.
Settings sunAlone(double sun_zenith_deg) {
    Settings s;
    s.terrain.enabled = false;
    s.water.enabled = false;
    s.clouds.enabled = false;
    s.debug.grid = false;
    s.taa.enabled = false;
    s.sky.moon = false;
    s.sky.stars = false;
    s.sky.height_fog = false;
    s.sky.rebuild_sun_deg = 0.0f;
    s.sky.sun_mode = SunMode::Angles;
    s.sky.sun_azimuth_deg = 0.0f;
    s.sky.sun_elevation_deg = float(90.0 - sun_zenith_deg);
    return s;
}

}  // namespace

TEST_CASE("gl: the sun disk has the spectral reference's colour and illuminance from noon to the horizon") {
    FrameRenderer& r = test::compiledFileRenderer();
    std::string table = "sun zenith: r/g GPU / reference / old, b/g GPU / reference / old, E GPU / reference (lx)\n";
    for (double zenith : {0.0, 60.0, 85.0, 89.0}) {
        const Settings s = sunAlone(zenith);
        // A 3x3 frame, 0.1 deg wide, centred on the sun (disk radius 0.27 deg): every pixel is disk.
        const ViewParams view{{0.0, 0.0, 0.0}, 0.0, 90.0 - zenith, 0.1, 0.1, 3, 3};
        const test::RenderedFrame f = test::renderFrame(r, s, view);
        const double pre = f.report.counters.count("sky.pre_exposure") ? f.report.counters.at("sky.pre_exposure") : 1.0;
        const glm::dvec3 centre(f.rgba[16], f.rgba[17], f.rgba[18]);  // pixel (1, 1): the disk's centre, limb factor 1
        // Radiance to illuminance: the disk's L = E / (pi alpha^2 (1 - u / 3)) at its centre.
        const double alpha = glm::radians(double(s.sky.sun_angular_radius_deg)), u = double(s.sky.sun_limb_darkening);
        const glm::dvec3 e_gpu = centre / pre * std::numbers::pi * alpha * alpha * (1.0 - u / 3.0) *
                                 luxPerHdrUnit(double(s.sky.sun_illuminance));
        const AtmosphereParams p = atmosphereParams(s.sky);
        const glm::dvec3 sun = sunDirectionFromZenith(zenith);
        SkyColour reference = spectralSunColour(p, 0.0, sun);
        // Near the horizon the sun's blue falls below 0 in linear sRGB (out of gamut); the sky pass
        // clamps its output at 0, so the reference is clamped too.
        reference.rgb = glm::max(reference.rgb, glm::dvec3(0.0));
        const glm::dvec3 old = sunTransmittance(p, glm::dvec3(0.0), sun);  // the samples read as sRGB, white sun
        const ColourError e = colourError(e_gpu, reference);
        const ColourError e_old = colourError(old * kSolarIlluminanceLux, reference);
        char line[200];
        std::snprintf(line, sizeof line, "%4.0f deg: %.3f / %.3f / %.3f   %.3f / %.3f / %.3f   %.0f / %.0f\n", zenith,
                      e_gpu.r / e_gpu.g, reference.rgb.r / reference.rgb.g, old.r / old.g, e_gpu.b / e_gpu.g,
                      reference.rgb.b / reference.rgb.g, old.b / old.g, srgbLuminance(e_gpu), reference.luminance);
        table += line;
        INFO(line);
        CHECK(e.r_over_g < 0.02);
        CHECK(e.b_over_g < 0.02);
        CHECK(e.luminance < 0.03);
        // The old reading misses the bound towards the horizon, so the check tells the two apart.
        if (zenith >= 85.0) CHECK(std::max(e_old.r_over_g, e_old.b_over_g) > 0.1);
    }
    MESSAGE(table);
}
