// [clouds], [clouds.low] and [clouds.high]: the keys, units, ranges and help text.
#include "sky/clouds/cloud_settings.h"

#include <array>

namespace vista {

namespace {

void describe(SettingsVisitor& v, CloudLayerSettings& s, const char* section, const char* help) {
    v.section(section, help);
    v.field({"enabled", "", "draw this layer"}, s.enabled);
    v.field({"base_m", "m", "altitude of the layer's bottom above sea level"}, s.base_m, 0.0f, 100000.0f);
    v.field({"thickness_m", "m", "layer thickness"}, s.thickness_m, 1.0f, 20000.0f);
    v.field({"coverage", "", "share of the sky covered (0: no clouds)"}, s.coverage, 0.0f, 1.0f);
    v.field({"density", "1/m", "extinction inside a cloud's core"}, s.density, 0.0f, 10.0f);
    v.field({"scale_m", "m", "size of the coarsest noise cell"}, s.scale_m, 10.0f, 1.0e6f);
    v.field({"octaves", "", "fBm octaves (frequency x2, amplitude x1/2 each)"}, s.octaves, 1, 8);
    v.field({"steps", "", "view-ray samples through the layer"}, s.steps, 1, 64);
    v.field({"wind_direction_deg", "deg", "heading the wind blows towards, clockwise from -z (north)"}, s.wind_direction_deg, -360.0f, 360.0f);
    v.field({"wind_speed", "m/s", "mean drift of the cloud pattern"}, s.wind_speed, 0.0f, 200.0f);
    v.field({"wind_gust", "", "random walk: the wind velocity varies by this share of wind_speed"}, s.wind_gust, 0.0f, 2.0f);
    v.field({"seed", "", "noise pattern"}, s.seed, 0, 65535);
}

}  // namespace

void describe(SettingsVisitor& v, CloudsSettings& s) {
    v.section("clouds", "noise cloud layers in spherical shells, lit by the sun through the atmosphere");
    v.field({"enabled", "", "draw the cloud layers (needs [sky])"}, s.enabled);
    v.field({"light_samples", "", "samples towards the sun per view sample (self-shadowing)"}, s.light_samples, 0, 16);
    v.field({"phase_g", "", "forward-scattering asymmetry (Henyey-Greenstein g)"}, s.phase_g, 0.0f, 0.95f);
    v.field({"ambient", "", "scale of the sky's ambient light on the clouds"}, s.ambient, 0.0f, 10.0f);
    v.field({"max_distance_km", "km", "clouds fade out towards this distance along the view"}, s.max_distance_km, 1.0f, 2000.0f);
    v.field({"half_resolution", "", "march at half size, upsampled over the image (clouds.composite)"}, s.half_resolution);
    v.field({"coverage_variation", "", "every layer's coverage swings by +- this over coverage_period_s"}, s.coverage_variation, 0.0f, 1.0f);
    v.field({"coverage_period_s", "s", "period of the coverage swing"}, s.coverage_period_s, 1.0f, 1.0e7f);
    v.field({"temporal", "", "accumulate the march over frames, reprojected along the clouds' depth (clouds.temporal)"}, s.temporal);
    v.field({"temporal_blend", "", "share of this frame's march once the history is full (1: no history)"}, s.temporal_blend, 0.01f, 1.0f);
    v.field({"temporal_parallax_decay", "1/px",
             "in motion the history's sample count falls by a factor e^(this * parallax) a frame, parallax being how far "
             "its cloud point moved on screen against the far sky: a history reprojected along an estimated distance lags "
             "by a share of it, and without the decay a sustained flight streaks the clouds (0: no decay)"},
            s.temporal_parallax_decay, 0.0f, 100.0f);
    v.field({"march_subset", "",
             "with temporal: march 1 pixel of every march_subset per frame, in a Bayer order (1: every pixel, 4: 1 of 2x2, "
             "16: 1 of 4x4; other values round down to these); clouds.temporal reprojects the rest; a frame without "
             "history marches every pixel; what comes into view is upsampled until each pixel's turn (counter "
             "clouds.marched_pixels)"},
            s.march_subset, 1, 16);
    v.field({"shadows", "", "cloud shadows on the terrain (clouds.shadow)"}, s.shadows);
    v.field({"shadow_size", "texels", "shadow map texels per side"}, s.shadow_size, 16, 2048);
    v.field({"shadow_extent_km", "km", "ground covered by the shadow map around the camera"}, s.shadow_extent_km, 0.1f, 1000.0f);
    describe(v, s.low, "clouds.low", "the lower cloud layer");
    describe(v, s.high, "clouds.high", "the upper cloud layer");
}

}  // namespace vista
