// The scene's settings: one plain struct per ini section, with defaults and units.
// Ranges live in the describe() functions (settings.cpp), the one description that the
// ini loader, the writer, `vista check` and the ImGui panel share.
#pragma once

#include "config/visitor.h"
#include "renderer/lighting/light_settings.h"  // LightsSettings: part of vista_config, no renderer code
#include "terrain/scatter/object_settings.h"  // ObjectsSettings: likewise

#include <glm/vec3.hpp>

#include <string>
#include <string_view>
#include <vector>

namespace vista {

struct WindowSettings {
    int width = 1280;       //!< px
    int height = 720;       //!< px
    bool fullscreen = false;
    bool vsync = true;
    bool gl_debug = false;  //!< KHR_debug callback printing GL errors and warnings
};

struct CameraSettings {
    glm::dvec3 position{0.0, 60.0, 0.0};  //!< m, world space (y up)
    float yaw_deg = 0.0f;                 //!< deg, 0 looks along -z, positive turns right
    float pitch_deg = -10.0f;             //!< deg, positive looks up
    float fov_deg = 60.0f;                //!< deg, vertical field of view
    float near_m = 0.1f;                  //!< m, near plane (the far plane is at infinity)
    float move_speed = 40.0f;             //!< m/s
    float fast_multiplier = 8.0f;         //!< speed factor while Shift is held
    float slow_multiplier = 0.125f;       //!< speed factor while Ctrl is held
    float mouse_sensitivity = 0.15f;      //!< deg per pixel of mouse motion
    float zoom_sensitivity = 2.0f;        //!< deg of field of view per scroll step
    float updown_speed = 1.0f;            //!< factor on move_speed for Q/E
    bool follow_terrain = false;          //!< walk: keep the eye at eye_height_m above the ground
    float eye_height_m = 1.7f;            //!< m above the ground when following the terrain
    bool allow_below_ground = false;      //!< free camera may go below the terrain surface
};

enum class ImageFormat : int { Png, Exr, Mp4 };  // Mp4: PNG frames, then an H.264 video of them

struct CaptureSettings {
    std::string path = "data/paths/default.path";  //!< camera path, relative to the vista root
    int frames = 8;                                //!< frames to render
    float fps = 2.0f;                              //!< frames per second of path time
    int width = 320;                               //!< px
    int height = 180;                              //!< px
    ImageFormat format = ImageFormat::Png;
    std::string out = "out";                       //!< output directory
    int settle_frames = 8;                         //!< unwritten frames before a run's first written frame, 0..10000
    int crf = 18;                                  //!< H.264 constant rate factor of mp4 output, 0 (lossless)..51
};

enum class DebugView : int { Final, Depth, Albedo, Normals, Lights, Cascades, ShadowMap, Shadow, SpotAtlas, PointShadows };

struct DebugSettings {
    DebugView view = DebugView::Final;
    bool grid = true;           //!< reference grid on the y = 0 plane
    float grid_spacing = 10.0f; //!< m between minor lines; major lines every 10
    float heat_max = 32.0f;     //!< lights per pixel shown red in the lights view, 1..65536
};

enum class TerrainView : int { Shaded, Lod, Morph, Normals, Error, Material };
enum class LodMetric : int { Error, Distance };
enum class DemNodata : int { Fill, Refuse };  // what a DEM's nodata cells get (terrain/dem.h)

//! Parallax occlusion mapping of the near terrain's materials ([terrain.pom], terrain/shaders/pom.glsl):
//! the view ray marched through the blended material height field (linear search, then binary
//! refinement), soft self-shadowing toward the sun, fading to plain normal mapping by distance.
//! Off: no program variant, nothing marched.
struct TerrainPomSettings {
    bool enabled = false;             //!< march the relief in the near material tier (a program variant)
    int max_steps = 32;               //!< linear search steps at a grazing view (a quarter of them looking straight down), 2..256
    int refine_steps = 5;             //!< binary refinement steps after the linear search, 0..16
    float depth_m = 0.05f;            //!< m, depth of material height 0 below height 1 (the drawn surface), 0.001..1
    float distance_m = 40.0f;         //!< m, the relief flattens from half this distance and is gone at it (at most detail_distance_m), 1..10000
    float shadow = 0.7f;              //!< strength of the relief's soft self-shadowing toward the sun (0: none), 0..1
    int shadow_steps = 8;             //!< steps of the self-shadowing march toward the sun, 1..64
};

//! Tessellated displacement of the near terrain ([terrain.tessellation], terrain/shaders/terrain_tess.glsl):
//! near quadrants drawn as patches, subdivided by each edge's size on screen and displaced by the
//! material relief, in the G-buffer and the shadow passes. Off: no program variant, no patches.
struct TerrainTessSettings {
    bool enabled = false;             //!< tessellate and displace the quadrants nearer than range_m
    float range_m = 40.0f;            //!< m, quadrants nearer than this are tessellated; displacement ends by 90% of it, 2..1000
    float edge_px = 6.0f;             //!< px, target length of a tessellated edge on screen, 1..64
    float max_factor = 16.0f;         //!< largest subdivision of an edge (llvmpipe's tessellator breaks beyond 32), 1..32
    float depth_m = 0.1f;             //!< m, depth of relief height 0 below the drawn surface, 0.001..1
};

//! Streaming from a tile cache ([terrain.stream], terrain/tile_stream.h, docs/dem.md): the map is
//! never held whole; a fixed GPU page pool is filled by worker threads from `vista terrain-cache`'s file.
struct TerrainStreamSettings {
    bool enabled = false;             //!< draw from the tile cache (built first when missing or stale)
    std::string cache;                //!< tile cache file (empty: the heightmap's or DEM's path + .vtc)
    int pool_pages = 2048;            //!< tiles the GPU pool holds (heights + normals), 16..65536
    int uploads_per_frame = 64;       //!< finished tile loads uploaded per frame at most, 1..4096
    int threads = 2;                  //!< worker threads reading tiles, 1..16
    int prefetch_frames = 30;         //!< frames: tiles the camera will need this many frames ahead (at its last frame's motion) are requested too, 0..600
};

//! A user material ([terrain.material.NAME], terrain/user_materials.h): image files read with
//! OpenImageIO, all of one square power-of-two size. NAME sand, grass, rock, snow or dirt replaces
//! that generated layer; any other NAME adds a layer that only a splat map places.
struct TerrainMaterialSettings {
    std::string name;                 //!< NAME (letters, digits, _)
    std::string section;              //!< "terrain.material.NAME" (visitors take section names as C strings)
    std::string albedo;               //!< sRGB colour image, RGB or RGBA (alpha ignored); required
    std::string normal;               //!< tangent-space normal map, RGB (0.5 + 0.5 n, green toward the bottom row: DirectX style); empty: flat
    std::string height;               //!< relief height, one channel (0 lowest .. 1 highest); empty: flat
    std::string roughness;            //!< one channel, 0..1; empty: roughness_value everywhere
    float roughness_value = 0.85f;    //!< roughness where no roughness image is given, 0..1
    float tiling_m = 4.0f;            //!< m covered by one repeat of the images, 0.05..1000
    bool operator==(const TerrainMaterialSettings&) const = default;
};

struct TerrainSettings {
    bool enabled = true;
    std::string heightmap = "data/heightmaps/island.png";  //!< PNG/TIFF/EXR, or .r16 with raw_width/raw_height
    int raw_width = 0;                //!< samples, .r16 only
    int raw_height = 0;               //!< samples, .r16 only
    std::string dem;                  //!< elevation model read by GDAL (GeoTIFF, .hgt, ASCII grid, VRT, ...); replaces heightmap, and size and heights come from its data
    DemNodata dem_nodata = DemNodata::Fill;  //!< nodata cells of a DEM: filled from their neighbours, or refused
    float dem_vertical_scale = 1.0f;  //!< x, multiplies a DEM's heights (exaggeration), 0.01..100
    glm::dvec3 origin{0.0};           //!< m, world position of the map centre (y: added to heights)
    float size_m = 8192.0f;           //!< m, extent of the map in x and z
    float height_scale_m = 600.0f;    //!< m, height of heightmap value 1
    float height_offset_m = 0.0f;     //!< m, height of heightmap value 0
    int grid = 32;                    //!< quads per node side (a leaf node spans this many texels)
    LodMetric lod_metric = LodMetric::Error;  //!< per-node screen error (terrain/lod_error.h) or distance only
    float max_error_px = 1.0f;        //!< px, largest vertical screen error the LOD may leave
    float bias_slope = 2.0f;          //!< m/m, slope limit of the error metric's distance bias (lowered while it would raise the ranges)
    float base_range_m = 150.0f;      //!< m, LOD 0 range (raised to what node size and error need)
    float range_ratio = 2.0f;         //!< range growth per LOD level
    float morph_start = 0.7f;         //!< fraction of each level's span before morphing starts
    TerrainView view = TerrainView::Shaded;
    bool wireframe = false;           //!< overlay node grid edges
    bool bounds = false;              //!< draw the selected nodes' bounding boxes
    float detail_distance_m = 250.0f; //!< m, detail textures fade out by this distance (near material tier)
    float far_material_m = 3000.0f;   //!< m, textures give way to each layer's mean albedo by here (far tier; 0: never)
    bool material_tiers = true;       //!< one draw per material tier (off: the near tier's program everywhere, same image, slower)
    float texture_scale_m = 4.0f;     //!< m covered by one repeat of a material texture
    float sand_top = 0.135f;          //!< heightmap value where beaches end
    float grass_top = 0.45f;          //!< heightmap value where grass gives way to rock
    float snow_start = 0.70f;         //!< heightmap value where snow begins
    float band_blend = 0.03f;         //!< heightmap units over which bands blend
    float band_jitter = 0.02f;        //!< heightmap units of noise on band edges
    float rock_slope = 0.75f;         //!< normal.y below which slopes turn to rock
    int material_anisotropy = 1;      //!< anisotropic filtering of the material textures (1: trilinear only), 1..16
    std::string splat_map;            //!< one or two RGBA images of layer weights over the heightmap (its size); empty: height/slope rules
    std::string splat_layers;         //!< layer names, one per splat channel (empty: the user materials in file order)
    TerrainPomSettings pom;           //!< [terrain.pom]
    TerrainTessSettings tessellation; //!< [terrain.tessellation]
    TerrainStreamSettings stream;     //!< [terrain.stream]
    std::vector<TerrainMaterialSettings> materials;  //!< [terrain.material.NAME] sections, in file order
};


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

//! One cloud layer ([clouds.low], [clouds.high]): a spherical shell around the planet filled
//! with fBm value noise (sky/clouds/clouds.h). Coverage 0 or enabled = false drops the layer.
struct CloudLayerSettings {
    bool enabled = true;
    float base_m = 1500.0f;          //!< m, altitude of the shell's bottom above sea level (y = 0), 0..100000
    float thickness_m = 1200.0f;     //!< m, shell thickness, 1..20000
    float coverage = 0.45f;          //!< share of the sky covered (threshold on the noise), 0..1
    float density = 0.02f;           //!< 1/m, extinction inside a cloud's core, 0..10
    float scale_m = 2500.0f;         //!< m, size of the coarsest noise cell, 10..1e6
    int octaves = 4;                 //!< fBm octaves (frequency x2, amplitude x1/2 each), 1..8
    int steps = 8;                   //!< view-ray samples through the shell, 1..64
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
    int light_samples = 3;           //!< samples towards the sun per view sample (self-shadowing), 0..16
    float phase_g = 0.6f;            //!< forward-scattering asymmetry of the HG phase, 0..0.95
    float ambient = 1.0f;            //!< scale of the sky's ambient light on the clouds, 0..10
    float max_distance_km = 160.0f;  //!< km, clouds fade out towards this distance along the view, 1..2000
    bool half_resolution = true;     //!< march at half size ("clouds.half"), upsampled by "clouds.composite"
    float coverage_variation = 0.1f; //!< coverage of every layer swings by +-this over coverage_period_s, 0..1
    float coverage_period_s = 1800.0f; //!< s, period of the coverage swing, 1..1e7
    bool temporal = true;            //!< accumulate the march over frames ("clouds.temporal", docs/temporal.md)
    float temporal_blend = 0.0625f;  //!< share of this frame's march once history is full, 0.01..1 (1: no history)
    bool shadows = true;             //!< cloud shadows on the terrain ("clouds.shadow"): sun light through the layers
    int shadow_size = 256;           //!< texels per side of the shadow map, 16..2048
    float shadow_extent_km = 16.0f;  //!< km covered by the shadow map around the camera, 0.1..1000
    CloudLayerSettings low;          //!< [clouds.low]
    CloudLayerSettings high{true, 7500.0f, 400.0f, 0.35f, 0.002f, 9000.0f, 3, 2, 80.0f, 25.0f, 0.3f, 7};  //!< [clouds.high]
};

enum class WeatherKind : int { Rain, Snow };

//! Rain or snow around the camera (sky/weather/weather.h): drops placed per world cell of a box that
//! moves with the camera, falling with the wind, drawn as camera-facing streaks oriented by their
//! velocity relative to the camera ("weather.rain"), splashes on the ground ("weather.splash")
//! and wet, darker and glossier terrain. Off: no pass, no object, dry terrain.
struct WeatherSettings {
    bool enabled = false;              //!< off: no pass, no buffer, the terrain stays dry
    WeatherKind kind = WeatherKind::Rain;  //!< rain: streaks, splashes, wet ground; snow: slow swaying flakes only
    float intensity = 0.5f;            //!< 0..1: share of max_density drawn, streak opacity, splash rate, wetness
    float max_density = 3.0f;          //!< drops per m^3 at intensity 1 (visible streaks, not every real drop), 0.01..50
    float radius_m = 16.0f;            //!< m, drops are drawn up to this distance (fading over its last 25%), 2..100
    float cell_m = 2.0f;               //!< m, side of a placement cell (drops per cell = max_density * cell^3, at most 256), 0.5..8
    float near_fade_m = 0.3f;          //!< m, drops closer than this are left out; they fade in over the next near_fade_m, 0..10
    float drop_speed_m_s = 8.0f;       //!< m/s, fall speed (rain 4..9, snow 0.5..1.5), 0.1..50
    float drop_width_m = 0.003f;       //!< m, streak width (rain) or flake diameter (snow), 0.0005..0.1
    float streak_time_s = 0.02f;       //!< s, a streak spans the drop's motion relative to the camera over this time (its length), 0..0.5
    float brightness = 1.0f;           //!< scale of the light a drop sends back (sun and sky irradiance at the camera), 0..20
    bool wind_from_clouds = true;      //!< on: the wind of [clouds.low] times wind_scale; off: wind_speed_m_s toward wind_direction_deg
    float wind_scale = 0.4f;           //!< share of the low cloud layer's wind felt near the ground, 0..2
    float wind_speed_m_s = 3.0f;       //!< m/s, horizontal wind when wind_from_clouds is off, 0..100
    float wind_direction_deg = 60.0f;  //!< deg, heading the wind blows toward, clockwise from -z, -360..360
    bool splashes = true;              //!< rain: short-lived splashes on the terrain ("weather.splash")
    float splash_rate = 40.0f;         //!< splashes per m^2 per s at intensity 1, 0..1000
    float splash_radius_m = 10.0f;     //!< m, splashes drawn up to this distance, 1..50
    float splash_size_m = 0.06f;       //!< m, largest radius of a splash's crown, 0.005..1
    float splash_life_s = 0.12f;       //!< s, a splash grows and fades over this time, 0.01..2
    float wetness = 0.8f;              //!< rain: how wet the terrain gets at intensity >= 0.5 (darker, lower roughness), 0..1
};

//! The post-processing effects that [postfx] order can list; each has a [postfx.NAME] section.
enum class PostEffect : int { Bloom, Exposure, Tonemap, Fxaa, Grade, Dof, MotionBlur, LensFlare, NightVision, Scotopic };

struct PostfxSettings {
    bool enabled = true;  //!< off: the HDR image is only clamped and sRGB-encoded
    //! Effects in the order they run on the image. Effects before `tonemap` see linear HDR,
    //! effects after it the display (sRGB) image. Without `tonemap` (or with it disabled) the
    //! chain still ends with a clamp and the sRGB encoding.
    std::vector<PostEffect> order{PostEffect::MotionBlur, PostEffect::Dof,      PostEffect::Bloom,
                                  PostEffect::LensFlare,  PostEffect::Scotopic, PostEffect::Exposure, PostEffect::Tonemap,
                                  PostEffect::Grade,      PostEffect::NightVision, PostEffect::Fxaa};
};

enum class ExposureMode : int { Manual, Auto, Camera };

//! Exposure: a scale 2^ev (manual), or one that brings the metered average luminance to middle
//! grey (0.18) times 2^ev (auto), metered from a log-luminance histogram and adapted over time,
//! or a physical camera's (camera): EV100 = log2(N^2 / t * 100 / S) from the lens's f-number N
//! ([postfx.dof] f_stop), the shutter time t ([postfx.motion_blur] shutter_deg / 360 / frame_rate)
//! and the sensitivity S (iso), whether or not depth of field and motion blur are on; a luminance
//! of 1.2 * 2^EV100 cd/m^2 (the sensor's saturation, ISO 12232) maps to 1, times 2^ev.
struct ExposureSettings {
    bool enabled = true;
    ExposureMode mode = ExposureMode::Auto;
    float ev = 0.0f;              //!< stops of compensation (manual: scale = 2^ev), -20..20
    float min_ev = -32.0f;        //!< auto: lowest metered log2 luminance (darker scenes stay darker; -32: a moonless night), -40..20
    float max_ev = 16.0f;         //!< auto: highest metered log2 luminance, -40..20
    //! auto: stops darker than middle grey once the adapted luminance is scotopic (below
    //! 0.005 cd/m^2; none above 5 cd/m^2, log-smooth between): night reads as night, 0..10
    float night_ev = 2.5f;
    float low_percent = 40.0f;    //!< auto: darkest pixels left out of the average, % of the histogram, 0..99
    float high_percent = 95.0f;   //!< auto: pixels above this percentile left out (highlights), 1..100
    float speed_up = 3.0f;        //!< auto: adaptation rate towards a brighter scene, stops settle by e per 1/rate s, 0.01..100
    float speed_down = 1.0f;      //!< auto: adaptation rate towards a darker scene, 1/s, 0.01..100
    float iso = 100.0f;           //!< camera: sensitivity S (ISO arithmetic), 1..1e6
};

enum class Tonemapper : int { Reinhard, Aces, Clamp, Agx };

struct TonemapSettings {
    bool enabled = true;
    Tonemapper op = Tonemapper::Aces;
    float white = 4.0f;  //!< linear value that maps to white (Reinhard)
};

//! Bloom after Jimenez 2014: a 13-tap downsample chain (Karis average on the first level),
//! tent-filtered upsampling back up, blended into the image.
struct BloomSettings {
    bool enabled = true;
    float intensity = 0.04f;  //!< share of the blurred image in the result (mix), 0..1
    float radius = 0.7f;      //!< weight of each coarser level while upsampling: 0 tight, 1 wide, 0..1
    int levels = 5;           //!< downsample levels (each half the size), 1..10
    float clamp = 1000.0f;    //!< highlights are clamped to this before blurring (NaN/Inf to 0), 1..65504
};

//! FXAA 3.11-style anti-aliasing on the display image (luma edges).
struct FxaaSettings {
    bool enabled = false;  //!< off by default: TAA ([postfx.taa]) anti-aliases; the low preset uses FXAA instead
    float edge_threshold = 0.125f;     //!< smallest local contrast treated as an edge, 0.01..1
    float edge_threshold_min = 0.0312f;//!< contrast below this (dark areas) is never an edge, 0..1
    float subpixel = 0.75f;            //!< sub-pixel aliasing removal (0 off, 1 soft), 0..1
};

//! Temporal anti-aliasing (postfx/taa.h, docs/temporal.md): a Halton sub-pixel jitter of the
//! projection and a resolve of the linear HDR image against its reprojected history, run on the
//! scene's HDR image before the post chain (so before tone mapping and in HDR captures).
//! cut_distance_m / cut_angle_deg also decide when the clouds' history is dropped.
struct TaaSettings {
    bool enabled = true;
    float blend = 0.1f;            //!< share of the current frame in the result, 0.02..1 (1: history off)
    float clip_gamma = 1.25f;      //!< neighbourhood box half-size in standard deviations, 0.5..4
    float sharpen = 0.25f;         //!< unsharp mask of the history against its bilinear fetch, 0..1
    float disocclusion = 0.05f;    //!< relative depth difference that rejects history, 0.001..1
    float cut_distance_m = 100.0f; //!< m, a camera jump beyond this between frames is a cut (history dropped)
    float cut_angle_deg = 30.0f;   //!< deg, a camera turn beyond this between frames is a cut
};

//! Colour grading on the display image: lift/gamma/gain per channel, saturation, vignette.
struct GradeSettings {
    bool enabled = false;
    glm::vec3 lift{0.0f};          //!< raises the blacks: c + lift * (1 - c), -1..1
    glm::vec3 gamma{1.0f};         //!< mid-tones: c^(1/gamma) (above 1 brightens), 0.1..10
    glm::vec3 gain{1.0f};          //!< scales the whites, 0..10
    float saturation = 1.0f;       //!< 0 grey, 1 unchanged, 0..4
    float vignette = 0.0f;         //!< darkening at the corners (0 none, 1 black), 0..1
    float vignette_start = 0.5f;   //!< share of the centre-to-corner distance where the darkening begins, 0..1
    float grain = 0.0f;            //!< film grain amplitude at mid-grey (fades to 0 at black and white), 0..1
    float grain_rate = 24.0f;      //!< 1/s, new grain pattern this many times per second of scene time, 0..1000
    std::string lut;               //!< optional 3D LUT (.cube), relative to the vista root; applied after saturation
};

//! Scotopic vision (postfx/scotopic.h): below mesopic luminance the rods take over from the
//! cones: colour fades to the rods' luminance with a blue shift (Krawczyk et al. 2005) and
//! detail blurs (acuity). Per pixel, by its luminance in cd/m^2: none from 5 cd/m^2 up, all
//! at 0.005 and below (CIE mesopic range). Runs on linear HDR (before exposure) and only on
//! frames whose sky gives less than 400 lx (sky/night_light.h kPreExposureLux).
struct ScotopicSettings {
    bool enabled = true;
    float blue_shift = 1.0f;       //!< share of the rods' blue tint (0: grey), 0..1
    float acuity_arcmin = 10.0f;   //!< arcmin, detail lost at full scotopic vision (blur radius), 0..60
    bool show_rod_share = false;   //!< debug: the rods' share per pixel as grey, instead of the image
};

//! Night vision (as 000's): luminance amplified, noise, a green phosphor tint and a round
//! scope vignette; on the display image (place it after tonemap).
struct NightVisionSettings {
    bool enabled = false;
    float gain = 6.0f;        //!< luminance amplification, 1..1000
    float noise = 0.15f;      //!< noise amplitude, 0..1
    float noise_rate = 30.0f; //!< 1/s, new noise pattern this many times per second of scene time, 0..1000
    float vignette = 1.0f;    //!< darkening outside the scope circle (1 black), 0..1
    glm::vec3 tint{0.25f, 1.0f, 0.3f};  //!< phosphor colour, 0..1
};

//! Screen-space ambient occlusion (horizon based, HBAO style) from depth and G-buffer normals,
//! computed before the lighting, which multiplies its ambient term by it. Not part of the
//! post chain's order: it runs wherever there is a G-buffer.
struct SsaoSettings {
    bool enabled = true;
    float radius_m = 2.0f;         //!< m, world-space reach of the horizon search, 0.01..100
    float intensity = 1.0f;        //!< strength: ao = 1 - intensity * occlusion, 0..4
    float bias = 0.1f;             //!< sine of the horizon angle ignored (against self-occlusion of flat ground), 0..0.9
    int directions = 4;            //!< horizon directions per pixel (rotated per pixel), 1..16
    int steps = 4;                 //!< depth samples along each direction, 1..32
    bool half_resolution = true;   //!< compute at half size; the blur upsamples depth-aware
    bool blur = true;              //!< 3x3 bilateral (depth-aware) blur; off: nearest upsample only
    float blur_depth_tolerance = 0.05f;  //!< relative depth difference at which blur weights fall by e, 0.001..1
};

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

//! Depth of field: a thin-lens circle of confusion from the focus distance, focal length and
//! f-stop (postfx/dof.h has the formula), autofocus on the screen centre smoothed over time, and
//! a gather blur with a separate near field so that the foreground bleeds over what is in focus.
struct DofSettings {
    bool enabled = false;
    float focus_distance_m = 50.0f;  //!< m, focus distance when autofocus is off, 0.1..1e6
    float focal_length_mm = 50.0f;   //!< mm, lens focal length, 1..2000
    float f_stop = 2.8f;             //!< f-number N (aperture diameter = focal length / N), 0.5..64
    float sensor_height_mm = 24.0f;  //!< mm, sensor height (maps the CoC to pixels of the image height), 1..100
    bool autofocus = true;           //!< focus on the screen centre (median of 5 depth samples)
    float autofocus_rate = 4.0f;     //!< 1/s, the focus (in diopters) closes the gap by e in 1/rate s, 0.01..100
    float max_coc_px = 16.0f;        //!< px, largest blur radius, 1..64
    int samples = 32;                //!< gather taps per pixel (Vogel disk), 4..256
    bool debug = false;              //!< the CoC replaces the final image: red far, green near, blue in focus
};

//! Camera motion blur after McGuire et al. 2012: per-pixel velocity from depth reprojected with
//! the previous frame's camera, tile max and neighbour max velocity, and a gather with depth
//! comparisons. The blur covers the motion during the exposure shutter_deg / 360 / frame_rate
//! seconds, whatever the rate frames are rendered at.
struct MotionBlurSettings {
    bool enabled = false;
    float shutter_deg = 180.0f;   //!< deg, shutter angle: exposure = shutter / 360 of a frame at frame_rate, 0..360
    float frame_rate = 30.0f;     //!< 1/s, the film rate the shutter angle refers to, 1..1000
    float max_blur_px = 20.0f;    //!< px, longest blur (half each side; also the tile size), 2..64
    int samples = 12;             //!< gather taps per pixel, 2..64
    float depth_extent = 0.02f;   //!< relative depth difference over which foreground/background blend, 0.001..1
};

//! Lens flare from the sun (after Chapman 2013's parts, drawn from the sun's screen position):
//! ghosts along the sun-to-centre axis, a halo, chromatic aberration and a starburst, scaled by
//! the sun's visibility (the share of depth samples around it that see the sky, smoothed).
struct LensFlareSettings {
    bool enabled = false;
    float intensity = 0.002f;        //!< flare radiance per unit sun illuminance, 0..1
    int ghosts = 5;                  //!< ghost discs along the axis, 0..16
    float ghost_spacing = 0.45f;     //!< spacing of the ghosts along the sun-to-centre axis (1 = sun to centre), 0.01..2
    float halo_radius = 0.45f;       //!< halo ring radius, share of the image height, 0..2
    float chromatic = 0.03f;         //!< red/blue separation along the axis, 0..0.5
    float starburst = 1.0f;          //!< strength of the rays around the sun, 0..10
    float visibility_radius_deg = 0.5f;  //!< deg, radius of the depth samples around the sun, 0.01..10
    float visibility_rate = 8.0f;    //!< 1/s, visibility follows its target by e in 1/rate s, 0.01..100
};

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

struct Settings {
    WindowSettings window;
    CameraSettings camera;
    CaptureSettings capture;
    DebugSettings debug;
    TerrainSettings terrain;
    GrassSettings grass;        // [grass]
    SkySettings sky;
    CloudsSettings clouds;      // [clouds], [clouds.low], [clouds.high]
    ShadowSettings shadows;
    WeatherSettings weather;    // [weather]
    LightsSettings lights;      // [lights], with the light.NAME / volume.NAME lists
    WaterSettings water;        // [water]
    ObjectsSettings objects;    // [objects], with the object.NAME / scatter.NAME lists
    PostfxSettings postfx;
    ExposureSettings exposure;  // [postfx.exposure]
    TonemapSettings tonemap;    // [postfx.tonemap]
    BloomSettings bloom;        // [postfx.bloom]
    FxaaSettings fxaa;          // [postfx.fxaa]
    TaaSettings taa;            // [postfx.taa]
    GradeSettings grade;        // [postfx.grade]
    SsaoSettings ssao;          // [postfx.ssao]
    DofSettings dof;            // [postfx.dof]
    MotionBlurSettings motion_blur;  // [postfx.motion_blur]
    LensFlareSettings lens_flare;    // [postfx.lens_flare]
    NightVisionSettings night_vision;  // [postfx.night_vision]
    ScotopicSettings scotopic;         // [postfx.scotopic]
};

// Lists every section and field of s to v, in file order.
void describe(SettingsVisitor& v, Settings& s);

// Adds the named section `section` (a family of sections with a NAME: terrain.material.NAME) to s
// when it is one and not there yet. True when s now has it (the ini loader and --set then set its
// keys); false for a name no family takes.
bool addNamedSection(Settings& s, std::string_view section);

}  // namespace vista
