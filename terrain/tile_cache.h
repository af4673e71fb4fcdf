// The terrain tile cache (`vista terrain-cache FILE`): a level-of-detail pyramid on disk, built
// once per input, holding per tile its heights, normals, min/max and grid error, and the map's
// exact grid errors per leaf cell, so a reader needs only the index in memory and reads the tiles
// it wants.
//
// Level 0 is the map; level l + 1 keeps every other sample of level l (what CDLOD's coarser
// grids sample), down to the first level that fits one tile. A tile of level l covers samples
// [t * tile, t * tile + tile] of that level (neighbours share their border samples), fewer at
// the map's far edges. The file is keyed by its input (size, modification time, a hash of the
// first 64 KiB), written atomically, and checked: a header/index hash, a hash per tile, an end
// marker, so a truncated, damaged or stale cache is found and rebuilt or refused.
#pragma once

#include "terrain/cdlod.h"
#include "terrain/heightmap.h"
#include "terrain/lod_error.h"

#include <cstdint>
#include <deque>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

namespace vista {

struct TileCacheKey {
    std::uint64_t size = 0;         // bytes of the input
    std::int64_t mtime_ns = 0;      // its modification time
    std::uint64_t header_hash = 0;  // FNV-1a of its first 64 KiB
    bool operator==(const TileCacheKey&) const = default;
};

// The key of an input file; "" on success, else why.
std::string tileCacheKey(const std::filesystem::path& input, TileCacheKey& key);

struct CacheTile {
    int width = 0, height = 0;        // samples
    float min_m = 0.0f, max_m = 0.0f; // heights (m) of the tile's samples
    float error_m = 0.0f;             // largest height difference (m) to the full map over the tile (0 at level 0)
    std::vector<float> heights;       // samples as the heightmap's (metres = offset + scale * sample), row-major
    std::vector<std::int8_t> normals; // world normals as RGBA8 snorm (x, y, z, 0), as the GPU keeps them
};

struct TileCacheLevel {
    int width = 0, height = 0;  // samples
    int tiles_x = 0, tiles_z = 0;
};

// The pyramid's levels: sizes, tile counts.
std::vector<TileCacheLevel> tileCacheLevels(int width, int height, int tile);

// Level l + 1 of the pyramid from level l (every other sample; the last one always kept).
Heightmap halveLevel(const Heightmap& level);
// Normals of a level (central differences at its texel spacing, one-sided at the edges), RGBA8 snorm.
std::vector<std::int8_t> levelNormals(const Heightmap& level, double texel_x_m, double texel_z_m, double height_scale_m);
// The tile (tx, tz) of a level held in memory, with min/max; error_m is left 0.
CacheTile cutTile(const Heightmap& level, const std::vector<std::int8_t>& normals, int tile, int tx, int tz,
                  const TerrainMapping& mapping);

// Writes the cache of map (its mapping, its input's key) to file atomically (config/file_io.h);
// force: replace a file there. progress(done, total) after each tile. "" on success, else why.
std::string buildTileCache(const Heightmap& map, const TerrainMapping& mapping, const TileCacheKey& key, int tile,
                           const std::filesystem::path& file, bool force,
                           const std::function<void(int, int)>& progress = {});
// Level-0 row z of a map into row (width samples); asked for z = 0, 1, ... once each, in order.
// "" on success, else why (which stops the build and is returned).
using TileCacheRows = std::function<std::string(int z, float* row)>;
// The same from a map read a row at a time: the map is never held (each level keeps about
// 2 * tile + 3 of its rows), so a map larger than memory can be cached. The same file as above.
std::string buildTileCache(int width, int height, const TileCacheRows& rows, const TerrainMapping& mapping,
                           const TileCacheKey& key, int tile, const std::filesystem::path& file, bool force,
                           const std::function<void(int, int)>& progress = {});

class TileCache {
public:
    // Opens and checks a cache: header, index and end marker (not the tiles: read() checks
    // each). Null with why when it is missing, truncated, damaged or of another version.
    static std::unique_ptr<TileCache> open(const std::filesystem::path& file, std::string& why);
    ~TileCache();
    TileCache(const TileCache&) = delete;
    TileCache& operator=(const TileCache&) = delete;

    const TileCacheKey& key() const { return key_; }
    const TerrainMapping& mapping() const { return mapping_; }
    int tileSize() const { return tile_; }
    const std::vector<TileCacheLevel>& levels() const { return levels_; }
    // Reads one tile from the disk and checks its hash; false with why.
    bool read(int level, int tx, int tz, CacheTile& out, std::string& why) const;
    // The exact grid errors stored with the tiles: GridErrors of the map (terrain/lod_error.h)
    // with leaf cells of a tile, one level per cache level (the quadtree's levels when its leaves
    // are tiles), equal to those computed from the map in memory. Read from the disk and checked
    // against their hash; false with why.
    bool gridErrors(GridErrors& out, std::string& why) const;
    // Bytes held in memory: the index only.
    std::size_t memoryBytes() const;
    // The file this reader reads.
    const std::filesystem::path& file() const { return file_; }

    // One tile's place in the file and what the index keeps of it.
    struct Entry {
        std::uint64_t offset = 0, hash = 0;
        std::uint32_t width = 0, height = 0;
        float min_m = 0, max_m = 0, error_m = 0;
        std::uint32_t pad = 0;
    };
    // What the index keeps of tile (tx, tz) of a level (min/max, error, size), without reading it.
    const Entry& entry(int level, int tx, int tz) const { return entries_[index(level, tx, tz)]; }

private:
    TileCache() = default;
    std::size_t index(int level, int tx, int tz) const;

    std::filesystem::path file_;
    int fd_ = -1;
    TileCacheKey key_;
    TerrainMapping mapping_;
    int tile_ = 0;
    std::vector<TileCacheLevel> levels_;
    std::vector<std::size_t> first_;  // first entry of each level
    std::vector<Entry> entries_;
    std::uint64_t errors_offset_ = 0, errors_hash_ = 0;
};

// Heights of a cache's map at continuous level-0 texel coordinates, bilinear (as
// Heightmap::sample; clamped to the map), from level-0 tiles read on demand, the last 16 kept:
// a streamed terrain's heightAt and `vista check`'s ground, without the map in memory.
class TileCacheSampler {
public:
    explicit TileCacheSampler(const TileCache& cache) : cache_(cache) {}
    // The map's units (metres = offset + scale * sample); 0 where a tile cannot be read.
    double sample(double tx, double tz);
    std::size_t memoryBytes() const;

private:
    const TileCache& cache_;
    std::unordered_map<int, CacheTile> tiles_;
    std::deque<int> order_;
};

// The cache file of an input when none is named: next to it, "<input>.vtc".
std::filesystem::path defaultTileCachePath(const std::filesystem::path& input);

}  // namespace vista
