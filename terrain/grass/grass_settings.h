// [grass]: the grass blades (terrain/grass/grass.h).
// describe() is the one description of the keys; config/settings.h gathers them into Settings.
#pragma once

#include "config/visitor.h"

#include <glm/vec3.hpp>

namespace vista {

//! Grass (terrain/grass/grass.h): instanced curved blades placed per world cell around the camera,
//! culled on the GPU, bent by wind, written to the G-buffer after the terrain. Needs [terrain].
struct GrassSettings {
    bool enabled = true;
    float radius_m = 40.0f;           //!< m, blades reach this distance (they thin and shrink to 0 at it), 2..1000
    float density = 24.0f;            //!< blades per m^2 near the camera on full grass, 0.25..400
    float cell_m = 2.0f;              //!< m, side of a placement cell (blades per cell = density * cell^2), 0.25..16
    float blade_height_m = 0.45f;     //!< m, mean blade length, 0.01..5
    float height_variation = 0.4f;    //!< relative spread of blade length, 0..1
    float blade_width_m = 0.035f;     //!< m, blade width at the root, 0.001..0.5
    int segments = 4;                 //!< segments per near blade (far ones get half, at least 1), 1..8
    float lod_distance_m = 12.0f;     //!< m, blades beyond this use the coarser segment count, 0..1000
    float thin_start = 0.25f;         //!< fraction of radius_m where blades begin to thin out, 0..1
    float far_keep = 0.2f;            //!< share of blades kept just before radius_m (widened to keep coverage), 0.01..1
    float forward_shift = 0.35f;      //!< placement box centre ahead of the camera, fraction of radius_m, 0..0.5
    glm::vec3 color{0.065f, 0.11f, 0.022f};     //!< linear albedo at the tip of a typical blade, 0..1
    glm::vec3 dry_color{0.15f, 0.13f, 0.045f}; //!< linear albedo of dry blades, 0..1
    float dry_fraction = 0.25f;       //!< share of the dry colour mixed in at most, per blade random, 0..1
    float color_variation = 0.3f;     //!< per-blade brightness spread, 0..1
    float root_darkening = 0.6f;      //!< albedo at the root = (1 - this) x tip (self-shadowing), 0..1
    float roughness = 0.65f;          //!< perceptual roughness, 0.05..1
    float normal_blend = 0.7f;        //!< shading normal blended toward the terrain normal (1 = terrain), 0..1
    float curvature = 0.35f;          //!< rad, rest bend of the tip (random per blade up to this), 0..1.5
    float wind_strength = 0.25f;      //!< rad, mean bend of the tips along the wind, 0..1.5
    float wind_direction_deg = 60.0f; //!< deg, where the wind blows toward, clockwise from -z, -360..360
    float gust_strength = 0.35f;      //!< rad, extra bend at the peak of a gust, 0..1.5
    float gust_scale_m = 18.0f;       //!< m, size of the gust pattern, 0.5..10000
    float gust_speed_m_s = 6.0f;      //!< m/s, speed the gusts travel along the wind, 0..200
    float sway_strength = 0.08f;      //!< rad, per-blade oscillation amplitude, 0..1
    float sway_frequency_hz = 0.9f;   //!< Hz, per-blade oscillation (varied +-25% per blade), 0..20
    float far_color_strength = 0.85f; //!< terrain grass band blended toward the blades' colour beyond the fade, 0..1
    bool cast_shadows = true;         //!< blades cast into the sun cascades and the spot shadow atlas
};

// Lists the keys of GrassSettings to v, in file order.
void describe(SettingsVisitor& v, GrassSettings& s);

}  // namespace vista
