// `vista terrain-cache`: read the input as a DEM (GDAL, a row at a time unless it has nodata to
// fill) or, when it has no georeferencing, as a heightmap image (a band of rows at a time when it
// has one channel); check any cache already there against the input's key; build when needed.
#include "app/terrain_cache_cmd.h"

#include "app/progress.h"
#include "terrain/dem.h"
#include "terrain/heightmap.h"
#include "terrain/heightmap_rows.h"
#include "terrain/tile_cache.h"

#include <chrono>
#include <cstdio>

namespace vista {
namespace {

int fail(const std::string& why, int code) {
    std::fprintf(stderr, "vista: %s\n", why.c_str());
    return code;
}

}  // namespace

int runTerrainCache(const TerrainCacheOptions& o) {
    if (o.tile < 2 || o.tile > 4096) return fail("--tile " + std::to_string(o.tile) + " is out of range; accepted: 2..4096", 2);
    const std::filesystem::path out = o.out.empty() ? defaultTileCachePath(o.input) : o.out;
    TileCacheKey key;
    if (std::string why = tileCacheKey(o.input, key); !why.empty()) return fail(why, 2);

    std::string why;
    if (auto cache = TileCache::open(out, why)) {
        if (cache->key() == key && cache->tileSize() == o.tile && !o.force) {
            std::printf("%s is up to date (%zu levels)\n", out.string().c_str(), cache->levels().size());
            return 0;
        }
        if (!(cache->key() == key)) std::fprintf(stderr, "vista: %s was built from another version of %s: rebuilding\n",
                                                out.string().c_str(), o.input.string().c_str());
    } else if (std::filesystem::exists(out)) {
        std::fprintf(stderr, "vista: %s: rebuilding\n", why.c_str());
    }

    // A DEM when GDAL finds georeferencing, read a row at a time (loaded whole when it has nodata
    // cells to fill); a plain image goes through OpenImageIO instead: a one-channel image (a
    // gen-heightmap TIFF, a 16-bit PNG) a band of rows at a time, a raw .r16 a row at a time,
    // anything else (EXR, RGB) whole.
    InputErrors errors;
    bool fill_whole = false;
    // A raw .r16 is no DEM (GDAL does not know it).
    const bool raw = isRawHeightmap(o.input);
    std::unique_ptr<DemRows> dem_rows = raw ? nullptr : DemRows::open(o.input, DemNodata::Fill, 1.0, errors, fill_whole);
    std::unique_ptr<HeightmapRows> image_rows;
    TileCacheRows read;  // set when the input is read a row at a time
    Heightmap map;       // the input held whole otherwise (or only its size)
    TerrainMapping mapping;
    if (dem_rows) {
        map.width = dem_rows->width();
        map.height = dem_rows->height();
        mapping = demMapping(dem_rows->info(), map.width, map.height);
        read = [&](int z, float* row) { return dem_rows->read(z, row); };
    } else if (fill_whole) {
        Dem dem = loadDem(o.input, DemNodata::Fill, 1.0, errors);
        if (!dem.map.samples.empty()) {
            mapping = demMapping(dem.info, dem.map.width, dem.map.height);
            map = std::move(dem.map);
        }
    } else if (raw || (errors.size() == 1 && errors[0].message.find("no geotransform") != std::string::npos)) {
        errors.clear();
        std::string not_rows;
        image_rows = HeightmapRows::open(o.input, not_rows, o.raw_width, o.raw_height);
        if (image_rows) {
            map.width = image_rows->width();
            map.height = image_rows->height();
            read = [&](int z, float* row) { return image_rows->read(z, row); };
        } else {
            map = loadHeightmap(o.input, o.raw_width, o.raw_height, errors);
        }
        mapping = TerrainMapping{o.size_m, o.height_scale_m, o.height_offset_m, map.width, map.height};
    }
    if (!read && map.samples.empty()) {
        for (const auto& e : errors) std::fprintf(stderr, "vista: %s\n", e.str().c_str());
        return 2;
    }
    const auto start = std::chrono::steady_clock::now();
    int total = 0;
    for (const auto& l : tileCacheLevels(map.width, map.height, o.tile)) total += l.tiles_x * l.tiles_z;
    Progress progress(total, "terrain-cache", stderr, "tiles");
    auto report = [&](int done, int) {
        if (o.progress) progress.update(done);
    };
    why = read ? buildTileCache(map.width, map.height, read, mapping, key, o.tile, out, true, report)
               : buildTileCache(map, mapping, key, o.tile, out, true, report);
    if (o.progress) progress.finish();
    if (!why.empty()) return fail(why, read && why.rfind(o.input.string(), 0) == 0 ? 2 : 1);
    std::printf("wrote %s: %dx%d samples, %d tiles of %d, %.1f MB, in %.2f s\n", out.string().c_str(), map.width, map.height,
                total, o.tile, double(std::filesystem::file_size(out)) / 1e6,
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    return 0;
}

}  // namespace vista
