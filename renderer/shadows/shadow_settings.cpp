// [shadows]: the keys, units, ranges and help text.
#include "renderer/shadows/shadow_settings.h"

#include <array>

namespace vista {

void describe(SettingsVisitor& v, ShadowSettings& s) {
    static constexpr std::array<const char*, 3> filters{"hard", "pcf", "pcss"};
    v.section("shadows", "sun shadows (cascaded shadow maps, stable while flying) and shadowed spot lights");
    v.field({"enabled", "", "the sun casts shadows"}, s.enabled);
    v.field({"cascades", "", "PSSM cascades up to max_distance_m"}, s.cascades, 1, 4);
    v.field({"resolution", "texels", "shadow map size per cascade side"}, s.resolution, 128, 4096);
    v.field({"max_distance_m", "m", "view depth where the PSSM cascades end"}, s.max_distance_m, 1.0f, 100000.0f);
    v.field({"split_lambda", "", "PSSM split blend: 0 uniform, 1 logarithmic"}, s.split_lambda, 0.0f, 1.0f);
    v.field({"far_cascade", "", "one more cascade from max_distance_m to far_distance_m (distant mountains)"}, s.far_cascade);
    v.field({"far_distance_m", "m", "where the far cascade ends"}, s.far_distance_m, 1.0f, 1000000.0f);
    v.field({"blend_band", "", "share of a cascade's depth range that cross-fades into the next"}, s.blend_band, 0.0f, 0.5f);
    v.choice({"filter", "", "hard (one bilinear compare), pcf (rotated Poisson disk), pcss (contact hardening)"}, s.filter, filters);
    v.field({"pcf_taps", "", "Poisson taps per pixel (pcf, pcss)"}, s.pcf_taps, 1, 64);
    v.field({"filter_radius_texels", "texels", "PCF kernel radius in texels of the first cascade"}, s.filter_radius_texels, 0.0f, 16.0f);
    v.field({"sun_size_scale", "", "PCSS penumbra relative to the drawn sun's angular size"}, s.sun_size_scale, 0.0f, 100.0f);
    v.field({"max_penumbra_texels", "texels", "PCSS: largest kernel radius"}, s.max_penumbra_texels, 1.0f, 64.0f);
    v.field({"slope_bias", "", "slope-scaled depth bias while drawing casters (glPolygonOffset factor)"}, s.slope_bias, 0.0f, 16.0f);
    v.field({"depth_bias_texels", "texels", "constant depth bias in texel sizes"}, s.depth_bias_texels, 0.0f, 16.0f);
    v.field({"normal_offset_texels", "texels", "receiver offset along its normal (times the sine of the sun angle)"}, s.normal_offset_texels, 0.0f, 16.0f);
    v.field({"min_sun_elevation_deg", "deg", "below this sun elevation there are no sun shadows (and no shadow passes)"}, s.min_sun_elevation_deg, -10.0f, 90.0f);
    v.field({"stabilize", "", "sphere-fitted cascades snapped to whole texels (off: tight boxes that shimmer)"}, s.stabilize);
    v.field({"freeze", "", "keep the cascades where they are while the camera moves"}, s.freeze);
    v.field({"caster_step_texels", "texels",
             "terrain quadrants whose grid is finer than this many texels of a sun cascade are drawn into it with every 2nd, "
             "4th, ... vertex, down to one common step (the vertices kept lie on the surface, so no cracks; counter "
             "shadows.caster_triangles; 0: full detail)"}, s.caster_step_texels, 0.0f, 16.0f);
    v.field({"caster_cull", "", "leave out terrain quadrants whose shadows cannot reach the view depths a cascade "
             "shades (off: every quadrant in the cascade's box, same image, slower)"}, s.caster_cull);
    v.field({"cache_cascades", "", "how many of the farthest cascades may keep their map from an earlier frame (1: the far "
             "cascade when far_cascade is on; 0: every cascade is drawn every frame)"}, s.cache_cascades, 0, 5);
    v.field({"cache_frames", "frames", "a kept cascade is drawn again when its snapped box moves (the view moved a texel or "
             "turned), when the sun moves, and on every this many frames of a sequence (keep it at most [capture] "
             "settle_frames, so capture shards stay identical; 1: every frame)"}, s.cache_frames, 1, 1000);
    v.field({"spot_enabled", "", "spot lights (with `shadow on`, their default) cast shadows from an atlas, largest on screen first"}, s.spot_enabled);
    v.field({"spot_atlas_resolution", "texels", "spot shadow atlas size per side"}, s.spot_atlas_resolution, 256, 8192);
    v.field({"spot_max_lights", "", "shadowed spot lights at once (atlas tiles); the rest go unshadowed and are counted"}, s.spot_max_lights, 1, 64);
    v.choice({"spot_filter", "", "spot shadows: hard, pcf or pcss (soft, contact hardening)"}, s.spot_filter, filters);
    v.field({"spot_taps", "", "spot shadows: Poisson taps per pixel (pcf, pcss)"}, s.spot_taps, 1, 64);
    v.field({"spot_filter_radius_texels", "texels", "spot shadows: PCF kernel radius (PCSS's smallest)"}, s.spot_filter_radius_texels, 0.0f, 16.0f);
    v.field({"spot_light_size_m", "m", "spot shadows, PCSS: radius of the light's bulb"}, s.spot_light_size_m, 0.0f, 10.0f);
    v.field({"spot_max_penumbra_texels", "texels", "spot shadows, PCSS: largest kernel and blocker search radius"}, s.spot_max_penumbra_texels, 1.0f, 64.0f);
    v.field({"spot_slope_bias", "", "spot shadows: slope-scaled depth bias while drawing casters"}, s.spot_slope_bias, 0.0f, 16.0f);
    v.field({"spot_depth_bias_texels", "texels", "spot shadows: receiver moved towards the light, in texel footprints"}, s.spot_depth_bias_texels, 0.0f, 16.0f);
    v.field({"spot_normal_offset_texels", "texels", "spot shadows: receiver offset along its normal"}, s.spot_normal_offset_texels, 0.0f, 16.0f);
    v.field({"spot_min_screen_px", "px", "spot lights whose bounding sphere is smaller on screen cast no shadow"}, s.spot_min_screen_px, 0.0f, 10000.0f);
    v.field({"point_enabled", "", "point lights (with `shadow on`) cast shadows from depth cubes, largest on screen first; filtered with the spot_* filter knobs"}, s.point_enabled);
    v.field({"point_resolution", "texels", "point shadows: texels per cube face side"}, s.point_resolution, 32, 2048);
    v.field({"point_max_lights", "", "shadowed point lights at once (cubes); the rest go unshadowed and are counted"}, s.point_max_lights, 1, 16);
    v.field({"point_slope_bias", "", "point shadows: slope-scaled depth bias while drawing casters"}, s.point_slope_bias, 0.0f, 16.0f);
    v.field({"point_depth_bias_texels", "texels", "point shadows: receiver moved towards the light, in texel footprints"}, s.point_depth_bias_texels, 0.0f, 16.0f);
    v.field({"point_normal_offset_texels", "texels", "point shadows: receiver offset along its normal"}, s.point_normal_offset_texels, 0.0f, 16.0f);
    v.field({"point_min_screen_px", "px", "point lights whose bounding sphere is smaller on screen cast no shadow"}, s.point_min_screen_px, 0.0f, 10000.0f);
}

}  // namespace vista
