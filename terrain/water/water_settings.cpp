// [water]: the keys, units, ranges and help text.
#include "terrain/water/water_settings.h"

#include <array>

namespace vista {

void describe(SettingsVisitor& v, WaterSettings& s) {
    static constexpr std::array<const char*, 2> reflections{"ssr", "sky"};
    static constexpr std::array<const char*, 4> views{"shaded", "normals", "foam", "depth"};
    v.section("water", "the sea: Gerstner waves from the wind, reflection, refraction, foam (a forward pass)");
    v.field({"enabled", "", "draw the sea (off: no pass, no buffers)"}, s.enabled);
    v.field({"level_m", "m", "world height of the still water surface"}, s.level_m, -1.0e5f, 1.0e5f);
    v.field({"wind_speed_m_s", "m/s", "wind speed: the spectrum's peak wavelength and the wave height"}, s.wind_speed_m_s, 0.5f, 40.0f);
    v.field({"wind_direction_deg", "deg", "direction the wind and the waves go, clockwise from -z"}, s.wind_direction_deg, -360.0f, 360.0f);
    v.field({"direction_spread_deg", "deg", "the waves' directions spread this much either side of the wind"}, s.direction_spread_deg, 0.0f, 90.0f);
    v.field({"amplitude_scale", "x", "factor on the spectrum's wave amplitudes"}, s.amplitude_scale, 0.0f, 4.0f);
    v.field({"choppiness", "", "horizontal over vertical orbit size (1: circles); capped so that crests never fold"}, s.choppiness, 0.0f, 2.0f);
    v.field({"waves", "", "Gerstner waves, wavelengths geometric from 4x the peak down to min_wavelength_m"}, s.waves, 1, 32);
    v.field({"min_wavelength_m", "m", "shortest wave (surface detail near the camera)"}, s.min_wavelength_m, 0.02f, 100.0f);
    v.field({"grid_cell_m", "m", "grid cell at the camera (at least 1% of the height above the water)"}, s.grid_cell_m, 0.05f, 100.0f);
    v.field({"grid_segments", "", "segments around each ring of the camera-centred grid"}, s.grid_segments, 16, 1024);
    v.field({"max_distance_m", "m", "outer radius of the grid"}, s.max_distance_m, 100.0f, 1.0e7f);
    v.field({"sector_cull", "", "draw only the grid's segments that displaced waves can bring into view (off: the whole "
             "circle, same image, slower)"}, s.sector_cull);
    v.field({"scatter_color", "", "single-scattering albedo of the water body (its deep colour)"}, s.scatter_color, 0.0f, 1.0f);
    v.field({"absorption_per_m", "1/m", "extinction of light in the water per metre (Beer-Lambert)"}, s.absorption_per_m, 0.0f, 100.0f);
    v.field({"roughness", "", "perceptual roughness below the smallest wave (width of the sun glitter)"}, s.roughness, 0.01f, 1.0f);
    v.field({"refraction_strength", "", "sideways shift (m) of the refracted image per unit normal tilt and metre of water (about 1 - 1/1.33)"}, s.refraction_strength, 0.0f, 1.0f);
    v.choice({"reflection", "", "ssr: screen-space ray march, the sky where it leaves the screen; sky: the sky alone"}, s.reflection, reflections);
    v.field({"ssr_steps", "", "ray-march steps of the screen-space reflection"}, s.ssr_steps, 4, 128);
    v.field({"ssr_max_distance_m", "m", "longest reflected ray"}, s.ssr_max_distance_m, 1.0f, 1.0e6f);
    v.field({"foam_depth_m", "m", "shore foam where the water is shallower than this (0: none)"}, s.foam_depth_m, 0.0f, 50.0f);
    v.field({"foam_color", "", "linear albedo of foam"}, s.foam_color, 0.0f, 1.0f);
    v.field({"whitecaps", "", "foam on crests the waves squeeze (Jacobian below 0.5)"}, s.whitecaps, 0.0f, 1.0f);
    v.choice({"view", "", "shaded, or the surface's normal, foam or water depth (0..10 m) for debugging"}, s.view, views);
}

}  // namespace vista
