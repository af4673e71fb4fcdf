// Spectral CPU reference of the sky's colour: the double-precision reference
// (sky/atmosphere_reference.h) run at many wavelengths, three at a time, under the
// extraterrestrial solar spectrum, and integrated against the CIE 1931 colour matching
// functions to XYZ, linear sRGB and luminance in cd/m^2. Also the conversion the GPU path uses
// from its three monochromatic samples (680/550/440 nm) to linear sRGB, and the fit that
// derives that conversion from this reference.
//
// Per wavelength: Rayleigh scattering scales as lambda^-4 from the model's 550 nm value, Mie is
// grey (Bruneton 2017's Angstrom exponent 0), ozone absorption is the cross-section table times
// the number density that reproduces the model's 550 nm value, ground albedo is grey.
#pragma once

#include "sky/atmosphere_model.h"
#include "sky/atmosphere_reference.h"

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <memory>
#include <vector>

namespace vista {

// One row of the tabulated physical data, every 10 nm from 380 to 780 nm.
struct SpectralSample {
    double wavelength_nm;
    double solar_irradiance;     //!< W m^-2 nm^-1 at the top of the atmosphere
    double ozone_cross_section;  //!< m^2 per molecule
    glm::dvec3 cmf;              //!< CIE 1931 2 deg x-bar, y-bar, z-bar
};
inline constexpr int kSpectralTableSize = 41;
inline constexpr double kSpectralTableStepNm = 10.0;
const std::array<SpectralSample, kSpectralTableSize>& spectralTable();

inline constexpr double kLuminousEfficacy = 683.0;  //!< lm/W at 555 nm (the candela's definition)

// Linear sRGB (IEC 61966-2-1, D65 white) from CIE XYZ; Y maps to 0.2126 R + 0.7152 G + 0.0722 B.
glm::dvec3 linearSrgbFromXyz(glm::dvec3 xyz);
inline double srgbLuminance(glm::dvec3 rgb) { return 0.2126 * rgb.x + 0.7152 * rgb.y + 0.0722 * rgb.z; }

// The solar illuminance at the top of the atmosphere, lux: 683 sum(y-bar E dlambda) over the
// wavelengths a reference with this stride uses.
double spectralSolarIlluminanceLux(int stride = 2);

// The model's parameters at three wavelengths (nm) as its three channels, solar_irradiance 1.
AtmosphereParams paramsAtWavelengths(const AtmosphereParams& base, glm::dvec3 wavelengths_nm);

// Sky radiance in physical units: linear sRGB scaled so that srgbLuminance() is cd/m^2.
struct SkyColour {
    glm::dvec3 rgb{0.0};     //!< linear sRGB, cd/m^2 per unit of luminance weight
    double luminance = 0.0;  //!< cd/m^2
};

// The spectral reference: every stride-th wavelength of spectralTable() (stride 2: 21
// wavelengths, 380..780 nm every 20 nm; stride 1: 41), three per run of the reference, each run
// with its own multiple-scattering table. Building costs one MultipleScatteringTable per three
// wavelengths.
class SpectralSkyReference {
public:
    explicit SpectralSkyReference(const AtmosphereParams& base, int stride = 2, const IntegrationSteps& steps = {},
                                  int ms_altitude_size = 32, int ms_mu_s_size = 128);
    ~SpectralSkyReference();
    int wavelengthCount() const { return int(wavelengths_.size()); }
    // Sky radiance (in-scattering, no sun disk, no ground) seen from altitude_m towards
    // view_dir with the sun towards sun_dir (vista's world, y up); ground_albedo > 0 adds the
    // sunlit Lambertian ground at the ray's end, seen through the air (no skylight on it).
    SkyColour radiance(double altitude_m, glm::dvec3 view_dir, glm::dvec3 sun_dir, bool ground = false) const;
    // Illuminance (lux) on a surface facing the sun at altitude_m: the transmitted direct sun.
    double sunIlluminanceLux(double altitude_m, glm::dvec3 sun_dir) const;

private:
    struct Run;
    std::vector<double> wavelengths_;
    std::vector<std::unique_ptr<Run>> runs_;
    IntegrationSteps steps_;
};

// What the GPU path computes, on the CPU: the reference at the model's three wavelengths (its
// own channels), converted to physical units by `colour` (cd/m^2-scaled linear sRGB per unit of
// transfer factor). colour = kSolarIlluminanceLux * I is the old reading (three monochromatic
// samples as linear sRGB under a white sun).
class ThreeSampleSky {
public:
    explicit ThreeSampleSky(const AtmosphereParams& p, const IntegrationSteps& steps = {}, int ms_altitude_size = 32,
                            int ms_mu_s_size = 128);
    // The three channels' transfer factors (1/sr per unit solar irradiance), as the LUTs hold them.
    glm::dvec3 samples(double altitude_m, glm::dvec3 view_dir, glm::dvec3 sun_dir, bool ground = false) const;
    glm::dvec3 sunTransmittance(double altitude_m, glm::dvec3 sun_dir) const;

private:
    AtmosphereParams p_;
    IntegrationSteps steps_;
    MultipleScatteringTable ms_;
};

// The conversion the GPU path applies to its three samples: linear sRGB per unit of transfer
// factor, in units of the solar illuminance (multiply by sun_illuminance for HDR units, by
// kSolarIlluminanceLux for cd/m^2). One 3x3 matrix does not fit every sun height (the ozone's
// Chappuis band at ~600 nm, between the 550 and 680 nm samples, reddens a low sun's light in a
// way the samples miss), so there is one per sun zenith of skyColourZenithsDeg(), each fitted by
// fitSkyColourMatrix() over altitudes 0..10 km and all view directions, and the renderer takes
// the linear interpolation at its sun (the 80 deg matrix below that, twilight included). The
// spectral test rebuilds the fits and checks the stored matrices match them.
inline constexpr int kSkyColourZenithCount = 6;
const std::array<double, kSkyColourZenithCount>& skyColourZenithsDeg();
glm::dmat3 skyColourMatrixAt(int zenith_index);
glm::dmat3 skyColourMatrix(double sun_mu);  // sun_mu: cos of the sun's zenith angle

// The colour of direct sunlight after the atmosphere, from the three transmittance samples the
// GPU path has (680/550/440 nm). Along any path the model's transmittance is exp(-tau) with
// tau(lambda) = Rayleigh(lambda) C_R + Mie C_M + ozone(lambda) C_O for three columns; Mie (and
// the height fog, and the grey share of the disk above the horizon) is grey. So the three samples'
// optical depths give the three columns exactly, and the columns give tau at every wavelength of
// the spectral reference: tau(lambda) = depth[i] . (-log T_samples). The transmitted colour is then
// sum_i rgb[i] exp(-tau_i), the spectral reference's sum (solar spectrum, CIE 1931, linear sRGB).
// Products of transmittances (a ray to the ground, then to the sun) are paths too. Exact for the
// model, up to the float LUT on the GPU; 21 exponentials per evaluation.
inline constexpr int kSunlightWavelengths = 21;  // the reference's stride 2: 380..780 nm every 20 nm
struct SunlightConversion {
    std::array<glm::dvec3, kSunlightWavelengths> depth{};  //!< tau_i per unit optical depth of each sample
    std::array<glm::dvec3, kSunlightWavelengths> rgb{};    //!< linear sRGB, in units of the solar illuminance
};
// For the atmosphere p (its own three channel coefficients); sum rgb has luminance 1 (the
// unattenuated sun: linear sRGB about (1.09, 0.98, 0.96)).
SunlightConversion sunlightConversion(const AtmosphereParams& p);
// Linear sRGB of sunlight (units of the solar illuminance) after a path of transmittance t.
glm::dvec3 sunlightRgb(const SunlightConversion& c, glm::dvec3 t);

// The spectral reference's direct sun at altitude_m (lux, linear sRGB scaled to luminance): the
// solar spectrum times the transmittance at each of the reference's wavelengths (no tables).
SkyColour spectralSunColour(const AtmosphereParams& base, double altitude_m, glm::dvec3 sun_dir, int stride = 2,
                            int transmittance_steps = 64);

// One geometry of the agreement tables and the fit.
struct SkyGeometry {
    double altitude_m, sun_zenith_deg, view_zenith_deg, view_azimuth_deg;
};
// Unit vectors in vista's world: the sun in the x-y plane (azimuth 0 = towards +x), the view
// at view_azimuth_deg from the sun's azimuth.
glm::dvec3 sunDirectionFromZenith(double sun_zenith_deg);
glm::dvec3 viewDirectionFromAngles(double view_zenith_deg, double view_azimuth_deg);

// Every view direction of the agreement tables for one (altitude, sun zenith): view zenith
// 0..170 every 10 deg (rays that end on the ground included, with no ground term) and azimuth
// 0..180 every 30 deg from the sun; rays with no air in front of them are left out.
std::vector<SkyGeometry> skyAgreementViews(double altitude_m, double sun_zenith_deg);

// Weighted least squares: the matrix M minimising sum |(M samples_i - target_i) / lum(target_i)|^2.
glm::dmat3 fitSkyColourMatrix(const std::vector<glm::dvec3>& samples, const std::vector<glm::dvec3>& targets);

// Relative errors of a GPU-path colour against the reference: luminance and the r/g and b/g
// chromaticity ratios, each |a / b - 1|.
struct ColourError {
    double luminance, r_over_g, b_over_g;
};
ColourError colourError(glm::dvec3 rgb, const SkyColour& reference);

// Median, 95th percentile and maximum of a set of errors (empty: zeros).
struct ErrorStats {
    double median = 0.0, p95 = 0.0, max = 0.0;
};
ErrorStats errorStats(std::vector<double> errors);

}  // namespace vista
