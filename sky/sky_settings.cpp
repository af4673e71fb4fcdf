// [sky]: the keys, units, ranges and help text.
#include "sky/sky_settings.h"

#include <array>

namespace vista {

void describe(SettingsVisitor& v, SkySettings& s) {
    static constexpr std::array<const char*, 2> sun_modes{"angles", "time"};
    static constexpr std::array<const char*, 2> mie_phases{"cornette_shanks", "henyey_greenstein"};
    v.section("sky", "physically based atmosphere and the sun");
    v.field({"enabled", "", "draw the sky"}, s.enabled);
    v.choice({"sun_mode", "", "angles: azimuth/elevation keys; time: latitude, day and solar time"}, s.sun_mode, sun_modes);
    v.field({"sun_azimuth_deg", "deg", "sun heading, clockwise from -z (sun_mode = angles)"}, s.sun_azimuth_deg, -360.0f, 360.0f);
    v.field({"sun_elevation_deg", "deg", "sun angle above the horizon (sun_mode = angles)"}, s.sun_elevation_deg, -90.0f, 90.0f);
    v.field({"time_of_day_h", "h", "apparent solar time, 12 = noon (sun_mode = time)"}, s.time_of_day_h, 0.0f, 24.0f);
    v.field({"latitude_deg", "deg", "latitude, north positive (sun_mode = time)"}, s.latitude_deg, -90.0f, 90.0f);
    v.field({"day_of_year", "day", "1 = 1 January (sun_mode = time)"}, s.day_of_year, 1.0f, 366.0f);
    v.field({"time_scale", "h/s", "day/night cycle: hours of time of day per second of scene time (sun_mode = time; 0 still)"},
            s.time_scale, -1000.0f, 1000.0f);
    v.field({"sun_illuminance", "", "HDR scale of the solar irradiance at the top of the atmosphere"}, s.sun_illuminance, 0.0f, 1000.0f);
    v.field({"sun_angular_radius_deg", "deg", "radius of the drawn sun disk"}, s.sun_angular_radius_deg, 0.05f, 5.0f);
    v.field({"sun_limb_darkening", "", "limb darkening u: I = 1 - u (1 - cos)"}, s.sun_limb_darkening, 0.0f, 1.0f);
    v.field({"planet_radius_km", "km", "ground radius"}, s.planet_radius_km, 100.0f, 100000.0f);
    v.field({"atmosphere_height_km", "km", "top of the atmosphere above the ground"}, s.atmosphere_height_km, 1.0f, 1000.0f);
    v.field({"rayleigh_scattering", "1/Mm", "Rayleigh scattering at sea level, RGB"}, s.rayleigh_scattering, 0.0f, 1000.0f);
    v.field({"rayleigh_scale_height_km", "km", "Rayleigh density exp(-h/H)"}, s.rayleigh_scale_height_km, 0.1f, 100.0f);
    v.field({"mie_scattering", "1/Mm", "aerosol scattering at sea level"}, s.mie_scattering, 0.0f, 1000.0f);
    v.field({"mie_absorption", "1/Mm", "aerosol absorption at sea level"}, s.mie_absorption, 0.0f, 1000.0f);
    v.field({"mie_scale_height_km", "km", "aerosol density exp(-h/H)"}, s.mie_scale_height_km, 0.01f, 100.0f);
    v.field({"mie_g", "", "aerosol phase asymmetry"}, s.mie_g, -0.99f, 0.99f);
    v.choice({"mie_phase", "", "aerosol phase function"}, s.mie_phase, mie_phases);
    v.field({"ozone_absorption", "1/Mm", "ozone absorption at its peak, RGB"}, s.ozone_absorption, 0.0f, 1000.0f);
    v.field({"ozone_center_km", "km", "altitude of the ozone peak"}, s.ozone_center_km, 0.0f, 1000.0f);
    v.field({"ozone_half_width_km", "km", "half width of the ozone tent (0: no ozone)"}, s.ozone_half_width_km, 0.0f, 1000.0f);
    v.field({"ground_albedo", "", "ground reflectance seen by multiple scattering"}, s.ground_albedo, 0.0f, 1.0f);
    v.field({"planet_ground", "", "draw the sunlit planet ground where a view ray meets it behind everything drawn "
                                  "(off: the sky's in-scattering alone, as vista sky without --ground)"},
            s.planet_ground);
    v.field({"transmittance_width", "texels", "transmittance LUT size along mu"}, s.transmittance_width, 16, 1024);
    v.field({"transmittance_height", "texels", "transmittance LUT size along altitude"}, s.transmittance_height, 8, 512);
    v.field({"transmittance_steps", "", "integration steps per transmittance texel"}, s.transmittance_steps, 4, 512);
    v.field({"multiscatter_size", "texels", "multiple-scattering LUT size per side"}, s.multiscatter_size, 8, 128);
    v.field({"multiscatter_steps", "", "steps along each multiple-scattering ray"}, s.multiscatter_steps, 4, 256);
    v.field({"sky_view_width", "texels", "sky-view LUT size in azimuth"}, s.sky_view_width, 16, 1024);
    v.field({"sky_view_height", "texels", "sky-view LUT size in elevation"}, s.sky_view_height, 16, 1024);
    v.field({"sky_view_steps", "", "steps along each sky-view (or from-space) ray"}, s.sky_view_steps, 4, 256);
    v.field({"rebuild_sun_deg", "deg", "grid of sun elevations the sky-view LUT is built for (0: every change)"}, s.rebuild_sun_deg, 0.0f, 10.0f);
    v.field({"aerial_perspective", "", "haze and extinction on geometry (froxel volume)"}, s.aerial_perspective);
    v.field({"aerial_distance_km", "km", "depth the aerial-perspective volume reaches"}, s.aerial_distance_km, 1.0f, 1000.0f);
    v.field({"aerial_size", "froxels", "aerial-perspective volume size per screen side"}, s.aerial_size, 8, 256);
    v.field({"aerial_slices", "", "aerial-perspective depth slices (quadratic in depth)"}, s.aerial_slices, 4, 256);
    v.field({"aerial_steps", "", "integration steps per aerial-perspective slice"}, s.aerial_steps, 1, 16);
    v.field({"height_fog", "", "add an exponential height fog to the aerial perspective and sky"}, s.height_fog);
    v.field({"fog_density_per_km", "1/km", "fog extinction at fog_base_m (visibility = 3.9 / value)"}, s.fog_density_per_km, 0.0f, 1000.0f);
    v.field({"fog_base_m", "m", "altitude where the fog has fog_density_per_km"}, s.fog_base_m, -10000.0f, 100000.0f);
    v.field({"fog_falloff_m", "m", "height over which the fog density falls by e"}, s.fog_falloff_m, 1.0f, 100000.0f);
    v.field({"moon", "", "draw the moon, lit by the sun (its phase follows)"}, s.moon);
    v.field({"moon_azimuth_deg", "deg", "moon heading, clockwise from -z (sun_mode = angles)"}, s.moon_azimuth_deg, -360.0f, 360.0f);
    v.field({"moon_elevation_deg", "deg", "moon angle above the horizon (sun_mode = angles)"}, s.moon_elevation_deg, -90.0f, 90.0f);
    v.field({"moon_age_days", "day", "days since new moon, 14.77 = full (sun_mode = time)"}, s.moon_age_days, 0.0f, 29.53f);
    v.field({"stars", "", "draw the star field at night"}, s.stars);
    v.field({"stars_intensity", "", "radiance of the brightest star per unit sun_illuminance (each fades as the sky brightens)"}, s.stars_intensity, 0.0f, 1.0f);
    v.field({"zenith_color", "", "unused by the physical sky (old scenes load)"}, s.zenith_color, 0.0f, 100.0f);
    v.field({"horizon_color", "", "unused by the physical sky (old scenes load)"}, s.horizon_color, 0.0f, 100.0f);
}

}  // namespace vista
