// Spectral reference of the sky's colour and the GPU path's three-sample conversion.
//
// Sources of the tabulated data (typed from the published tables, every 10 nm, 380..780 nm):
// - CIE 1931 2 deg standard observer colour matching functions: CIE 015:2018 "Colorimetry",
//   table of the 1931 observer (also ISO/CIE 11664-1), the 10 nm rows.
// - Extraterrestrial solar spectral irradiance: ASTM G-173-03 "Reference Solar Spectral
//   Irradiance", extraterrestrial (ETR) column, averaged over each 10 nm bin [lambda,
//   lambda + 10) (NREL RReDC). Its luminous integral, 683 lm/W x sum(y-bar E) x 10 nm, is
//   132,552 lx: vista's kSolarIlluminanceLux (sky/night_light.h), so the reference's sun and
//   the renderer's are the same (before issue 23 the constant was 127,250 lx, 1361 W/m^2 x
//   93.5 lm/W, 4 % low, and the colour matrices below carried the difference).
// - Ozone absorption cross-sections: Serdyuchenko et al. 2014, "High spectral resolution
//   ozone absorption cross-sections" (Atmos. Meas. Tech. 7, 625-636; IUP Bremen data set), at
//   293 K, sampled every 10 nm (the values Bruneton 2017 uses for its ozone layer).
#include "sky/atmosphere_spectral.h"

#include <glm/common.hpp>
#include <glm/exponential.hpp>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace vista {

namespace {

constexpr double kReferenceNm = 550.0;  // the model's green channel: Rayleigh and ozone scale from it
constexpr double kOzoneCrossSection550 = 3.5e-25;  // m^2, Serdyuchenko et al. 2014 at 550 nm, 293 K

// The three channels' transfer factors (1/sr per unit solar irradiance) towards view_dir from
// altitude_m: in-scattering, plus the sunlit Lambertian ground at the ray's end with `ground`.
glm::dvec3 transferFactors(const AtmosphereParams& p, const MultipleScatteringTable& ms, const IntegrationSteps& steps,
                           double altitude_m, glm::dvec3 view_dir, glm::dvec3 sun_dir, bool ground) {
    const glm::dvec3 camera(0.0, altitude_m, 0.0);
    ViewRayResult ray = integrateViewRay(p, camera, view_dir, sun_dir, std::numeric_limits<double>::infinity(), steps, &ms);
    glm::dvec3 l = ray.radiance;
    if (ground && ray.hits_ground) {
        glm::dvec3 end = camera + ray.distance * glm::normalize(view_dir);
        glm::dvec3 up = glm::normalize(planetFromWorld(p, end));
        double mu_s = glm::dot(up, glm::normalize(sun_dir));
        if (mu_s > 0.0)
            l += ray.transmittance * (p.ground_albedo / std::numbers::pi) * mu_s *
                 sunTransmittance(p, end, sun_dir, steps.transmittance);
    }
    return l;
}

}  // namespace

const std::array<SpectralSample, kSpectralTableSize>& spectralTable() {
    static const std::array<SpectralSample, kSpectralTableSize> table = {{
        // nm, ETR W m^-2 nm^-1, O3 m^2, CIE 1931 x-bar, y-bar, z-bar
        {380, 1.01249, 2.818e-28, {0.001368, 0.000039, 0.006450}},
        {390, 1.14716, 6.636e-28, {0.004243, 0.000120, 0.020050}},
        {400, 1.72765, 1.527e-27, {0.014310, 0.000396, 0.067850}},
        {410, 1.73054, 2.763e-27, {0.043510, 0.001210, 0.207400}},
        {420, 1.68870, 5.520e-27, {0.134380, 0.004000, 0.645600}},
        {430, 1.61253, 8.451e-27, {0.283900, 0.011600, 1.385600}},
        {440, 1.91198, 1.582e-26, {0.348280, 0.023000, 1.747060}},
        {450, 2.03474, 2.316e-26, {0.336200, 0.038000, 1.772110}},
        {460, 2.02042, 3.669e-26, {0.290800, 0.060000, 1.669200}},
        {470, 2.02212, 4.924e-26, {0.195360, 0.090980, 1.287640}},
        {480, 1.93377, 7.752e-26, {0.095640, 0.139020, 0.812950}},
        {490, 1.95809, 9.016e-26, {0.032010, 0.208020, 0.465180}},
        {500, 1.91686, 1.480e-25, {0.004900, 0.323000, 0.272000}},
        {510, 1.82980, 1.602e-25, {0.009300, 0.503000, 0.158200}},
        {520, 1.86850, 2.139e-25, {0.063270, 0.710000, 0.078250}},
        {530, 1.89310, 2.755e-25, {0.165500, 0.862000, 0.042160}},
        {540, 1.85149, 3.091e-25, {0.290400, 0.954000, 0.020300}},
        {550, 1.85040, 3.500e-25, {0.433450, 0.994950, 0.008750}},
        {560, 1.83410, 4.266e-25, {0.594500, 0.995000, 0.003900}},
        {570, 1.83450, 4.672e-25, {0.762100, 0.952000, 0.002100}},
        {580, 1.81470, 4.398e-25, {0.916300, 0.870000, 0.001650}},
        {590, 1.78158, 4.701e-25, {1.026300, 0.757000, 0.001100}},
        {600, 1.75330, 5.019e-25, {1.062200, 0.631000, 0.000800}},
        {610, 1.69650, 4.305e-25, {1.002600, 0.503000, 0.000340}},
        {620, 1.68194, 3.740e-25, {0.854450, 0.381000, 0.000190}},
        {630, 1.64654, 3.215e-25, {0.642400, 0.265000, 0.000050}},
        {640, 1.60480, 2.662e-25, {0.447900, 0.175000, 0.000020}},
        {650, 1.52143, 2.238e-25, {0.283500, 0.107000, 0.000000}},
        {660, 1.55622, 1.852e-25, {0.164900, 0.061000, 0.000000}},
        {670, 1.51130, 1.473e-25, {0.087400, 0.032000, 0.000000}},
        {680, 1.47400, 1.209e-25, {0.046770, 0.017000, 0.000000}},
        {690, 1.44820, 9.423e-26, {0.022700, 0.008210, 0.000000}},
        {700, 1.41018, 7.455e-26, {0.011359, 0.004102, 0.000000}},
        {710, 1.36775, 6.566e-26, {0.005790, 0.002091, 0.000000}},
        {720, 1.34188, 5.105e-26, {0.002899, 0.001047, 0.000000}},
        {730, 1.31429, 4.150e-26, {0.001440, 0.000520, 0.000000}},
        {740, 1.28303, 4.228e-26, {0.000690, 0.000249, 0.000000}},
        {750, 1.26758, 3.237e-26, {0.000332, 0.000120, 0.000000}},
        {760, 1.23670, 2.451e-26, {0.000166, 0.000060, 0.000000}},
        {770, 1.20820, 2.801e-26, {0.000083, 0.000030, 0.000000}},
        {780, 1.18737, 2.534e-26, {0.000042, 0.000015, 0.000000}},
    }};
    return table;
}

glm::dvec3 linearSrgbFromXyz(glm::dvec3 xyz) {
    return {3.2406 * xyz.x - 1.5372 * xyz.y - 0.4986 * xyz.z, -0.9689 * xyz.x + 1.8758 * xyz.y + 0.0415 * xyz.z,
            0.0557 * xyz.x - 0.2040 * xyz.y + 1.0570 * xyz.z};
}

double spectralSolarIlluminanceLux(int stride) {
    stride = std::max(stride, 1);
    double y = 0.0;
    for (int i = 0; i < kSpectralTableSize; i += stride)
        y += spectralTable()[std::size_t(i)].cmf.y * spectralTable()[std::size_t(i)].solar_irradiance;
    return kLuminousEfficacy * y * kSpectralTableStepNm * stride;
}

namespace {

double ozoneCrossSection(double nm) {
    const auto& t = spectralTable();
    double f = std::clamp((nm - t.front().wavelength_nm) / kSpectralTableStepNm, 0.0, double(kSpectralTableSize - 1));
    int i = std::min(int(f), kSpectralTableSize - 2);
    double a = f - i;
    return (1.0 - a) * t[std::size_t(i)].ozone_cross_section + a * t[std::size_t(i) + 1].ozone_cross_section;
}

}  // namespace

AtmosphereParams paramsAtWavelengths(const AtmosphereParams& base, glm::dvec3 wavelengths_nm) {
    AtmosphereParams p = base;
    const double ozone_density = base.ozone_absorption.y / kOzoneCrossSection550;  // molecules / m^3 at the peak
    for (int k = 0; k < 3; ++k) {
        double ratio = kReferenceNm / wavelengths_nm[k];
        p.rayleigh_scattering[k] = base.rayleigh_scattering.y * ratio * ratio * ratio * ratio;
        p.mie_scattering[k] = base.mie_scattering.y;
        p.mie_extinction[k] = base.mie_extinction.y;
        p.ozone_absorption[k] = ozoneCrossSection(wavelengths_nm[k]) * ozone_density;
        p.ground_albedo[k] = base.ground_albedo.y;
    }
    p.solar_irradiance = glm::dvec3(1.0);
    return p;
}

struct SpectralSkyReference::Run {
    Run(const AtmosphereParams& params, const IntegrationSteps& steps, int altitude_size, int mu_s_size)
        : p(params), ms(params, steps, altitude_size, mu_s_size) {}
    AtmosphereParams p;
    MultipleScatteringTable ms;
    // Per channel: the XYZ a unit transfer factor contributes, 683 cmf E dlambda (0 for padding).
    std::array<glm::dvec3, 3> weight{};
};

SpectralSkyReference::SpectralSkyReference(const AtmosphereParams& base, int stride, const IntegrationSteps& steps,
                                           int ms_altitude_size, int ms_mu_s_size)
    : steps_(steps) {
    stride = std::max(stride, 1);
    std::vector<int> rows;
    for (int i = 0; i < kSpectralTableSize; i += stride) rows.push_back(i);
    for (int i : rows) wavelengths_.push_back(spectralTable()[std::size_t(i)].wavelength_nm);
    const double dl = kSpectralTableStepNm * stride;
    for (std::size_t first = 0; first < rows.size(); first += 3) {
        glm::dvec3 nm;
        std::array<glm::dvec3, 3> weight{};
        for (std::size_t k = 0; k < 3; ++k) {
            std::size_t j = std::min(first + k, rows.size() - 1);  // the last run repeats its last wavelength
            const SpectralSample& s = spectralTable()[std::size_t(rows[j])];
            nm[int(k)] = s.wavelength_nm;
            if (first + k < rows.size()) weight[k] = kLuminousEfficacy * s.cmf * s.solar_irradiance * dl;
        }
        runs_.push_back(std::make_unique<Run>(paramsAtWavelengths(base, nm), steps, ms_altitude_size, ms_mu_s_size));
        runs_.back()->weight = weight;
    }
}

SpectralSkyReference::~SpectralSkyReference() = default;

SkyColour SpectralSkyReference::radiance(double altitude_m, glm::dvec3 view_dir, glm::dvec3 sun_dir, bool ground) const {
    glm::dvec3 xyz(0.0);
    for (const auto& run : runs_) {
        glm::dvec3 t = transferFactors(run->p, run->ms, steps_, altitude_m, view_dir, sun_dir, ground);
        for (int k = 0; k < 3; ++k) xyz += run->weight[std::size_t(k)] * t[k];
    }
    return {linearSrgbFromXyz(xyz), xyz.y};
}

double SpectralSkyReference::sunIlluminanceLux(double altitude_m, glm::dvec3 sun_dir) const {
    double y = 0.0;
    for (const auto& run : runs_) {
        glm::dvec3 t = sunTransmittance(run->p, glm::dvec3(0.0, altitude_m, 0.0), sun_dir, steps_.transmittance);
        for (int k = 0; k < 3; ++k) y += run->weight[std::size_t(k)].y * t[k];
    }
    return y;
}

ThreeSampleSky::ThreeSampleSky(const AtmosphereParams& p, const IntegrationSteps& steps, int ms_altitude_size,
                               int ms_mu_s_size)
    : p_(p), steps_(steps), ms_(p, steps, ms_altitude_size, ms_mu_s_size) {}

glm::dvec3 ThreeSampleSky::samples(double altitude_m, glm::dvec3 view_dir, glm::dvec3 sun_dir, bool ground) const {
    return transferFactors(p_, ms_, steps_, altitude_m, view_dir, sun_dir, ground);
}

glm::dvec3 ThreeSampleSky::sunTransmittance(double altitude_m, glm::dvec3 sun_dir) const {
    return vista::sunTransmittance(p_, glm::dvec3(0.0, altitude_m, 0.0), sun_dir, steps_.transmittance);
}

const std::array<double, kSkyColourZenithCount>& skyColourZenithsDeg() {
    static const std::array<double, kSkyColourZenithCount> zeniths = {0.0, 20.0, 40.0, 60.0, 70.0, 80.0};
    return zeniths;
}

glm::dmat3 skyColourMatrixAt(int zenith_index) {
    // Columns: what one unit of the 680, 550 and 440 nm samples adds to linear sRGB, per sun
    // zenith of skyColourZenithsDeg(). Fitted over altitudes 0..10 km and all view directions;
    // regenerate with the "spectral: the stored sky colour matrices are the fit" test's message.
    static const double kColumns[kSkyColourZenithCount][9] = {
        {0.92814, -0.12922, -0.12083, 0.22577, 1.12338, 0.19363, -0.02699, -0.02923, 0.88382},
        {0.95843, -0.13845, -0.12785, 0.19675, 1.13212, 0.20039, -0.02102, -0.03102, 0.88246},
        {0.98521, -0.14807, -0.13454, 0.16462, 1.14257, 0.20843, -0.01429, -0.03309, 0.88086},
        {0.96085, -0.14492, -0.13182, 0.16377, 1.14451, 0.21191, -0.01388, -0.03315, 0.88032},
        {0.91078, -0.13409, -0.12492, 0.18377, 1.13955, 0.21278, -0.01823, -0.03151, 0.88049},
        {0.81870, -0.11388, -0.11455, 0.21586, 1.12875, 0.21970, -0.02757, -0.02688, 0.88062},
    };
    const double* c = kColumns[std::clamp(zenith_index, 0, kSkyColourZenithCount - 1)];
    return glm::dmat3(c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7], c[8]);
}

glm::dmat3 skyColourMatrix(double sun_mu) {
    const auto& z = skyColourZenithsDeg();
    double zenith = glm::degrees(std::acos(std::clamp(sun_mu, -1.0, 1.0)));
    if (zenith <= z.front()) return skyColourMatrixAt(0);
    for (int i = 0; i + 1 < kSkyColourZenithCount; ++i)
        if (zenith <= z[std::size_t(i) + 1]) {
            double a = (zenith - z[std::size_t(i)]) / (z[std::size_t(i) + 1] - z[std::size_t(i)]);
            return (1.0 - a) * skyColourMatrixAt(i) + a * skyColourMatrixAt(i + 1);
        }
    return skyColourMatrixAt(kSkyColourZenithCount - 1);
}

glm::dvec3 sunDirectionFromZenith(double sun_zenith_deg) {
    double z = glm::radians(sun_zenith_deg);
    return {std::sin(z), std::cos(z), 0.0};
}

glm::dvec3 viewDirectionFromAngles(double view_zenith_deg, double view_azimuth_deg) {
    double z = glm::radians(view_zenith_deg), a = glm::radians(view_azimuth_deg);
    return {std::sin(z) * std::cos(a), std::cos(z), std::sin(z) * std::sin(a)};
}

std::vector<SkyGeometry> skyAgreementViews(double altitude_m, double sun_zenith_deg) {
    std::vector<SkyGeometry> views;
    for (int zenith = 0; zenith <= 170; zenith += 10) {
        if (altitude_m <= 0.0 && zenith > 90) continue;  // no air between the camera and the ground
        for (int azimuth = 0; azimuth <= 180; azimuth += 30) {
            views.push_back({altitude_m, sun_zenith_deg, double(zenith), double(azimuth)});
            if (zenith == 0) break;  // every azimuth is the same ray
        }
    }
    return views;
}

glm::dmat3 fitSkyColourMatrix(const std::vector<glm::dvec3>& samples, const std::vector<glm::dvec3>& targets) {
    // Normal equations per output channel, rows weighted by 1 / luminance^2 of the target.
    glm::dmat3 ata(0.0);
    glm::dmat3 atb(0.0);  // column c: sum w s target_c
    for (std::size_t i = 0; i < samples.size() && i < targets.size(); ++i) {
        double lum = srgbLuminance(targets[i]);
        if (!(lum > 0.0)) continue;
        double w = 1.0 / (lum * lum);
        const glm::dvec3& s = samples[i];
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b) ata[a][b] += w * s[a] * s[b];
        for (int c = 0; c < 3; ++c) atb[c] += w * s * targets[i][c];
    }
    glm::dmat3 inv = glm::inverse(ata);
    glm::dmat3 m(0.0);
    for (int c = 0; c < 3; ++c) {
        glm::dvec3 row = inv * atb[c];  // output channel c = dot(row, samples)
        for (int k = 0; k < 3; ++k) m[k][c] = row[k];
    }
    return m;
}

ColourError colourError(glm::dvec3 rgb, const SkyColour& reference) {
    auto rel = [](double a, double b) { return std::abs(b) > 0.0 ? std::abs(a / b - 1.0) : 0.0; };
    const glm::dvec3& r = reference.rgb;
    return {rel(srgbLuminance(rgb), reference.luminance), rel(rgb.x / rgb.y, r.x / r.y), rel(rgb.z / rgb.y, r.z / r.y)};
}

ErrorStats errorStats(std::vector<double> errors) {
    ErrorStats s;
    if (errors.empty()) return s;
    std::sort(errors.begin(), errors.end());
    auto at = [&](double q) { return errors[std::min(errors.size() - 1, std::size_t(q * double(errors.size() - 1) + 0.5))]; };
    s.median = at(0.5);
    s.p95 = at(0.95);
    s.max = errors.back();
    return s;
}

SunlightConversion sunlightConversion(const AtmosphereParams& p) {
    // A: the samples' optical depth per unit of each column (rows: samples; columns: Rayleigh,
    // Mie, ozone). A species with no extinction in any sample (no ozone, say) has no column to
    // find and none to spend, so the pseudo-inverse (Tikhonov, a 1e-12 share of the trace) drops it.
    glm::dmat3 a;  // glm: a[column][row]
    for (int k = 0; k < 3; ++k) {
        a[0][k] = p.rayleigh_scattering[k];
        a[1][k] = p.mie_extinction[k];
        a[2][k] = p.ozone_absorption[k];
    }
    glm::dmat3 ata = glm::transpose(a) * a;
    const double eps = 1e-12 * (ata[0][0] + ata[1][1] + ata[2][2]) + 1e-300;
    for (int k = 0; k < 3; ++k) ata[k][k] += eps;
    const glm::dmat3 columns_from_depth = glm::inverse(ata) * glm::transpose(a);  // C = this * tau_samples
    SunlightConversion c;
    glm::dvec3 sum_xyz(0.0);
    std::array<glm::dvec3, kSunlightWavelengths> xyz{};
    for (int i = 0; i < kSunlightWavelengths; ++i) {
        const SpectralSample& s = spectralTable()[std::size_t(2 * i)];
        const AtmosphereParams w = paramsAtWavelengths(p, glm::dvec3(s.wavelength_nm));
        const glm::dvec3 b(w.rayleigh_scattering.x, w.mie_extinction.x, w.ozone_absorption.x);
        c.depth[std::size_t(i)] = glm::transpose(columns_from_depth) * b;  // tau_i = b . C = (M^T b) . tau_samples
        xyz[std::size_t(i)] = s.cmf * s.solar_irradiance;
        sum_xyz += xyz[std::size_t(i)];
    }
    for (int i = 0; i < kSunlightWavelengths; ++i) c.rgb[std::size_t(i)] = linearSrgbFromXyz(xyz[std::size_t(i)] / sum_xyz.y);
    return c;
}

glm::dvec3 sunlightRgb(const SunlightConversion& c, glm::dvec3 t) {
    if (t.x <= 0.0 && t.y <= 0.0 && t.z <= 0.0) return glm::dvec3(0.0);  // blocked (the planet): none at any wavelength
    const glm::dvec3 depth = -glm::log(glm::max(t, glm::dvec3(1e-300)));
    glm::dvec3 rgb(0.0);
    for (int i = 0; i < kSunlightWavelengths; ++i)
        rgb += c.rgb[std::size_t(i)] * std::exp(-std::max(glm::dot(c.depth[std::size_t(i)], depth), 0.0));
    return rgb;
}

SkyColour spectralSunColour(const AtmosphereParams& base, double altitude_m, glm::dvec3 sun_dir, int stride,
                            int transmittance_steps) {
    stride = std::max(stride, 1);
    glm::dvec3 xyz(0.0);
    const double dl = kSpectralTableStepNm * stride;
    for (int i = 0; i < kSpectralTableSize; i += stride) {
        const SpectralSample& s = spectralTable()[std::size_t(i)];
        const AtmosphereParams w = paramsAtWavelengths(base, glm::dvec3(s.wavelength_nm));
        const double t = sunTransmittance(w, glm::dvec3(0.0, altitude_m, 0.0), sun_dir, transmittance_steps).x;
        xyz += kLuminousEfficacy * s.cmf * s.solar_irradiance * dl * t;
    }
    return {linearSrgbFromXyz(xyz), xyz.y};
}

}  // namespace vista
