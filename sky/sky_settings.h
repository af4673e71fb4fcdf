// [sky]: the sun, the atmosphere, the aerial perspective, height fog and the night sky (sky/atmosphere.h).
// describe() is the one description of the keys; config/settings.h gathers them into Settings.
#pragma once

#include "config/visitor.h"

#include <glm/vec3.hpp>

namespace vista {

//! How the sun's direction is given: explicit angles, or latitude, day of year and solar time.
enum class SunMode : int { Angles, Time };
enum class SkyMiePhase : int { CornetteShanks, HenyeyGreenstein };

//! The physically based atmosphere (Hillaire 2020, sky/atmosphere.h). Earth defaults after
//! Bruneton 2017; coefficients in 1/Mm (1e-6 per metre) at the altitude where the profile is 1.
struct SkySettings {
    bool enabled = true;
    SunMode sun_mode = SunMode::Angles;  //!< angles: sun_azimuth/elevation_deg; time: the three below
    float sun_azimuth_deg = 135.0f;  //!< deg, clockwise from -z (north), -360..360
    float sun_elevation_deg = 35.0f; //!< deg above the horizon, -90..90
    float time_of_day_h = 10.0f;     //!< h, apparent local solar time (12 = sun on the meridian), 0..24
    float latitude_deg = 45.0f;      //!< deg, north positive, -90..90
    float day_of_year = 172.0f;      //!< day, 1 = 1 January (fractional allowed), 1..366
    //! h of time of day per s of scene time (sun_mode = time; 0: still, 1: a day in 24 s), -1000..1000
    float time_scale = 0.0f;
    float sun_illuminance = 3.0f;    //!< HDR units: solar irradiance at the top of the atmosphere, 0..1000
    float sun_angular_radius_deg = 0.2679f;  //!< deg, drawn sun disk (0.27 = real), 0.05..5
    float sun_limb_darkening = 0.6f; //!< u of I = 1 - u (1 - cos), 0..1
    float planet_radius_km = 6360.0f;       //!< km, ground, 100..100000
    float atmosphere_height_km = 100.0f;    //!< km, top above the ground, 1..1000
    glm::vec3 rayleigh_scattering{5.802f, 13.558f, 33.1f};  //!< 1/Mm at sea level, RGB 680/550/440 nm, 0..1000
    float rayleigh_scale_height_km = 8.0f;  //!< km, 0.1..100
    float mie_scattering = 3.996f;          //!< 1/Mm at sea level, 0..1000
    float mie_absorption = 0.444f;          //!< 1/Mm at sea level, 0..1000
    float mie_scale_height_km = 1.2f;       //!< km, 0.01..100
    float mie_g = 0.8f;                     //!< phase asymmetry, -0.99..0.99
    SkyMiePhase mie_phase = SkyMiePhase::CornetteShanks;
    glm::vec3 ozone_absorption{0.650f, 1.881f, 0.085f};  //!< 1/Mm at the peak, 0..1000
    float ozone_center_km = 25.0f;          //!< km, peak of the tent profile, 0..1000
    float ozone_half_width_km = 15.0f;      //!< km, 0 disables ozone, 0..1000
    glm::vec3 ground_albedo{0.1f, 0.1f, 0.1f};  //!< Lambertian, for multiple scattering, 0..1
    //! "sky.atmosphere" draws the sunlit ground (ground_albedo) where a view ray below the horizon
    //! meets the planet and nothing is drawn (terrain, water); off: in-scattering alone (vista sky)
    bool planet_ground = true;
    // Quality knobs (vista bench sky measures them; defaults sit on the knee of error vs cost).
    int transmittance_width = 256;   //!< texels along mu, 16..1024
    int transmittance_height = 64;   //!< texels along altitude, 8..512
    int transmittance_steps = 40;    //!< integration steps per texel, 4..512
    int multiscatter_size = 32;      //!< texels per side, 8..128
    int multiscatter_steps = 20;     //!< steps along each of its 64 rays, 4..256
    int sky_view_width = 192;        //!< texels in azimuth, 16..1024
    int sky_view_height = 108;       //!< texels in elevation (sqrt horizon mapping), 16..1024
    int sky_view_steps = 32;         //!< steps along each view ray, 4..256 (also for views from space)
    float rebuild_sun_deg = 0.05f;   //!< deg, grid of sun elevations the sky-view LUT is built for (0: exact), 0..10
    // Aerial perspective: haze over everything at finite depth, from a froxel volume of the
    // in-scattering and transmittance between the camera and each depth slice (Hillaire 2020).
    bool aerial_perspective = true;  //!< haze and extinction on geometry ("sky.aerial"); off adds no pass
    float aerial_distance_km = 64.0f; //!< km, depth the volume reaches (slices quadratic in depth; beyond, the last), 1..1000
    int aerial_size = 32;            //!< froxels per screen side, 8..256
    int aerial_slices = 32;          //!< depth slices, 4..256
    int aerial_steps = 2;            //!< integration steps per slice, 1..16
    // Optional height fog: an extra grey scattering medium, density fog_density_per_km *
    // exp(-(altitude - fog_base_m) / fog_falloff_m), lit like the aerosols, in the aerial
    // perspective and the sky view (so fogged terrain meets a fogged horizon).
    bool height_fog = false;         //!< add the fog medium
    float fog_density_per_km = 1.0f; //!< 1/km extinction at fog_base_m (3.9 / value = visibility in km), 0..1000
    float fog_base_m = 0.0f;         //!< m, altitude where the density is fog_density_per_km, -10000..100000
    float fog_falloff_m = 200.0f;    //!< m, height over which the density falls by e, 1..100000
    // Night sky, drawn by "sky.atmosphere" behind the atmosphere (dimmed by its transmittance).
    bool moon = true;                //!< a Lommel-Seeliger sphere lit by the sun: its phase follows
    float moon_azimuth_deg = 300.0f; //!< deg, clockwise from -z (sun_mode = angles), -360..360
    float moon_elevation_deg = 30.0f; //!< deg above the horizon (sun_mode = angles), -90..90
    float moon_age_days = 10.0f;     //!< days since new moon (sun_mode = time; 14.77 = full), 0..29.53
    bool stars = true;               //!< a fixed random star field turning with the sky (sun_mode = time)
    float stars_intensity = 1e-3f;   //!< radiance at the centre of the brightest star, per unit sun_illuminance;
                                     //!< each star fades out as the sky behind it reaches 1% to 10% of its own, 0..1
    glm::vec3 zenith_color{0.18f, 0.36f, 0.80f};  //!< unused by the physical sky; old scenes load
    glm::vec3 horizon_color{0.70f, 0.80f, 0.95f}; //!< unused by the physical sky; old scenes load
};

// Lists the keys of SkySettings to v, in file order.
void describe(SettingsVisitor& v, SkySettings& s);

}  // namespace vista
