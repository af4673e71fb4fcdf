// [water]: the sea (terrain/water/water.h).
// describe() is the one description of the keys; config/settings.h gathers them into Settings.
#pragma once

#include "config/visitor.h"

#include <glm/vec3.hpp>

namespace vista {

enum class WaterReflection : int { Ssr, Sky };
enum class WaterView : int { Shaded, Normals, Foam, Depth };

//! The sea (terrain/water/water.h): a sum of Gerstner waves from a Pierson-Moskowitz spectrum of the
//! wind, displaced in the vertex shader over camera-centred rings and shaded in a forward pass
//! after the deferred lighting (reflection, refraction with absorption, foam, sun glitter, local
//! lights), fogged by the aerial perspective; an underwater tint when the camera is below it.
struct WaterSettings {
    bool enabled = false;
    float level_m = 0.0f;                 //!< m, world height of the still surface, -1e5..1e5
    float wind_speed_m_s = 6.0f;          //!< m/s, 10 m above the sea: peak wavelength and wave height, 0.5..40
    float wind_direction_deg = 60.0f;     //!< deg, where the wind (and the waves) go, clockwise from -z, -360..360
    float direction_spread_deg = 35.0f;   //!< deg, waves' directions spread this much either side of the wind, 0..90
    float amplitude_scale = 1.0f;         //!< factor on the spectrum's amplitudes, 0..4
    float choppiness = 1.0f;              //!< horizontal over vertical orbit (1: Gerstner's circles; capped so crests never fold), 0..2
    int waves = 24;                       //!< Gerstner waves, wavelengths geometric from 4x the peak down to min_wavelength_m, 1..32
    float min_wavelength_m = 0.25f;       //!< m, shortest wave (surface detail near the camera), 0.02..100
    float grid_cell_m = 0.5f;             //!< m, grid cell at the camera (grows with 1% of the height above the water), 0.05..100
    int grid_segments = 128;              //!< segments around each ring of the camera-centred grid, 16..1024
    float max_distance_m = 1.0e6f;        //!< m, the grid's outer radius, 100..1e7
    bool sector_cull = true;              //!< draw only the grid's segments the view can see (off: the whole circle, same image, slower)
    glm::vec3 scatter_color{0.012f, 0.05f, 0.06f};     //!< single-scattering albedo of the water body (its deep colour), 0..1
    glm::vec3 absorption_per_m{0.45f, 0.075f, 0.05f}; //!< 1/m, extinction of light in the water (Beer-Lambert), 0..100
    float roughness = 0.08f;              //!< perceptual roughness below the smallest wave (sun glitter width), 0.01..1
    float refraction_strength = 0.25f;    //!< m of sideways shift of the refracted image per unit normal tilt and metre of water (about 1 - 1/1.33), 0..1
    WaterReflection reflection = WaterReflection::Ssr;  //!< ssr: screen-space ray march with the sky as fallback; sky: the sky alone
    int ssr_steps = 24;                   //!< ray-march steps of the screen-space reflection, 4..128
    float ssr_max_distance_m = 3000.0f;   //!< m, longest reflected ray, 1..1e6
    float foam_depth_m = 1.2f;            //!< m, shore foam where the water column is shallower than this (0: none), 0..50
    glm::vec3 foam_color{0.75f, 0.75f, 0.75f};  //!< linear albedo of foam, 0..1
    float whitecaps = 0.25f;              //!< foam on crests squeezed by the waves (Jacobian below 0.5), 0..1
    WaterView view = WaterView::Shaded;   //!< shaded, or the surface's normal, foam or water depth (debug)
};

// Lists the keys of WaterSettings to v, in file order.
void describe(SettingsVisitor& v, WaterSettings& s);

}  // namespace vista
