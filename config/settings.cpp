// The one description of every setting: keys, units, ranges and help text.
#include "config/settings.h"

#include <algorithm>
#include <array>

namespace vista {
namespace {

void describe(SettingsVisitor& v, WindowSettings& s) {
    v.section("window", "window and GL context");
    v.field({"width", "px", "window width"}, s.width, 1, 16384);
    v.field({"height", "px", "window height"}, s.height, 1, 16384);
    v.field({"fullscreen", "", "fullscreen on the primary monitor"}, s.fullscreen);
    v.field({"vsync", "", "wait for vertical sync"}, s.vsync);
    v.field({"gl_debug", "", "print GL errors and warnings through KHR_debug"}, s.gl_debug);
}

void describe(SettingsVisitor& v, CameraSettings& s) {
    v.section("camera", "start pose and free-fly controls");
    v.field({"position", "m", "start position x y z (y up)"}, s.position, -1e8, 1e8);
    v.field({"yaw_deg", "deg", "start heading, 0 looks along -z, positive turns right"}, s.yaw_deg, -360.0f, 360.0f);
    v.field({"pitch_deg", "deg", "start pitch, positive looks up"}, s.pitch_deg, -89.0f, 89.0f);
    v.field({"fov_deg", "deg", "vertical field of view"}, s.fov_deg, 5.0f, 120.0f);
    v.field({"near_m", "m", "near plane (the far plane is at infinity)"}, s.near_m, 0.001f, 100.0f);
    v.field({"move_speed", "m/s", "WASD speed"}, s.move_speed, 0.01f, 100000.0f);
    v.field({"fast_multiplier", "x", "speed factor with Shift"}, s.fast_multiplier, 1.0f, 1000.0f);
    v.field({"slow_multiplier", "x", "speed factor with Ctrl"}, s.slow_multiplier, 0.001f, 1.0f);
    v.field({"mouse_sensitivity", "deg/px", "mouse look"}, s.mouse_sensitivity, 0.001f, 10.0f);
    v.field({"zoom_sensitivity", "deg", "field of view change per scroll step"}, s.zoom_sensitivity, 0.0f, 30.0f);
    v.field({"updown_speed", "x", "factor on move_speed for Q/E"}, s.updown_speed, 0.0f, 100.0f);
    v.field({"follow_terrain", "", "walk: keep the eye at eye_height_m above the ground"}, s.follow_terrain);
    v.field({"eye_height_m", "m", "eye height above the ground when following the terrain"}, s.eye_height_m, 0.01f, 1000.0f);
    v.field({"allow_below_ground", "", "the free camera may go below the terrain surface"}, s.allow_below_ground);
}

void describe(SettingsVisitor& v, CaptureSettings& s) {
    static constexpr std::array<const char*, 3> formats{"png", "exr", "mp4"};
    v.section("capture", "headless rendering of a camera path");
    v.field({"path", "", "camera path file"}, s.path);
    v.field({"frames", "", "frames to render"}, s.frames, 1, 1000000);
    v.field({"fps", "1/s", "frames per second of path time"}, s.fps, 0.01f, 1000.0f);
    v.field({"width", "px", "image width"}, s.width, 1, 16384);
    v.field({"height", "px", "image height"}, s.height, 1, 16384);
    v.choice({"format", "", "png: 8-bit sRGB after tone mapping; exr: linear half-float HDR; mp4: the PNG frames, then "
                            "an H.264 video of them (out/capture.mp4, through ffmpeg)"},
             s.format, formats);
    v.field({"out", "", "output directory"}, s.out);
    v.field({"settle_frames", "frames",
             "frames rendered but not written before a run's first written frame (at the path times of the frames "
             "before it), so temporal state (auto exposure, autofocus, motion blur, weather, history) is the same "
             "whichever shard or resumed run renders a frame; adaptation settles by exp(-rate * settle_frames / fps)"},
            s.settle_frames, 0, 10000);
    v.field({"crf", "", "H.264 constant rate factor of mp4 output: 0 lossless, 18 visually lossless, 23 ffmpeg's "
                        "default, 51 worst"},
            s.crf, 0, 51);
}

void describe(SettingsVisitor& v, DebugSettings& s) {
    static constexpr std::array<const char*, 10> views{"final", "depth", "albedo", "normals", "lights", "cascades", "shadow_map", "shadow", "spot_atlas", "point_shadows"};
    v.section("debug", "debug views and helpers");
    v.choice({"view", "", "what the screen shows: final image, depth, G-buffer albedo or normals, lights = heat map of local lights evaluated per pixel, cascades = sun shadow cascade colours, shadow_map = the cascades' depth maps, shadow = the sun's visibility (white lit, black shadowed or facing away), spot_atlas = the spot lights' shadow atlas, point_shadows = the point lights' depth cubes (a row of six faces per light)"},
             s.view, views);
    v.field({"heat_max", "lights", "light count shown red in the lights view"}, s.heat_max, 1.0f, 65536.0f);
    v.field({"grid", "", "reference grid on the y = 0 plane"}, s.grid);
    v.field({"grid_spacing", "m", "distance between minor grid lines"}, s.grid_spacing, 0.01f, 100000.0f);
}

void describe(SettingsVisitor& v, TerrainSettings& s) {
    static constexpr std::array<const char*, 6> views{"shaded", "lod", "morph", "normals", "error", "material"};
    static constexpr std::array<const char*, 2> metrics{"error", "distance"};
    v.section("terrain", "heightmap terrain with CDLOD level of detail");
    v.field({"enabled", "", "draw the terrain"}, s.enabled);
    v.field({"heightmap", "", "PNG (8/16-bit), TIFF, EXR, or raw .r16 with raw_width/raw_height"}, s.heightmap);
    v.field({"raw_width", "samples", "width of a .r16 heightmap"}, s.raw_width, 0, 65536);
    v.field({"raw_height", "samples", "height of a .r16 heightmap"}, s.raw_height, 0, 65536);
    static constexpr std::array<const char*, 2> nodata{"fill", "refuse"};
    v.field({"dem", "", "elevation model read by GDAL (GeoTIFF, SRTM .hgt, ESRI ASCII grid, VRT mosaic, ...): replaces "
                        "heightmap; size_m, height_scale_m and height_offset_m then come from its geotransform and heights "
                        "(docs/dem.md)"},
            s.dem);
    v.choice({"dem_nodata", "", "a DEM's nodata cells: fill = from their neighbours, refuse = an error naming the first"},
             s.dem_nodata, nodata);
    v.field({"dem_vertical_scale", "x", "multiplies a DEM's heights (vertical exaggeration)"}, s.dem_vertical_scale, 0.01f,
            100.0f);
    v.field({"origin", "m", "world position of the map centre; y is added to heights"}, s.origin, -1e8, 1e8);
    v.field({"size_m", "m", "extent of the map in x and z"}, s.size_m, 1.0f, 1.0e7f);
    v.field({"height_scale_m", "m", "height of heightmap value 1"}, s.height_scale_m, 0.0f, 1.0e5f);
    v.field({"height_offset_m", "m", "height of heightmap value 0"}, s.height_offset_m, -1.0e5f, 1.0e5f);
    v.field({"grid", "quads", "quads per node side; a leaf node spans this many texels"}, s.grid, 2, 256);
    v.choice({"lod_metric", "", "error: per-node screen error picks the detail; distance: Strugar's ranges alone"},
             s.lod_metric, metrics);
    v.field({"max_error_px", "px", "largest vertical screen error the LOD may leave"}, s.max_error_px, 0.05f, 100.0f);
    v.field({"bias_slope", "m/m", "error metric: largest slope of the distance bias (finer transitions, larger ranges)"},
            s.bias_slope, 0.05f, 4.0f);
    v.field({"base_range_m", "m", "LOD 0 range (raised to what node size and error need)"}, s.base_range_m, 1.0f, 1.0e6f);
    v.field({"range_ratio", "x", "range growth per LOD level"}, s.range_ratio, 1.5f, 4.0f);
    v.field({"morph_start", "", "fraction of each level's span before morphing starts"}, s.morph_start, 0.0f, 0.95f);
    v.choice({"view", "", "shaded, or colour by LOD level, morph factor, normal, screen error (px) or material layer (the "
                          "largest weight; alpha = layer index)"},
             s.view, views);
    v.field({"wireframe", "", "overlay the node grids' edges"}, s.wireframe);
    v.field({"bounds", "", "draw the selected nodes' bounding boxes"}, s.bounds);
    v.field({"detail_distance_m", "m", "detail normals and triplanar rock fade out by this distance (near material tier)"},
            s.detail_distance_m, 1.0f, 100000.0f);
    v.field({"far_material_m", "m", "material textures give way to each layer's mean albedo by this distance, from 3/4 of it "
                                    "(far material tier; 0: never)"},
            s.far_material_m, 0.0f, 1.0e7f);
    v.field({"material_tiers", "", "draw each distance tier of the material with its own program (off: the near tier's "
                                   "everywhere: the same image, slower; for checking seams)"},
            s.material_tiers);
    v.field({"texture_scale_m", "m", "size of one repeat of a material texture"}, s.texture_scale_m, 0.05f, 1000.0f);
    v.field({"sand_top", "", "heightmap value where beaches end"}, s.sand_top, 0.0f, 1.0f);
    v.field({"grass_top", "", "heightmap value where grass gives way to rock"}, s.grass_top, 0.0f, 1.0f);
    v.field({"snow_start", "", "heightmap value where snow begins"}, s.snow_start, 0.0f, 1.0f);
    v.field({"band_blend", "", "heightmap units over which bands blend"}, s.band_blend, 0.0001f, 0.5f);
    v.field({"band_jitter", "", "heightmap units of noise on band edges"}, s.band_jitter, 0.0f, 0.5f);
    v.field({"rock_slope", "", "normal y below which slopes turn to rock (1 = flat)"}, s.rock_slope, 0.0f, 1.0f);
    v.field({"material_anisotropy", "x", "anisotropic filtering of the material textures (albedo, detail normals, heights); "
                                         "1: trilinear only"},
            s.material_anisotropy, 1, 16);
    v.field({"splat_map", "", "RGBA image(s) of material weights over the heightmap, one texel per height sample: replace "
                              "the height/slope rules (one file, or two separated by a space: 8 channels; docs/terrain-materials.md)"},
            s.splat_map);
    v.field({"splat_layers", "", "the layer each splat channel weighs, by name (sand grass rock snow dirt or a "
                                 "[terrain.material.NAME]), separated by spaces; empty: the user materials in file order"},
            s.splat_layers);
    TerrainPomSettings& p = s.pom;
    v.section("terrain.pom", "parallax occlusion mapping of the near terrain's material relief (docs/terrain-detail.md)");
    v.field({"enabled", "", "march the material height field in the near material tier (off: no program variant)"}, p.enabled);
    v.field({"max_steps", "steps", "linear search steps at a grazing view; a quarter of them looking straight down"},
            p.max_steps, 2, 256);
    v.field({"refine_steps", "steps", "binary refinement steps after the linear search"}, p.refine_steps, 0, 16);
    v.field({"depth_m", "m", "depth of material height 0 below height 1 (the drawn surface)"}, p.depth_m, 0.001f, 1.0f);
    v.field({"distance_m", "m", "the relief flattens from half this distance and is plain normal mapping beyond it "
                               "(at most [terrain] detail_distance_m)"},
            p.distance_m, 1.0f, 10000.0f);
    v.field({"shadow", "", "strength of the relief's soft self-shadowing toward the sun (0: none)"}, p.shadow, 0.0f, 1.0f);
    v.field({"shadow_steps", "steps", "steps of the self-shadowing march toward the sun"}, p.shadow_steps, 1, 64);
    TerrainTessSettings& t = s.tessellation;
    v.section("terrain.tessellation", "tessellated displacement of the near terrain by the material relief, also in the "
                                      "shadow passes (docs/terrain-detail.md)");
    v.field({"enabled", "", "tessellate and displace the quadrants nearer than range_m (off: no program variant)"}, t.enabled);
    v.field({"range_m", "m", "quadrants nearer than this are tessellated; the displacement fades out by 90% of it"}, t.range_m,
            2.0f, 1000.0f);
    v.field({"edge_px", "px", "target length of a tessellated edge on screen"}, t.edge_px, 1.0f, 64.0f);
    v.field({"max_factor", "", "largest subdivision of an edge"}, t.max_factor, 1.0f, 32.0f);
    v.field({"depth_m", "m", "depth of relief height 0 below the drawn surface"}, t.depth_m, 0.001f, 1.0f);
    TerrainStreamSettings& st = s.stream;
    v.section("terrain.stream", "draw the terrain from its tile cache through a fixed GPU page pool, loaded by worker "
                                "threads, without the whole map in memory (docs/dem.md)");
    v.field({"enabled", "", "stream from the tile cache (built first when missing or stale; its tile must equal [terrain] "
                            "grid); not with grass, rain splashes or tessellation, which read the whole map"},
            st.enabled);
    v.field({"cache", "", "tile cache file (vista terrain-cache --tile GRID); empty: the heightmap's or DEM's path + .vtc"},
            st.cache);
    v.field({"pool_pages", "tiles", "tiles the GPU page pool holds (heights and normals; the coarsest levels stay)"},
            st.pool_pages, 16, 65536);
    v.field({"uploads_per_frame", "tiles", "finished tile loads uploaded per frame at most"}, st.uploads_per_frame, 1, 4096);
    v.field({"threads", "", "worker threads reading tiles"}, st.threads, 1, 16);
    v.field({"prefetch_frames", "frames", "also request the tiles the camera will need this many frames ahead, moving as "
                                          "it did over the last frame (0: none)"},
            st.prefetch_frames, 0, 600);
    for (TerrainMaterialSettings& m : s.materials) {
        v.section(m.section.c_str(), "a user material: images of one square power-of-two size; NAME sand, grass, rock, "
                                     "snow or dirt replaces that layer, any other adds one (docs/terrain-materials.md)");
        v.field({"albedo", "", "sRGB colour image, RGB or RGBA (alpha ignored); required"}, m.albedo);
        v.field({"normal", "", "tangent-space normal map, RGB (0.5 + 0.5 n, green toward the bottom row: DirectX style); empty: flat"}, m.normal);
        v.field({"height", "", "relief height for POM and tessellation, one channel (0 lowest .. 1 highest); empty: flat"},
                m.height);
        v.field({"roughness", "", "roughness image, one channel; empty: roughness_value"}, m.roughness);
        v.field({"roughness_value", "", "roughness where no roughness image is given"}, m.roughness_value, 0.0f, 1.0f);
        v.field({"tiling_m", "m", "size of one repeat of the images on the ground"}, m.tiling_m, 0.05f, 1000.0f);
    }
}

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
    v.field({"shadows", "", "cloud shadows on the terrain (clouds.shadow)"}, s.shadows);
    v.field({"shadow_size", "texels", "shadow map texels per side"}, s.shadow_size, 16, 2048);
    v.field({"shadow_extent_km", "km", "ground covered by the shadow map around the camera"}, s.shadow_extent_km, 0.1f, 1000.0f);
    describe(v, s.low, "clouds.low", "the lower cloud layer");
    describe(v, s.high, "clouds.high", "the upper cloud layer");
}

void describe(SettingsVisitor& v, PostfxSettings& s) {
    static constexpr std::array<const char*, 10> effects{"bloom", "exposure", "tonemap", "fxaa", "grade", "dof",
                                                        "motion_blur", "lens_flare", "night_vision", "scotopic"};
    v.section("postfx", "post-processing chain");
    v.field({"enabled", "", "run the post chain (off: clamp and sRGB only)"}, s.enabled);
    v.sequence({"order", "", "effects in the order they run; before tonemap on linear HDR, after it on the display image"},
               s.order, effects);
}

void describe(SettingsVisitor& v, ExposureSettings& s) {
    static constexpr std::array<const char*, 3> modes{"manual", "auto", "camera"};
    v.section("postfx.exposure", "exposure: manual, automatic from a log-luminance histogram, or a physical camera's");
    v.field({"enabled", "", "apply exposure"}, s.enabled);
    v.choice({"mode", "",
              "manual: scale 2^ev; auto: metered average to middle grey (0.18), times 2^ev; camera: EV100 from "
              "[postfx.dof] f_stop, [postfx.motion_blur] shutter_deg / 360 / frame_rate and iso, 1.2 * 2^EV100 cd/m^2 "
              "to 1, times 2^ev"},
             s.mode, modes);
    v.field({"ev", "stops", "exposure compensation, scale 2^ev"}, s.ev, -20.0f, 20.0f);
    v.field({"min_ev", "stops", "auto: lowest metered log2 luminance in [sky] sun_illuminance units (darker scenes stay dark)"}, s.min_ev, -40.0f, 20.0f);
    v.field({"max_ev", "stops", "auto: highest metered log2 luminance (brighter scenes stay bright)"}, s.max_ev, -40.0f, 20.0f);
    v.field({"night_ev", "stops", "auto: darker than middle grey by this at scotopic adaptation (< 0.005 cd/m^2), none above 5 cd/m^2"}, s.night_ev, 0.0f, 10.0f);
    v.field({"low_percent", "%", "auto: darkest share of pixels left out of the average"}, s.low_percent, 0.0f, 99.0f);
    v.field({"high_percent", "%", "auto: percentile above which pixels are left out of the average"}, s.high_percent, 1.0f, 100.0f);
    v.field({"speed_up", "1/s", "auto: adaptation rate towards brighter (difference falls by e in 1/rate s)"}, s.speed_up, 0.01f, 100.0f);
    v.field({"speed_down", "1/s", "auto: adaptation rate towards darker"}, s.speed_down, 0.01f, 100.0f);
    v.field({"iso", "", "camera: sensitivity (ISO arithmetic); sunny 16: f/16, 1/100 s, ISO 100"}, s.iso, 1.0f, 1.0e6f);
}

void describe(SettingsVisitor& v, TonemapSettings& s) {
    static constexpr std::array<const char*, 4> ops{"reinhard", "aces", "clamp", "agx"};
    v.section("postfx.tonemap", "tone mapping from HDR to display");
    v.field({"enabled", "", "tone map (off: clamp)"}, s.enabled);
    v.choice({"op", "", "operator: extended Reinhard on luminance, ACES fit (Narkowicz), clamp, AgX (Sobotka)"}, s.op, ops);
    v.field({"white", "", "linear value mapped to white (reinhard)"}, s.white, 0.01f, 1000.0f);
}

void describe(SettingsVisitor& v, BloomSettings& s) {
    v.section("postfx.bloom", "bloom: 13-tap downsample chain and tent upsample (Jimenez 2014)");
    v.field({"enabled", "", "add bloom"}, s.enabled);
    v.field({"intensity", "", "share of the blurred image in the result"}, s.intensity, 0.0f, 1.0f);
    v.field({"radius", "", "weight of each coarser level while upsampling: 0 tight, 1 wide"}, s.radius, 0.0f, 1.0f);
    v.field({"levels", "", "downsample levels, each half the size of the one above"}, s.levels, 1, 10);
    v.field({"clamp", "", "highlights clamped to this before blurring (NaN and Inf count as 0)"}, s.clamp, 1.0f, 65504.0f);
}

void describe(SettingsVisitor& v, FxaaSettings& s) {
    v.section("postfx.fxaa", "FXAA anti-aliasing on the display image");
    v.field({"enabled", "", "run FXAA"}, s.enabled);
    v.field({"edge_threshold", "", "smallest local luma contrast treated as an edge"}, s.edge_threshold, 0.01f, 1.0f);
    v.field({"edge_threshold_min", "", "luma contrast below this is never an edge (dark areas)"}, s.edge_threshold_min, 0.0f, 1.0f);
    v.field({"subpixel", "", "sub-pixel aliasing removal, 0 off, 1 softest"}, s.subpixel, 0.0f, 1.0f);
}

void describe(SettingsVisitor& v, TaaSettings& s) {
    v.section("postfx.taa", "temporal anti-aliasing on the HDR image before the post chain (Karis 2014)");
    v.field({"enabled", "", "jitter the projection and resolve against the reprojected history"}, s.enabled);
    v.field({"blend", "", "share of the current frame in the result (1: history off)"}, s.blend, 0.02f, 1.0f);
    v.field({"clip_gamma", "", "history clipped to the neighbourhood mean +- this many standard deviations (YCoCg)"}, s.clip_gamma, 0.5f, 4.0f);
    v.field({"sharpen", "", "unsharp mask of the history against its bilinear fetch"}, s.sharpen, 0.0f, 1.0f);
    v.field({"disocclusion", "", "relative depth difference that rejects the history"}, s.disocclusion, 0.001f, 1.0f);
    v.field({"cut_distance_m", "m", "a camera jump beyond this between frames is a cut: TAA and cloud history dropped"}, s.cut_distance_m, 0.0f, 1.0e9f);
    v.field({"cut_angle_deg", "deg", "a camera turn beyond this between frames is a cut"}, s.cut_angle_deg, 0.0f, 180.0f);
}

void describe(SettingsVisitor& v, GradeSettings& s) {
    v.section("postfx.grade", "colour grading on the display image: lift/gamma/gain, saturation, vignette");
    v.field({"enabled", "", "grade the image"}, s.enabled);
    v.field({"lift", "", "raises the blacks per channel: c + lift * (1 - c)"}, s.lift, -1.0f, 1.0f);
    v.field({"gamma", "", "mid-tones per channel: c^(1/gamma), above 1 brightens"}, s.gamma, 0.1f, 10.0f);
    v.field({"gain", "", "scales the whites per channel"}, s.gain, 0.0f, 10.0f);
    v.field({"saturation", "", "0 grey, 1 unchanged"}, s.saturation, 0.0f, 4.0f);
    v.field({"vignette", "", "darkening at the corners, 0 none, 1 black"}, s.vignette, 0.0f, 1.0f);
    v.field({"vignette_start", "", "share of the centre-to-corner distance where the darkening begins"}, s.vignette_start, 0.0f, 1.0f);
    v.field({"grain", "", "film grain amplitude at mid-grey (none at black and white)"}, s.grain, 0.0f, 1.0f);
    v.field({"grain_rate", "1/s", "new grain pattern this many times per second of scene time"}, s.grain_rate, 0.0f, 1000.0f);
    v.field({"lut", "", "optional 3D LUT (.cube file), applied after saturation; empty: none"}, s.lut);
}

void describe(SettingsVisitor& v, ScotopicSettings& s) {
    v.section("postfx.scotopic", "scotopic vision at night: rods' luminance, blue shift, loss of acuity, below 5 cd/m^2");
    v.field({"enabled", "", "apply on frames whose sky gives less than 400 lx"}, s.enabled);
    v.field({"blue_shift", "", "share of the rods' blue tint (0: grey)"}, s.blue_shift, 0.0f, 1.0f);
    v.field({"acuity_arcmin", "arcmin", "blur radius at full scotopic vision"}, s.acuity_arcmin, 0.0f, 60.0f);
    v.field({"show_rod_share", "", "debug: show the rods' share per pixel as grey"}, s.show_rod_share);
}

void describe(SettingsVisitor& v, NightVisionSettings& s) {
    v.section("postfx.night_vision", "night vision: amplified luminance, noise, green tint, scope vignette");
    v.field({"enabled", "", "night vision (place it after tonemap)"}, s.enabled);
    v.field({"gain", "", "luminance amplification"}, s.gain, 1.0f, 1000.0f);
    v.field({"noise", "", "noise amplitude"}, s.noise, 0.0f, 1.0f);
    v.field({"noise_rate", "1/s", "new noise pattern this many times per second of scene time"}, s.noise_rate, 0.0f, 1000.0f);
    v.field({"vignette", "", "darkening outside the scope circle, 1 black"}, s.vignette, 0.0f, 1.0f);
    v.field({"tint", "", "phosphor colour"}, s.tint, 0.0f, 1.0f);
}

void describe(SettingsVisitor& v, SsaoSettings& s) {
    v.section("postfx.ssao", "screen-space ambient occlusion (horizon based), multiplies the ambient light");
    v.field({"enabled", "", "compute ambient occlusion before the lighting"}, s.enabled);
    v.field({"radius_m", "m", "world-space reach of the horizon search"}, s.radius_m, 0.01f, 100.0f);
    v.field({"intensity", "", "strength: ao = 1 - intensity * occlusion"}, s.intensity, 0.0f, 4.0f);
    v.field({"bias", "", "sine of the horizon angle ignored (against self-occlusion)"}, s.bias, 0.0f, 0.9f);
    v.field({"directions", "", "horizon directions per pixel"}, s.directions, 1, 16);
    v.field({"steps", "", "depth samples along each direction"}, s.steps, 1, 32);
    v.field({"half_resolution", "", "compute at half size (the blur upsamples depth-aware)"}, s.half_resolution);
    v.field({"blur", "", "3x3 bilateral blur (off: nearest upsample only)"}, s.blur);
    v.field({"blur_depth_tolerance", "", "relative depth difference at which blur weights fall by e"}, s.blur_depth_tolerance, 0.001f, 1.0f);
}

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

void describe(SettingsVisitor& v, WeatherSettings& s) {
    static constexpr std::array<const char*, 2> kinds{"rain", "snow"};
    v.section("weather", "rain or snow around the camera: falling streaks, splashes, wet terrain");
    v.field({"enabled", "", "draw rain or snow (off: no pass, no buffer, dry terrain)"}, s.enabled);
    v.choice({"kind", "", "rain: velocity streaks, splashes and wet ground; snow: slow swaying flakes"}, s.kind, kinds);
    v.field({"intensity", "", "share of max_density drawn; also streak opacity, splash rate and wetness"}, s.intensity, 0.0f, 1.0f);
    v.field({"max_density", "1/m^3", "drops per cubic metre at intensity 1"}, s.max_density, 0.01f, 50.0f);
    v.field({"radius_m", "m", "drops are drawn up to this distance (fading over its last quarter)"}, s.radius_m, 2.0f, 100.0f);
    v.field({"cell_m", "m", "side of a placement cell; each cell's drops come from a hash of its coordinates"}, s.cell_m, 0.5f, 8.0f);
    v.field({"near_fade_m", "m", "drops closer than this are left out; they fade in over the next near_fade_m"}, s.near_fade_m, 0.0f, 10.0f);
    v.field({"drop_speed_m_s", "m/s", "fall speed (rain 4..9, snow 0.5..1.5)"}, s.drop_speed_m_s, 0.1f, 50.0f);
    v.field({"drop_width_m", "m", "streak width (rain) or flake diameter (snow)"}, s.drop_width_m, 0.0005f, 0.1f);
    v.field({"streak_time_s", "s", "a streak spans the drop's motion relative to the camera over this time"}, s.streak_time_s, 0.0f, 0.5f);
    v.field({"brightness", "", "scale of the sun and sky light a drop sends back"}, s.brightness, 0.0f, 20.0f);
    v.field({"wind_from_clouds", "", "use the wind of [clouds.low] times wind_scale (off: wind_speed_m_s, wind_direction_deg)"}, s.wind_from_clouds);
    v.field({"wind_scale", "", "share of the low cloud layer's wind felt near the ground"}, s.wind_scale, 0.0f, 2.0f);
    v.field({"wind_speed_m_s", "m/s", "horizontal wind when wind_from_clouds is off"}, s.wind_speed_m_s, 0.0f, 100.0f);
    v.field({"wind_direction_deg", "deg", "heading the wind blows toward, clockwise from -z (wind_from_clouds off)"}, s.wind_direction_deg, -360.0f, 360.0f);
    v.field({"splashes", "", "rain: short-lived splashes on the terrain (weather.splash)"}, s.splashes);
    v.field({"splash_rate", "1/(m^2 s)", "splashes per square metre per second at intensity 1"}, s.splash_rate, 0.0f, 1000.0f);
    v.field({"splash_radius_m", "m", "splashes are drawn up to this distance"}, s.splash_radius_m, 1.0f, 50.0f);
    v.field({"splash_size_m", "m", "largest radius of a splash's crown"}, s.splash_size_m, 0.005f, 1.0f);
    v.field({"splash_life_s", "s", "a splash grows and fades over this time"}, s.splash_life_s, 0.01f, 2.0f);
    v.field({"wetness", "", "rain: how wet the terrain gets at intensity 0.5 and above (darker, glossier)"}, s.wetness, 0.0f, 1.0f);
}

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

void describe(SettingsVisitor& v, DofSettings& s) {
    v.section("postfx.dof", "depth of field: thin-lens circle of confusion, autofocus, near/far gather");
    v.field({"enabled", "", "blur what is out of focus (needs the scene depth)"}, s.enabled);
    v.field({"focus_distance_m", "m", "focus distance when autofocus is off"}, s.focus_distance_m, 0.1f, 1.0e6f);
    v.field({"focal_length_mm", "mm", "lens focal length"}, s.focal_length_mm, 1.0f, 2000.0f);
    v.field({"f_stop", "", "f-number N: aperture diameter = focal length / N"}, s.f_stop, 0.5f, 64.0f);
    v.field({"sensor_height_mm", "mm", "sensor height: CoC in pixels = CoC on the sensor / sensor height * image height"},
            s.sensor_height_mm, 1.0f, 100.0f);
    v.field({"autofocus", "", "focus on the screen centre (median of 5 depth samples)"}, s.autofocus);
    v.field({"autofocus_rate", "1/s", "autofocus speed: the gap (in diopters) falls by e in 1/rate s"}, s.autofocus_rate,
            0.01f, 100.0f);
    v.field({"max_coc_px", "px", "largest blur radius"}, s.max_coc_px, 1.0f, 64.0f);
    v.field({"samples", "", "gather taps per pixel (quality knob)"}, s.samples, 4, 256);
    v.field({"debug", "", "show the circle of confusion: red far, green near, blue in focus"}, s.debug);
}

void describe(SettingsVisitor& v, MotionBlurSettings& s) {
    v.section("postfx.motion_blur", "camera motion blur: depth reprojection, tile/neighbour max, McGuire 2012 gather");
    v.field({"enabled", "", "blur by the camera's motion (needs the scene depth)"}, s.enabled);
    v.field({"shutter_deg", "deg", "shutter angle: exposure = shutter / 360 / frame_rate seconds"}, s.shutter_deg, 0.0f, 360.0f);
    v.field({"frame_rate", "1/s", "film rate the shutter angle refers to (not the render rate)"}, s.frame_rate, 1.0f, 1000.0f);
    v.field({"max_blur_px", "px", "longest blur, half on each side of a pixel; also the tile size"}, s.max_blur_px, 2.0f, 64.0f);
    v.field({"samples", "", "gather taps per pixel (quality knob)"}, s.samples, 2, 64);
    v.field({"depth_extent", "", "relative depth difference over which foreground and background blend"},
            s.depth_extent, 0.001f, 1.0f);
}

void describe(SettingsVisitor& v, LensFlareSettings& s) {
    v.section("postfx.lens_flare", "sun lens flare: ghosts, halo, chromatic aberration, starburst, faded by visibility");
    v.field({"enabled", "", "add a lens flare while the sun is on screen and above the horizon"}, s.enabled);
    v.field({"intensity", "", "flare radiance per unit sun illuminance"}, s.intensity, 0.0f, 1.0f);
    v.field({"ghosts", "", "ghost discs along the sun-to-centre axis"}, s.ghosts, 0, 16);
    v.field({"ghost_spacing", "", "ghost spacing along the axis (1 = sun to centre)"}, s.ghost_spacing, 0.01f, 2.0f);
    v.field({"halo_radius", "", "halo ring radius, share of the image height"}, s.halo_radius, 0.0f, 2.0f);
    v.field({"chromatic", "", "red/blue separation along the axis"}, s.chromatic, 0.0f, 0.5f);
    v.field({"starburst", "", "strength of the rays around the sun"}, s.starburst, 0.0f, 10.0f);
    v.field({"visibility_radius_deg", "deg", "radius of the 16 depth samples around the sun"}, s.visibility_radius_deg,
            0.01f, 10.0f);
    v.field({"visibility_rate", "1/s", "visibility follows the sky share of the samples by e in 1/rate s"},
            s.visibility_rate, 0.01f, 100.0f);
}

}  // namespace

bool isValidListName(std::string_view name) {
    return !name.empty() && std::ranges::all_of(name, [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
    });
}

bool addNamedSection(Settings& s, std::string_view section) {
    constexpr std::string_view kMaterial = "terrain.material.";
    if (!section.starts_with(kMaterial) || !isValidListName(section.substr(kMaterial.size()))) return false;
    for (const TerrainMaterialSettings& m : s.terrain.materials)
        if (m.section == section) return true;
    TerrainMaterialSettings m;
    m.name = std::string(section.substr(kMaterial.size()));
    m.section = std::string(section);
    s.terrain.materials.push_back(std::move(m));
    return true;
}

void describe(SettingsVisitor& v, Settings& s) {
    describe(v, s.window);
    describe(v, s.camera);
    describe(v, s.capture);
    describe(v, s.debug);
    describe(v, s.terrain);
    describe(v, s.grass);
    describe(v, s.sky);
    describe(v, s.clouds);
    describe(v, s.shadows);
    describe(v, s.weather);
    describe(v, s.lights);  // renderer/lighting/light_settings.cpp
    describe(v, s.water);
    describe(v, s.objects);  // terrain/scatter/object_settings.cpp
    describe(v, s.postfx);
    describe(v, s.exposure);
    describe(v, s.tonemap);
    describe(v, s.bloom);
    describe(v, s.fxaa);
    describe(v, s.taa);
    describe(v, s.grade);
    describe(v, s.ssao);
    describe(v, s.dof);
    describe(v, s.motion_blur);
    describe(v, s.lens_flare);
    describe(v, s.night_vision);
    describe(v, s.scotopic);
}

}  // namespace vista
