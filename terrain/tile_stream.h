// Terrain streaming ([terrain.stream], docs/dem.md): the renderer draws from a tile cache
// (terrain/tile_cache.h) without the map in memory. What stays resident on the CPU: the cache's
// index, the min/max quadtree (built from the index) and the grid errors (stored in the cache):
// a few bytes per leaf node; a handful of level-0 tiles for heightAt(). On the GPU: a fixed pool
// of pages (a texture array of heights, one of normals; one page per cache tile) and a page table
// (one int per cache tile of every level: its page or -1), which the TERRAIN_STREAM variant of the
// terrain shaders reads (terrain/shaders/tiles.glsl streamSample()).
//
// Residency is hierarchical: a tile is uploaded only when its parent is resident, and a parent
// is evicted only after its children (every use of a tile also stamps its ancestors, and ties
// go to the finer level). The coarsest levels are loaded when the stream opens and never
// evicted. A point's height is then the finest resident level's at or above the one asked for:
// a node whose tile is missing draws at its finest resident ancestor's level (never a hole,
// never a wait), and neighbours agree on shared vertices (the choice depends on the point and
// the residency only).
//
// Loads run on worker threads (pread + hash check); the render thread uploads at most
// uploads_per_frame finished tiles per frame, coarse first, and evicts the least recently used.
#pragma once

#include "renderer/gl/objects.h"
#include "terrain/cdlod.h"
#include "terrain/lod_error.h"
#include "terrain/tile_cache.h"

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace vista {

struct StreamCounters {
    std::int64_t resident = 0;   // pages holding a tile
    std::int64_t requested = 0;  // tiles the frame wanted that were not resident (queued for loading)
    std::int64_t loaded = 0;     // tiles uploaded this frame
    std::int64_t evicted = 0;    // tiles evicted this frame
    std::int64_t missing = 0;    // selected nodes drawn from a coarser ancestor this frame
    double missing_error_px = 0.0;  // largest screen error (px) a missing tile adds (its ancestor's grid error)
    std::int64_t pool_pages = 0;
};

// The screen error (px) a node drawn from a coarser tile adds: that tile's grid error (m) over
// the distance to the node's nearest point, error_scale px per (m / m). The distance is at least
// near_m (nothing nearer than the near plane is drawn), so the node the camera stands in gives a
// finite bound rather than a division by ~0.
double missingTileErrorPx(double error_m, double error_scale, double distance_m, double near_m);

// The page table's header (ints before the table, terrain/shaders/tiles.glsl): levels, tile,
// map width, height; then per level (at 4 + 8 l) first entry, tiles x, z, level width, height.
inline constexpr int kStreamHeaderInts = 4 + 8 * 32;

class TileStream {
public:
    // Opens the stream over cache with pool_pages pages (at least what the coarsest levels need:
    // they are loaded here), threads workers; null with why. Needs a current GL context.
    static std::unique_ptr<TileStream> open(std::unique_ptr<TileCache> cache, int pool_pages, int threads,
                                            std::string& why);
    ~TileStream();
    TileStream(const TileStream&) = delete;
    TileStream& operator=(const TileStream&) = delete;

    const TileCache& cache() const { return *cache_; }
    // The min/max quadtree with leaves of the cache's tile size (the [terrain] grid), from the index.
    MinMaxQuadtree quadtree() const;

    // Per frame: beginFrame(), then want() the tiles the selection draws (most wanted first;
    // prefetch after), then endFrame() uploads and evicts.
    void beginFrame();
    void want(int level, int tx, int tz);
    // Whether (level, tx, tz) is resident, else the level that covers it (the finest resident
    // ancestor's level).
    int residentLevel(int level, int tx, int tz) const;
    void endFrame(int max_uploads);
    // Tests: waits until every tile wanted this frame is loaded, uploading all (or the pool is full).
    void settle();

    GLuint heightPages() const { return heights_.id(); }
    GLuint normalPages() const { return normals_.id(); }
    GLuint pageTable() const { return table_.id(); }
    StreamCounters& counters() { return counters_; }
    const StreamCounters& counters() const { return counters_; }
    std::size_t memoryBytes() const;
    std::size_t gpuMemoryBytes() const;

    // Height sample (the map's units, as Heightmap::sample) at continuous level-0 texel
    // coordinates, bilinear, from level-0 tiles read on demand (a few kept).
    double sample(double tx, double tz) const;

    // Tests: "" when the pool is consistent (every resident tile's parent resident, pages and
    // tiles one to one, the GPU's page table equal to the CPU's), else what is wrong.
    std::string checkConsistency() const;

    // Test hook: every tile read waits this long first (an artificially slow disk).
    static void setReadDelayForTests(int ms);

private:
    TileStream() = default;
    int tileId(int level, int tx, int tz) const;
    void worker();
    bool upload(int id, const CacheTile& t);  // false when no page is free
    int parentId(int id) const;
    void touch(int id);

    struct Loaded {
        int id;
        CacheTile tile;
    };

    std::unique_ptr<TileCache> cache_;
    int tile_ = 0;
    std::vector<int> first_;  // first tile id per level
    std::vector<int> page_of_;           // per tile: its page or -1
    std::vector<int> level_of_page_;     // per page: level of its tile (-1 free)
    std::vector<int> tile_of_page_;      // per page: tile id (-1 free)
    std::vector<std::uint32_t> stamp_;   // per page: last frame its tile was wanted
    std::vector<char> pinned_;           // per page: a coarsest-level tile (never evicted)
    std::vector<int> free_;              // free pages
    std::uint32_t frame_ = 1;
    std::vector<int> wanted_;            // this frame's missing tiles, in order
    std::unordered_set<int> wanted_set_;
    int table_lo_ = 0, table_hi_ = -1;   // dirty page-table range (tile ids)

    gl::Texture heights_, normals_;
    gl::Buffer table_;
    StreamCounters counters_;

    // Worker side.
    std::mutex mutex_;
    std::condition_variable cv_, done_cv_;
    std::deque<int> queue_;                 // tiles to read, most wanted first
    std::unordered_set<int> in_flight_;     // queued or being read
    std::vector<Loaded> loaded_;            // read, not yet uploaded
    std::vector<std::thread> threads_;
    bool stop_ = false;

    // heightAt's level-0 tiles (render thread only).
    std::unique_ptr<TileCacheSampler> sampler_;  // made with cache_
};

}  // namespace vista
