// The physically based atmosphere model shared by the CPU reference and the GPU LUTs: Earth
// parameters, density profiles, phase functions, ray/sphere geometry in the planet frame, and
// the sun's direction from latitude, day of year and solar time. Double precision, no GL.
#pragma once

#include <glm/vec3.hpp>

namespace vista {

// The three spectral samples every radiance and coefficient below is given at ("RGB"):
// the wavelengths of Bruneton's demo, at which Hillaire 2020's Earth coefficients were computed.
inline constexpr double kAtmosphereWavelengthsNm[3] = {680.0, 550.0, 440.0};

// Cornette-Shanks is the default: it is what Bruneton uses, it keeps the (1 + cos^2) shape that
// Mie scattering tends to for small particles (so g -> 0 gives Rayleigh, not isotropic), and it
// has a weaker back-scatter lobe than Henyey-Greenstein, closer to real Mie curves. Hillaire's
// demo uses Henyey-Greenstein; both are normalised, cost the same, and the GPU code must pick
// the same one as the reference it is compared against.
enum class MiePhase : int { CornetteShanks, HenyeyGreenstein };

// Earth defaults after Bruneton 2017 (ebruneton/precomputed_atmospheric_scattering, demo
// constants) as tabulated by Hillaire 2020 (sebh/UnrealEngineSkyAtmosphere,
// SetupEarthAtmosphere). Coefficients are per metre at the altitude where the profile is 1.
struct AtmosphereParams {
    double bottom_radius = 6360.0e3;  //!< m, planet radius (ground)
    double top_radius = 6460.0e3;     //!< m, top of the atmosphere (100 km above the ground)

    //! 1/m at sea level, Rayleigh scattering (no absorption); 1.24062e-6 / lambda_um^4.
    glm::dvec3 rayleigh_scattering{5.802e-6, 13.558e-6, 33.1e-6};
    double rayleigh_scale_height = 8000.0;  //!< m, density exp(-h / H)

    glm::dvec3 mie_scattering{3.996e-6, 3.996e-6, 3.996e-6};  //!< 1/m at sea level
    glm::dvec3 mie_extinction{4.440e-6, 4.440e-6, 4.440e-6};  //!< 1/m at sea level (absorption 0.444e-6)
    double mie_scale_height = 1200.0;                          //!< m, density exp(-h / H)
    double mie_g = 0.8;                                        //!< asymmetry, -0.999..0.999
    MiePhase mie_phase = MiePhase::CornetteShanks;

    //! 1/m at the peak, ozone absorption (300 Dobson units' cross-sections, Bruneton 2017).
    glm::dvec3 ozone_absorption{0.650e-6, 1.881e-6, 0.085e-6};
    double ozone_center_altitude = 25.0e3;  //!< m, peak of the tent profile
    double ozone_half_width = 15.0e3;       //!< m, the tent is zero below 10 km and above 40 km

    glm::dvec3 ground_albedo{0.1, 0.1, 0.1};  //!< Lambertian ground, 0..1 (Bruneton's demo value)

    //! Solar irradiance at the top of the atmosphere, per RGB sample. 1 makes every radiance a
    //! transfer factor the renderer scales by its sun illuminance (Hillaire's choice); the
    //! physical spectrum at 680/550/440 nm is about (1.474, 1.850, 1.912) W m^-2 nm^-1.
    glm::dvec3 solar_irradiance{1.0, 1.0, 1.0};
    double sun_angular_radius = 0.004675;  //!< rad (0.268 deg, Bruneton 2017)
};

// Relative densities (1 at the profile's reference altitude) at altitude h metres above ground.
double rayleighDensity(const AtmosphereParams& p, double altitude_m);
double mieDensity(const AtmosphereParams& p, double altitude_m);
double ozoneDensity(const AtmosphereParams& p, double altitude_m);  // tent, 0..1

struct MediumSample {
    glm::dvec3 rayleigh_scattering{0.0};  //!< 1/m
    glm::dvec3 mie_scattering{0.0};       //!< 1/m
    glm::dvec3 extinction{0.0};           //!< 1/m: Rayleigh + Mie extinction + ozone absorption
    glm::dvec3 scattering() const { return rayleigh_scattering + mie_scattering; }
};
MediumSample sampleMedium(const AtmosphereParams& p, double altitude_m);

// Phase functions in 1/sr of cos_theta = dot(view direction, direction to the sun) (both
// pointing away from the viewer), each normalised to 1 over the sphere.
double rayleighPhase(double cos_theta);
double cornetteShanksPhase(double g, double cos_theta);
double henyeyGreensteinPhase(double g, double cos_theta);
double miePhase(const AtmosphereParams& p, double cos_theta);
inline constexpr double kIsotropicPhase = 0.07957747154594767;  // 1 / (4 pi)

// Ray geometry in the planet frame (centre at the origin): a ray starts at radius r with
// mu = cos(angle between the ray and the local up). The formulas avoid cancellation for
// r from the ground to geostationary orbit.
bool rayIntersectsGround(const AtmosphereParams& p, double r, double mu);
double distanceToGround(const AtmosphereParams& p, double r, double mu);  // valid if it intersects
double distanceToTop(const AtmosphereParams& p, double r, double mu);     // r <= top_radius
double horizonMu(const AtmosphereParams& p, double r);  // mu of the ray tangent to the ground, <= 0

// The part of a ray that lies in the atmosphere: from t_enter (0 inside it; the entry point
// from above it) to t_exit (top of the atmosphere or the ground).
struct AtmosphereSegment {
    bool hit = false;             //!< false: the ray misses the atmosphere (or is empty)
    double t_enter = 0.0;         //!< m along the ray
    double t_exit = 0.0;          //!< m along the ray
    bool ends_on_ground = false;  //!< the segment ends on the planet surface
};
// origin in the planet frame (metres), dir unit length. An origin below the ground is first
// lifted to it (clampToGround).
AtmosphereSegment atmosphereSegment(const AtmosphereParams& p, glm::dvec3 origin, glm::dvec3 dir);

// vista's world to the planet frame: y up, the ground under the world origin at y = 0, so the
// planet centre is at (0, -bottom_radius, 0). A point below the ground is moved radially onto it.
glm::dvec3 planetFromWorld(const AtmosphereParams& p, glm::dvec3 world_pos_m);
glm::dvec3 clampToGround(const AtmosphereParams& p, glm::dvec3 planet_pos_m);

// The sun seen from latitude latitude_deg (north positive) on day_of_year (1 = 1 January,
// fractional allowed) at apparent local solar time solar_time_h (12 = solar noon: the sun on
// the meridian). Declination and equation of time are Spencer's (1971) Fourier series, good to
// about 0.04 deg and 0.6 min; no refraction (which lifts the sun ~0.5 deg at the horizon), no
// parallax. Overall the direction is within ~0.1 deg of an ephemeris for any year near 2000.
struct SunPosition {
    double azimuth_deg = 0.0;    //!< 0..360, clockwise from north (-z): 90 = east (+x)
    double elevation_deg = 0.0;  //!< above the geometric horizon, -90..90
    glm::dvec3 direction{0.0, 1.0, 0.0};  //!< unit, towards the sun, vista world (y up, -z north)
};
// day: day number at local noon (1 = noon on 1 January); a fraction moves it in time.
double solarDeclinationRad(double day);
// Apparent minus mean solar time in minutes; clock time -> solar time:
// solar_time_h = clock_h + (4 min/deg * (longitude - zone meridian) + equationOfTime) / 60.
double equationOfTimeMinutes(double day);
SunPosition sunPosition(double latitude_deg, double day_of_year, double solar_time_h);

}  // namespace vista
