// `vista terrain-cache FILE`: builds the tile cache (terrain/tile_cache.h) of a DEM or a
// heightmap once, and says whether an existing one is up to date, stale or damaged.
#pragma once

#include <filesystem>

namespace vista {

struct TerrainCacheOptions {
    std::filesystem::path input;
    std::filesystem::path out;     // "" : <input>.vtc
    int tile = 256;                // samples between tile origins, 2..4096
    bool force = false;            // rebuild even when the cache is up to date
    bool progress = true;
    // A heightmap image (no georeferencing) is mapped as [terrain] maps it:
    double size_m = 8192.0, height_scale_m = 600.0, height_offset_m = 0.0;
    int raw_width = 0, raw_height = 0;  // a raw .r16's size in samples ([terrain] raw_width, raw_height)
};

// 0: the cache is up to date or was built; 2: bad input (the file, the tile size); 1: the
// cache could not be written. A stale, truncated or damaged cache is rebuilt (and says why).
int runTerrainCache(const TerrainCacheOptions& o);

}  // namespace vista
