// [shadows]: sun cascades, the spot atlas and the point cubes (renderer/shadows/).
// describe() is the one description of the keys; config/settings.h gathers them into Settings.
#pragma once

#include "config/visitor.h"

namespace vista {

enum class ShadowFilter : int { Hard, Pcf, Pcss };

//! Sun shadows: cascaded shadow maps (renderer/shadows/cascades.h) with PSSM splits, each cascade fitted
//! to its view slice's bounding sphere and snapped to whole texels (stable while flying), plus
//! an optional far cascade for distant mountains; filtered by rotated-Poisson PCF or PCSS.
struct ShadowSettings {
    bool enabled = true;
    int cascades = 4;                    //!< PSSM cascades up to max_distance_m, 1..4
    int resolution = 1024;               //!< texels per cascade side, 128..4096
    float max_distance_m = 500.0f;       //!< m, view depth where the PSSM cascades end, 1..100000
    float split_lambda = 0.9f;           //!< PSSM: 0 uniform, 1 logarithmic split distances, 0..1
    bool far_cascade = true;             //!< one more cascade from max_distance_m to far_distance_m
    float far_distance_m = 5000.0f;      //!< m, where the far cascade (and all sun shadows) end, 1..1000000
    float blend_band = 0.1f;             //!< share of a cascade's depth range over which it cross-fades into the next (and the last fades out), 0..0.5
    ShadowFilter filter = ShadowFilter::Pcf;  //!< hard: one bilinear compare; pcf: rotated Poisson disk; pcss: contact hardening
    int pcf_taps = 12;                   //!< Vogel-disk taps (pcf, pcss; also the PCSS blocker search), 1..64
    float filter_radius_texels = 1.5f;   //!< PCF kernel radius in texels of cascade 0 (others keep its world size, up to 1 texel minimum), 0..16
    float sun_size_scale = 1.0f;         //!< PCSS: penumbra width per metre of occluder distance relative to the drawn sun's diameter, 0..100
    float max_penumbra_texels = 12.0f;   //!< PCSS: largest kernel radius, texels, 1..64
    float slope_bias = 1.5f;             //!< glPolygonOffset factor while drawing casters (slope-scaled), 0..16
    float depth_bias_texels = 1.0f;      //!< constant depth bias in texel sizes of the cascade, 0..16
    float normal_offset_texels = 1.5f;   //!< receiver moved along its normal by this many texels (scaled by the sine of the sun angle), 0..16
    float min_sun_elevation_deg = 0.0f;  //!< deg, below this the sun casts no shadows (no passes), -10..90
    bool stabilize = true;               //!< sphere fit snapped to whole texels; off: tight unsnapped boxes (they shimmer)
    bool freeze = false;                 //!< keep the cascades where they are (fly around to inspect them)
    float caster_step_texels = 1.0f;     //!< terrain casters finer than this many cascade texels are drawn with every 2nd, 4th, ... grid vertex down to it (0: full detail), 0..16
    bool caster_cull = true;             //!< leave out terrain quadrants whose shadows cannot reach a cascade's receivers (off: every quadrant in its box, same image, slower)
    int cache_cascades = 1;              //!< how many of the farthest cascades may keep their map from an earlier frame (1: the far cascade when on), 0..5
    int cache_frames = 8;                //!< a kept cascade is redrawn when its snapped box moves (the view moved a texel or turned), the sun moves, or on every this many frames of a sequence (1: every frame), 1..1000
    // Shadowed spot lights (renderer/shadows/spot_shadows.h): the visible spot lights with `shadow on`
    // (their default), largest on screen first, each get a square tile of one depth atlas.
    bool spot_enabled = true;            //!< spot lights cast shadows from the atlas
    int spot_atlas_resolution = 2048;    //!< texels per atlas side, 256..8192
    int spot_max_lights = 16;            //!< shadowed spot lights at once (atlas tiles), 1..64; the rest go unshadowed (counted)
    ShadowFilter spot_filter = ShadowFilter::Pcss;  //!< hard | pcf | pcss (000: blocker search, penumbra (d_r - d_b) w / d_b)
    int spot_taps = 16;                  //!< Vogel-disk taps (pcf, pcss; also the blocker search), 1..64
    float spot_filter_radius_texels = 1.5f;   //!< PCF kernel radius (and PCSS's smallest), texels, 0..16
    float spot_light_size_m = 0.1f;      //!< PCSS: radius of the light's bulb, m, 0..10
    float spot_max_penumbra_texels = 10.0f;   //!< PCSS: largest kernel radius and blocker search radius, texels, 1..64
    float spot_slope_bias = 2.0f;        //!< glPolygonOffset factor while drawing casters, 0..16
    float spot_depth_bias_texels = 1.0f; //!< receiver moved towards the light by this many texel footprints, 0..16
    float spot_normal_offset_texels = 1.5f;   //!< receiver moved along its normal (times the sine of the light angle), texels, 0..16
    float spot_min_screen_px = 4.0f;     //!< px, lights whose bounding sphere is smaller on screen cast no shadow, 0..10000
    // Shadowed point lights (renderer/shadows/point_shadows.h): the visible point lights with `shadow on`,
    // largest on screen first (the spots' ranking), each get a depth cube of one cube-map array.
    // Filtered with the spot knobs above (spot_filter, spot_taps, spot_filter_radius_texels,
    // spot_light_size_m, spot_max_penumbra_texels). Off unless a scene asks: a cube is six views.
    bool point_enabled = false;          //!< point lights cast shadows from depth cubes
    int point_resolution = 256;          //!< texels per cube face side, 32..2048
    int point_max_lights = 4;            //!< shadowed point lights at once (cubes), 1..16; the rest go unshadowed (counted)
    float point_slope_bias = 2.0f;       //!< glPolygonOffset factor while drawing casters, 0..16
    float point_depth_bias_texels = 1.0f;     //!< receiver moved towards the light by this many texel footprints, 0..16
    float point_normal_offset_texels = 1.5f;  //!< receiver moved along its normal (times the sine of the light angle), texels, 0..16
    float point_min_screen_px = 16.0f;   //!< px, lights whose bounding sphere is smaller on screen cast no shadow, 0..10000
};

// Lists the keys of ShadowSettings to v, in file order.
void describe(SettingsVisitor& v, ShadowSettings& s);

}  // namespace vista
