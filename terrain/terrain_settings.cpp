// [terrain], [terrain.pom], [terrain.tessellation], [terrain.stream] and [terrain.material.NAME]: the keys, units, ranges and help text.
#include "terrain/terrain_settings.h"

#include <array>

namespace vista {

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

}  // namespace vista
