// [clouds], [clouds.low] and [clouds.high]: the noise cloud layers (sky/clouds/clouds.h).
// describe() is the one description of the keys; config/settings.h gathers them into Settings.
#pragma once

#include "config/visitor.h"

namespace vista {

//! One cloud layer ([clouds.low], [clouds.high]): a spherical shell around the planet filled
//! with fBm value noise (sky/clouds/clouds.h). Coverage 0 or enabled = false drops the layer.
struct CloudLayerSettings {
    bool enabled = true;
    float base_m = 1500.0f;          //!< m, altitude of the shell's bottom above sea level (y = 0), 0..100000
    float thickness_m = 1200.0f;     //!< m, shell thickness, 1..20000
    float coverage = 0.45f;          //!< share of the sky covered (threshold on the noise), 0..1
    float density = 0.02f;           //!< 1/m, extinction inside a cloud's core, 0..10
    float scale_m = 2500.0f;         //!< m, size of the coarsest noise cell, 10..1e6
    int octaves = 8;                 //!< fBm octaves (frequency x2, amplitude x1/2 each), 1..8
    int steps = 32;                  //!< view-ray samples through the shell, 1..64
    float wind_direction_deg = 60.0f;  //!< deg, heading the wind blows towards, clockwise from -z (north), -360..360
    float wind_speed = 8.0f;         //!< m/s, mean drift of the pattern, 0..200
    float wind_gust = 0.5f;          //!< random walk of the wind: velocity varies by this share of wind_speed, 0..2
    int seed = 1;                    //!< noise pattern, 0..65535
};

//! Noise cloud layers over the atmosphere (sky/clouds/clouds.h): "clouds.shadow" (a sun
//! transmittance map for the terrain) and "clouds.shell" (the layers over the sky). They need
//! [sky] enabled: the clouds are lit through its transmittance LUT.
struct CloudsSettings {
    bool enabled = true;             //!< off (or every layer off or at coverage 0): no pass, no texture
    int light_samples = 8;           //!< samples towards the sun per view sample (self-shadowing), 0..16
    float phase_g = 0.6f;            //!< forward-scattering asymmetry of the HG phase, 0..0.95
    float ambient = 1.0f;            //!< scale of the sky's ambient light on the clouds, 0..10
    float max_distance_km = 160.0f;  //!< km, clouds fade out towards this distance along the view, 1..2000
    bool half_resolution = false;    //!< march at half size ("clouds.half"), upsampled by "clouds.composite"
    float coverage_variation = 0.1f; //!< coverage of every layer swings by +-this over coverage_period_s, 0..1
    float coverage_period_s = 1800.0f; //!< s, period of the coverage swing, 1..1e7
    bool temporal = true;            //!< accumulate the march over frames ("clouds.temporal", docs/temporal.md)
    float temporal_blend = 0.0625f;  //!< share of this frame's march once history is full, 0.01..1 (1: no history)
    float temporal_parallax_decay = 3.0f; //!< 1/px, in motion the history's sample count falls by e^(this * parallax px) a frame, 0..100
    int march_subset = 16;           //!< with temporal: 1 pixel of every march_subset marched per frame: 1 (all), 4 (2x2) or 16 (4x4), 1..16
    bool shadows = true;             //!< cloud shadows on the terrain ("clouds.shadow"): sun light through the layers
    int shadow_size = 256;           //!< texels per side of the shadow map, 16..2048
    float shadow_extent_km = 16.0f;  //!< km covered by the shadow map around the camera, 0.1..1000
    CloudLayerSettings low;          //!< [clouds.low]
    CloudLayerSettings high{true, 7500.0f, 400.0f, 0.35f, 0.002f, 9000.0f, 8, 16, 80.0f, 25.0f, 0.3f, 7};  //!< [clouds.high]
};

// Lists the keys of CloudsSettings to v, in file order.
void describe(SettingsVisitor& v, CloudsSettings& s);

}  // namespace vista
