// Spectral sky reference: the tabulated data against their known integrals, the per-wavelength
// coefficients against the model's three channels, and the GPU path's colour (three samples
// and skyColourMatrix()) against the spectral reference over altitudes 0..10 km, sun zeniths
// 0..80 deg and all view directions: median error within 2 % in luminance, r/g and b/g.
#include "sky/atmosphere_spectral.h"

#include "sky/atmosphere_model.h"
#include "sky/night_light.h"

#include <doctest/doctest.h>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

using namespace vista;

namespace {

constexpr double kSpectralAltitudesM[] = {0.0, 2000.0, 5000.0, 10000.0};
// The fitted sun zeniths (skyColourZenithsDeg()) and, between them, zeniths the fits never saw
// (the renderer interpolates the matrices there).
constexpr double kSpectralSunZenithsDeg[] = {0.0, 10.0, 20.0, 30.0, 40.0, 50.0, 60.0, 65.0, 70.0, 75.0, 80.0};

// The references at reduced cost (the two are compared with each other, so they share it):
// view 32 / transmittance 32 steps are within ~1e-3 of converged, the psi_ms tables a quarter
// of the default size.
IntegrationSteps spectralTestSteps() {
    IntegrationSteps s;
    s.view = 32;
    s.transmittance = 32;
    return s;
}

struct SpectralRow {
    double altitude_m, sun_zenith_deg;
    std::vector<glm::dvec3> samples;  // the three-sample path's transfer factors
    std::vector<SkyColour> reference;
};

// Every (altitude, sun zenith) row of the agreement tables, built once for the whole file.
const std::vector<SpectralRow>& spectralRows() {
    static const std::vector<SpectralRow> rows = [] {
        const AtmosphereParams p;
        const SpectralSkyReference spectral(p, 2, spectralTestSteps(), 16, 64);
        const ThreeSampleSky three(p, spectralTestSteps(), 16, 64);
        std::vector<SpectralRow> out;
        for (double altitude : kSpectralAltitudesM)
            for (double sun_zenith : kSpectralSunZenithsDeg) {
                SpectralRow row{altitude, sun_zenith, {}, {}};
                glm::dvec3 sun = sunDirectionFromZenith(sun_zenith);
                for (const SkyGeometry& g : skyAgreementViews(altitude, sun_zenith)) {
                    glm::dvec3 view = viewDirectionFromAngles(g.view_zenith_deg, g.view_azimuth_deg);
                    row.samples.push_back(three.samples(altitude, view, sun));
                    row.reference.push_back(spectral.radiance(altitude, view, sun));
                }
                out.push_back(std::move(row));
            }
        return out;
    }();
    return rows;
}

struct RowErrors {
    ErrorStats luminance, r_over_g, b_over_g;
};

RowErrors rowErrors(const SpectralRow& row, const glm::dmat3& colour) {
    std::vector<double> lum, rg, bg;
    for (std::size_t i = 0; i < row.samples.size(); ++i) {
        ColourError e = colourError(kSolarIlluminanceLux * (colour * row.samples[i]), row.reference[i]);
        lum.push_back(e.luminance);
        rg.push_back(e.r_over_g);
        bg.push_back(e.b_over_g);
    }
    return {errorStats(lum), errorStats(rg), errorStats(bg)};
}

// The agreement table in the docs' Markdown (percent: median / p95 / max).
std::string agreementTable(bool converted) {
    std::string text = "| altitude km | sun zenith deg | luminance % | r/g % | b/g % |\n|---|---|---|---|---|\n";
    char line[256];
    for (const SpectralRow& row : spectralRows()) {
        glm::dmat3 colour = converted ? skyColourMatrix(std::cos(glm::radians(row.sun_zenith_deg))) : glm::dmat3(1.0);
        RowErrors e = rowErrors(row, colour);
        auto cell = [](const ErrorStats& s) {
            char c[64];
            std::snprintf(c, sizeof c, "%.1f / %.1f / %.1f", 100.0 * s.median, 100.0 * s.p95, 100.0 * s.max);
            return std::string(c);
        };
        std::snprintf(line, sizeof line, "| %g | %g | %s | %s | %s |\n", row.altitude_m * 1e-3, row.sun_zenith_deg,
                      cell(e.luminance).c_str(), cell(e.r_over_g).c_str(), cell(e.b_over_g).c_str());
        text += line;
    }
    return text;
}

}  // namespace

TEST_CASE("spectral: the CIE 1931 table integrates to its known areas and the sun to ~131 klx") {
    // CIE 1931 2 deg: the integrals of x-bar, y-bar and z-bar are 106.857, 106.857 and 106.892
    // nm at 1 nm; 10 nm sums are within a few tenths of a percent. A typo in a row moves them.
    glm::dvec3 sum(0.0);
    for (const SpectralSample& s : spectralTable()) sum += s.cmf * kSpectralTableStepNm;
    CHECK(sum.x == doctest::Approx(106.857).epsilon(0.005));
    CHECK(sum.y == doctest::Approx(106.857).epsilon(0.005));
    CHECK(sum.z == doctest::Approx(106.892).epsilon(0.005));
    // Equal energy (illuminant E) comes out neutral: x = y = 1/3.
    CHECK(sum.x / (sum.x + sum.y + sum.z) == doctest::Approx(1.0 / 3.0).epsilon(0.003));
    // D65 white in XYZ (0.9505, 1, 1.089) is linear sRGB (1, 1, 1).
    glm::dvec3 white = linearSrgbFromXyz({0.9505, 1.0, 1.089});
    CHECK(white.x == doctest::Approx(1.0).epsilon(0.002));
    CHECK(white.y == doctest::Approx(1.0).epsilon(0.002));
    CHECK(white.z == doctest::Approx(1.0).epsilon(0.002));
    // The extraterrestrial sun: ~1361 W/m^2 over all wavelengths, ~129-133 klx in the visible.
    CHECK(spectralSolarIlluminanceLux(1) == doctest::Approx(131000.0).epsilon(0.03));
    CHECK(spectralSolarIlluminanceLux(2) == doctest::Approx(spectralSolarIlluminanceLux(1)).epsilon(0.01));
    // The renderer's sun (sky/night_light.h) is this integral: 683 x sum(y-bar E) x 10 nm.
    double sum_y = 0.0;
    for (const SpectralSample& s : spectralTable()) sum_y += s.cmf.y * s.solar_irradiance;
    CHECK(683.0 * sum_y * 10.0 == doctest::Approx(spectralSolarIlluminanceLux(1)).epsilon(1e-12));
    CHECK(kSolarIlluminanceLux == doctest::Approx(spectralSolarIlluminanceLux(1)).epsilon(1e-5));
}

TEST_CASE("spectral: per-wavelength coefficients reproduce the model's three channels") {
    const AtmosphereParams p;
    AtmosphereParams q = paramsAtWavelengths(p, {680.0, 550.0, 440.0});
    for (int k = 0; k < 3; ++k) {
        CHECK(q.rayleigh_scattering[k] == doctest::Approx(p.rayleigh_scattering[k]).epsilon(0.002));
        CHECK(q.mie_scattering[k] == doctest::Approx(p.mie_scattering[k]));
        CHECK(q.ozone_absorption[k] == doctest::Approx(p.ozone_absorption[k]).epsilon(0.01));
    }
    // Twice the ozone column gives twice the absorption at every wavelength.
    AtmosphereParams thick = p;
    thick.ozone_absorption *= 2.0;
    CHECK(paramsAtWavelengths(thick, {600.0, 500.0, 400.0}).ozone_absorption.x ==
          doctest::Approx(2.0 * paramsAtWavelengths(p, {600.0, 500.0, 400.0}).ozone_absorption.x));
}

TEST_CASE("spectral: the GPU path's colour agrees with the spectral reference within 2 % median") {
    MESSAGE("three samples read as linear sRGB (before):\n" << agreementTable(false));
    MESSAGE("three samples through skyColourMatrix() (after):\n" << agreementTable(true));
    for (const SpectralRow& row : spectralRows()) {
        RowErrors e = rowErrors(row, skyColourMatrix(std::cos(glm::radians(row.sun_zenith_deg))));
        INFO("altitude " << row.altitude_m << " m, sun zenith " << row.sun_zenith_deg << " deg");
        CHECK(e.luminance.median < 0.02);
        CHECK(e.r_over_g.median < 0.02);
        CHECK(e.b_over_g.median < 0.02);
    }
    // The old reading is measurably off in colour: the test can tell the two apart.
    std::vector<double> old_rg;
    for (const SpectralRow& row : spectralRows()) old_rg.push_back(rowErrors(row, glm::dmat3(1.0)).r_over_g.median);
    CHECK(errorStats(old_rg).median > 0.03);
}

TEST_CASE("spectral: the stored sky colour matrices are the fit") {
    for (int z = 0; z < kSkyColourZenithCount; ++z) {
        std::vector<glm::dvec3> samples, targets;
        for (const SpectralRow& row : spectralRows()) {
            if (row.sun_zenith_deg != skyColourZenithsDeg()[std::size_t(z)]) continue;
            for (std::size_t i = 0; i < row.samples.size(); ++i) {
                samples.push_back(row.samples[i]);
                targets.push_back(row.reference[i].rgb / kSolarIlluminanceLux);
            }
        }
        glm::dmat3 fit = fitSkyColourMatrix(samples, targets), stored = skyColourMatrixAt(z);
        char text[512];
        std::snprintf(text, sizeof text, "sun zenith %g: {%.5f, %.5f, %.5f, %.5f, %.5f, %.5f, %.5f, %.5f, %.5f},",
                      skyColourZenithsDeg()[std::size_t(z)], fit[0][0], fit[0][1], fit[0][2], fit[1][0], fit[1][1],
                      fit[1][2], fit[2][0], fit[2][1], fit[2][2]);
        MESSAGE(text);
        for (int c = 0; c < 3; ++c)
            for (int r = 0; r < 3; ++r) CHECK(stored[c][r] == doctest::Approx(fit[c][r]).epsilon(0.01).scale(0.05));
    }
    // Between the fitted zeniths the renderer interpolates; beyond 80 deg it keeps the last.
    CHECK(skyColourMatrix(std::cos(glm::radians(95.0)))[0][0] == doctest::Approx(skyColourMatrixAt(kSkyColourZenithCount - 1)[0][0]));
    CHECK(skyColourMatrix(std::cos(glm::radians(30.0)))[1][1] ==
          doctest::Approx(0.5 * (skyColourMatrixAt(1)[1][1] + skyColourMatrixAt(2)[1][1])).epsilon(1e-6));
}

namespace {

// Relative errors of a linear sRGB colour against another, as colourError().
ColourError sunColourError(glm::dvec3 rgb, glm::dvec3 reference) {
    return colourError(rgb, SkyColour{reference, srgbLuminance(reference)});
}

}  // namespace

TEST_CASE("spectral: sunlightRgb() turns the three transmittance samples into the spectral reference's sun") {
    const AtmosphereParams p;
    const SunlightConversion conversion = sunlightConversion(p);
    // The unattenuated sun: luminance 1, the solar spectrum's colour.
    const glm::dvec3 top = sunlightRgb(conversion, glm::dvec3(1.0));
    CHECK(srgbLuminance(top) == doctest::Approx(1.0).epsilon(1e-4));  // sRGB's luminance row is Y to 4 digits
    CHECK(top.r / top.g == doctest::Approx(1.11).epsilon(0.02));
    const double lux_per_unit = spectralSolarIlluminanceLux(2);
    std::string table = "sun zenith, altitude: luminance new/old - 1, r/g and b/g error new / old (%)\n";
    double worst_new = 0.0, worst_old_low_sun = 0.0;
    for (double altitude : {0.0, 2000.0, 10000.0})
        for (double zenith : {0.0, 60.0, 80.0, 85.0, 89.0}) {
            const glm::dvec3 sun = sunDirectionFromZenith(zenith);
            const glm::dvec3 t = sunTransmittance(p, glm::dvec3(0.0, altitude, 0.0), sun, 64);
            const SkyColour reference = spectralSunColour(p, altitude, sun, 2, 64);
            const glm::dvec3 now = sunlightRgb(conversion, t) * lux_per_unit;
            const glm::dvec3 old = t * lux_per_unit;  // the samples read as linear sRGB under a white sun
            const ColourError e_new = sunColourError(now, reference.rgb), e_old = sunColourError(old, reference.rgb);
            worst_new = std::max({worst_new, e_new.luminance, e_new.r_over_g, e_new.b_over_g});
            if (zenith >= 85.0) worst_old_low_sun = std::max({worst_old_low_sun, e_old.r_over_g, e_old.b_over_g});
            char line[200];
            std::snprintf(line, sizeof line, "%4.0f deg, %5.0f m: %+6.2f   %.4f / %.1f   %.4f / %.1f\n", zenith, altitude,
                          100.0 * (srgbLuminance(now) / srgbLuminance(old) - 1.0), 100.0 * e_new.r_over_g,
                          100.0 * e_old.r_over_g, 100.0 * e_new.b_over_g, 100.0 * e_old.b_over_g);
            table += line;
        }
    MESSAGE(table);
    // The conversion is exact for the model: only rounding separates it from the reference.
    CHECK(worst_new < 1e-6);
    // ... and the old reading is far off towards a low sun, so the check can tell them apart.
    CHECK(worst_old_low_sun > 0.2);
}

TEST_CASE("spectral: sunlightRgb() without ozone, and in the planet's shadow") {
    AtmosphereParams p;
    p.ozone_absorption = glm::dvec3(0.0);
    const SunlightConversion conversion = sunlightConversion(p);
    const glm::dvec3 sun = sunDirectionFromZenith(80.0);
    const glm::dvec3 now = sunlightRgb(conversion, sunTransmittance(p, glm::dvec3(0.0), sun, 64));
    const SkyColour reference = spectralSunColour(p, 0.0, sun, 2, 64);
    const ColourError e = sunColourError(now * spectralSolarIlluminanceLux(2), reference.rgb);
    CHECK(e.luminance < 1e-6);
    CHECK(e.r_over_g < 1e-6);
    CHECK(e.b_over_g < 1e-6);
    const glm::dvec3 dark = sunlightRgb(conversion, glm::dvec3(0.0));
    CHECK(std::isfinite(dark.r + dark.g + dark.b));
    CHECK(srgbLuminance(dark) < 1e-20);
}
