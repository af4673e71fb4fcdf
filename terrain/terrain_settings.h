// [terrain], [terrain.pom], [terrain.tessellation], [terrain.stream] and [terrain.material.NAME]: the heightmap terrain (terrain/terrain.h).
// describe() is the one description of the keys; config/settings.h gathers them into Settings.
#pragma once

#include "config/visitor.h"

#include <glm/vec3.hpp>

#include <string>
#include <vector>

namespace vista {

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

// Lists the keys of TerrainSettings to v, in file order.
void describe(SettingsVisitor& v, TerrainSettings& s);

}  // namespace vista
