// [grass]: the keys, units, ranges and help text.
#include "terrain/grass/grass_settings.h"

namespace vista {

void describe(SettingsVisitor& v, GrassSettings& s) {
    v.section("grass", "instanced wind-animated grass blades around the camera (needs [terrain])");
    v.field({"enabled", "", "draw grass (off: no pass, no buffers)"}, s.enabled);
    v.field({"radius_m", "m", "blades reach this distance; they thin out and shrink to nothing at it"}, s.radius_m, 2.0f, 1000.0f);
    v.field({"density", "1/m^2", "blades per square metre near the camera on full grass"}, s.density, 0.25f, 400.0f);
    v.field({"cell_m", "m", "side of a placement cell; each cell's blades come from a hash of its coordinates"}, s.cell_m, 0.25f, 16.0f);
    v.field({"blade_height_m", "m", "mean blade length"}, s.blade_height_m, 0.01f, 5.0f);
    v.field({"height_variation", "", "relative spread of blade length"}, s.height_variation, 0.0f, 1.0f);
    v.field({"blade_width_m", "m", "blade width at the root"}, s.blade_width_m, 0.001f, 0.5f);
    v.field({"segments", "", "segments per near blade; far blades get half (at least 1)"}, s.segments, 1, 8);
    v.field({"lod_distance_m", "m", "blades beyond this use the coarser segment count"}, s.lod_distance_m, 0.0f, 1000.0f);
    v.field({"thin_start", "", "fraction of radius_m where blades begin to thin out"}, s.thin_start, 0.0f, 1.0f);
    v.field({"far_keep", "", "share of blades kept just before radius_m (they widen to keep coverage)"}, s.far_keep, 0.01f, 1.0f);
    v.field({"forward_shift", "", "placement box centre ahead of the camera along the view, fraction of radius_m"}, s.forward_shift, 0.0f, 0.5f);
    v.field({"color", "", "linear albedo at the tip of a typical blade"}, s.color, 0.0f, 1.0f);
    v.field({"dry_color", "", "linear albedo of dry blades"}, s.dry_color, 0.0f, 1.0f);
    v.field({"dry_fraction", "", "largest share of the dry colour in a blade (random per blade)"}, s.dry_fraction, 0.0f, 1.0f);
    v.field({"color_variation", "", "per-blade brightness spread"}, s.color_variation, 0.0f, 1.0f);
    v.field({"root_darkening", "", "albedo at the root is (1 - this) times the tip's"}, s.root_darkening, 0.0f, 1.0f);
    v.field({"roughness", "", "perceptual roughness of the blades"}, s.roughness, 0.05f, 1.0f);
    v.field({"normal_blend", "", "shading normal blended toward the terrain normal (1 = terrain normal)"}, s.normal_blend, 0.0f, 1.0f);
    v.field({"curvature", "rad", "largest rest bend of a blade's tip (random per blade)"}, s.curvature, 0.0f, 1.5f);
    v.field({"wind_strength", "rad", "mean bend of the tips along the wind"}, s.wind_strength, 0.0f, 1.5f);
    v.field({"wind_direction_deg", "deg", "direction the wind blows toward, clockwise from -z"}, s.wind_direction_deg, -360.0f, 360.0f);
    v.field({"gust_strength", "rad", "extra bend at the peak of a gust"}, s.gust_strength, 0.0f, 1.5f);
    v.field({"gust_scale_m", "m", "size of the travelling gust pattern"}, s.gust_scale_m, 0.5f, 10000.0f);
    v.field({"gust_speed_m_s", "m/s", "speed the gusts travel along the wind"}, s.gust_speed_m_s, 0.0f, 200.0f);
    v.field({"sway_strength", "rad", "per-blade oscillation amplitude"}, s.sway_strength, 0.0f, 1.0f);
    v.field({"sway_frequency_hz", "Hz", "per-blade oscillation frequency (varied +-25% per blade)"}, s.sway_frequency_hz, 0.0f, 20.0f);
    v.field({"far_color_strength", "", "beyond the blades the terrain's grass band takes the blades' colour by this much"}, s.far_color_strength, 0.0f, 1.0f);
    v.field({"cast_shadows", "", "blades cast sun and spot light shadows (drawn into the shadow maps)"}, s.cast_shadows);
}

}  // namespace vista
