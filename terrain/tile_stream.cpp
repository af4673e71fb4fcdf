// Terrain streaming: the page pool, page table, worker threads and LRU (terrain/tile_stream.h).
#include "terrain/tile_stream.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

namespace vista {

double missingTileErrorPx(double error_m, double error_scale, double distance_m, double near_m) {
    const double d = std::max({distance_m, near_m, 1e-3});
    return error_m * error_scale / d;
}
namespace {

std::atomic<int> g_read_delay_ms{0};

float below(float v) { return std::nextafter(v, -std::numeric_limits<float>::infinity()); }
float above(float v) { return std::nextafter(v, std::numeric_limits<float>::infinity()); }

}  // namespace

void TileStream::setReadDelayForTests(int ms) { g_read_delay_ms = std::max(ms, 0); }

std::unique_ptr<TileStream> TileStream::open(std::unique_ptr<TileCache> cache, int pool_pages, int threads,
                                             std::string& why) {
    std::unique_ptr<TileStream> s(new TileStream);
    const std::vector<TileCacheLevel>& levels = cache->levels();
    if (int(levels.size()) > 32) {
        why = cache->file().string() + ": a tile cache of more than 32 levels cannot be streamed";
        return nullptr;
    }
    s->tile_ = cache->tileSize();
    int total = 0;
    for (const TileCacheLevel& l : levels) {
        s->first_.push_back(total);
        total += l.tiles_x * l.tiles_z;
    }
    // The coarsest levels stay resident: from the top down while they take at most a quarter of
    // the pool (the top level always).
    int pinned_levels = 0, pinned_tiles = 0;
    for (int l = int(levels.size()) - 1; l >= 0; --l) {
        const int n = levels[std::size_t(l)].tiles_x * levels[std::size_t(l)].tiles_z;
        if (pinned_levels > 0 && pinned_tiles + n > pool_pages / 4) break;
        pinned_tiles += n;
        ++pinned_levels;
    }
    if (pinned_tiles + 1 > pool_pages) {
        why = cache->file().string() + ": [terrain.stream] pool_pages = " + std::to_string(pool_pages) +
              " cannot hold the coarsest level and one more tile; accepted: at least " + std::to_string(pinned_tiles + 1);
        return nullptr;
    }
    s->cache_ = std::move(cache);
    s->sampler_ = std::make_unique<TileCacheSampler>(*s->cache_);
    s->page_of_.assign(std::size_t(total), -1);
    s->level_of_page_.assign(std::size_t(pool_pages), -1);
    s->tile_of_page_.assign(std::size_t(pool_pages), -1);
    s->stamp_.assign(std::size_t(pool_pages), 0);
    s->pinned_.assign(std::size_t(pool_pages), 0);
    for (int p = pool_pages - 1; p >= 0; --p) s->free_.push_back(p);

    const int side = s->tile_ + 1;
    auto makeArray = [&](GLenum format, const char* name) {
        GLuint id = 0;
        glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &id);
        glTextureStorage3D(id, 1, format, side, side, pool_pages);
        glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTextureParameteri(id, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTextureParameteri(id, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        glObjectLabel(GL_TEXTURE, id, -1, name);
        return gl::Texture::adopt(id, side, side, format);
    };
    s->heights_ = makeArray(GL_R32F, "terrain stream height pages");
    s->normals_ = makeArray(GL_RGBA8_SNORM, "terrain stream normal pages");
    std::vector<int> header(kStreamHeaderInts, 0);
    header[0] = int(levels.size());
    header[1] = s->tile_;
    header[2] = s->cache_->mapping().width;
    header[3] = s->cache_->mapping().height;
    for (std::size_t l = 0; l < levels.size(); ++l) {
        int* h = &header[4 + 8 * l];
        h[0] = s->first_[l];
        h[1] = levels[l].tiles_x;
        h[2] = levels[l].tiles_z;
        h[3] = levels[l].width;
        h[4] = levels[l].height;
    }
    s->table_ = gl::Buffer::create(GLsizeiptr((kStreamHeaderInts + std::size_t(total)) * sizeof(int)), nullptr,
                                   GL_DYNAMIC_STORAGE_BIT, "terrain stream page table");
    glNamedBufferSubData(s->table_.id(), 0, GLsizeiptr(header.size() * sizeof(int)), header.data());
    s->table_lo_ = 0;
    s->table_hi_ = total - 1;

    // The pinned levels, read here (coarse first, so every parent is in before its children).
    CacheTile t;
    for (int l = int(levels.size()) - 1; l >= int(levels.size()) - pinned_levels; --l)
        for (int tz = 0; tz < levels[std::size_t(l)].tiles_z; ++tz)
            for (int tx = 0; tx < levels[std::size_t(l)].tiles_x; ++tx) {
                if (!s->cache_->read(l, tx, tz, t, why)) return nullptr;
                const int id = s->tileId(l, tx, tz);
                s->upload(id, t);
                s->pinned_[std::size_t(s->page_of_[std::size_t(id)])] = 1;
            }
    s->counters_.loaded = 0;
    s->counters_.pool_pages = pool_pages;
    s->endFrame(0);  // the page table
    for (int i = 0; i < std::max(threads, 1); ++i) s->threads_.emplace_back([p = s.get()] { p->worker(); });
    return s;
}

TileStream::~TileStream() {
    {
        std::lock_guard lock(mutex_);
        stop_ = true;
    }
    cv_.notify_all();
    for (std::thread& t : threads_) t.join();
}

int TileStream::tileId(int level, int tx, int tz) const {
    return first_[std::size_t(level)] + tz * cache_->levels()[std::size_t(level)].tiles_x + tx;
}

int TileStream::parentId(int id) const {
    const int level = int(std::upper_bound(first_.begin(), first_.end(), id) - first_.begin()) - 1;
    if (level + 1 >= int(first_.size())) return -1;
    const int local = id - first_[std::size_t(level)];
    const int tiles_x = cache_->levels()[std::size_t(level)].tiles_x;
    const TileCacheLevel& up = cache_->levels()[std::size_t(level) + 1];
    return tileId(level + 1, std::min((local % tiles_x) / 2, up.tiles_x - 1), std::min((local / tiles_x) / 2, up.tiles_z - 1));
}

MinMaxQuadtree TileStream::quadtree() const {
    const TileCacheLevel& l0 = cache_->levels()[0];
    std::vector<glm::vec2> leaves(std::size_t(l0.tiles_x) * std::size_t(l0.tiles_z));
    for (int tz = 0; tz < l0.tiles_z; ++tz)
        for (int tx = 0; tx < l0.tiles_x; ++tx) {
            const TileCache::Entry& e = cache_->entry(0, tx, tz);
            // One float step outward: the cache rounded the metres to the nearest float.
            leaves[std::size_t(tz) * std::size_t(l0.tiles_x) + std::size_t(tx)] = {below(e.min_m), above(e.max_m)};
        }
    return MinMaxQuadtree(cache_->mapping(), tile_, std::move(leaves));
}

void TileStream::touch(int id) {
    for (; id >= 0; id = parentId(id)) {
        const int page = page_of_[std::size_t(id)];
        if (page < 0 || stamp_[std::size_t(page)] == frame_) return;  // its ancestors too, then
        stamp_[std::size_t(page)] = frame_;
    }
}

void TileStream::beginFrame() {
    ++frame_;
    wanted_.clear();
    wanted_set_.clear();
    counters_.requested = counters_.loaded = counters_.evicted = counters_.missing = 0;
    counters_.missing_error_px = 0.0;
}

void TileStream::want(int level, int tx, int tz) {
    const int id = tileId(level, tx, tz);
    if (page_of_[std::size_t(id)] >= 0) {
        touch(id);
        return;
    }
    // Missing: it and its missing ancestors are wanted, coarse first (a child needs its parent).
    for (int a = id; a >= 0 && page_of_[std::size_t(a)] < 0; a = parentId(a))
        if (wanted_set_.insert(a).second) wanted_.push_back(a);
    for (int a = parentId(id); a >= 0; a = parentId(a))
        if (page_of_[std::size_t(a)] >= 0) {
            touch(a);
            break;
        }
}

int TileStream::residentLevel(int level, int tx, int tz) const {
    int id = tileId(level, tx, tz);
    for (; page_of_[std::size_t(id)] < 0; ++level) id = parentId(id);
    return level;
}

bool TileStream::upload(int id, const CacheTile& t) {
    int page = -1;
    if (!free_.empty()) {
        page = free_.back();
        free_.pop_back();
    } else {
        // The least recently wanted page not wanted this frame, finer levels first on a tie: a
        // parent's stamp is never older than its children's, so children go first.
        std::uint64_t best = std::numeric_limits<std::uint64_t>::max();
        for (std::size_t p = 0; p < tile_of_page_.size(); ++p) {
            if (pinned_[p] || stamp_[p] >= frame_) continue;
            const std::uint64_t key = (std::uint64_t(stamp_[p]) << 8) | std::uint64_t(level_of_page_[p]);
            if (key < best) {
                best = key;
                page = int(p);
            }
        }
        if (page < 0) return false;
        const int old = tile_of_page_[std::size_t(page)];
        page_of_[std::size_t(old)] = -1;
        table_lo_ = std::min(table_lo_, old);
        table_hi_ = std::max(table_hi_, old);
        ++counters_.evicted;
    }
    // The tile's samples at the page's origin; a tile at the map's far edge is smaller (the
    // shader never reads past its samples).
    glTextureSubImage3D(heights_.id(), 0, 0, 0, page, t.width, t.height, 1, GL_RED, GL_FLOAT, t.heights.data());
    glTextureSubImage3D(normals_.id(), 0, 0, 0, page, t.width, t.height, 1, GL_RGBA, GL_BYTE, t.normals.data());
    const int level = int(std::upper_bound(first_.begin(), first_.end(), id) - first_.begin()) - 1;
    page_of_[std::size_t(id)] = page;
    tile_of_page_[std::size_t(page)] = id;
    level_of_page_[std::size_t(page)] = level;
    stamp_[std::size_t(page)] = frame_;
    table_lo_ = std::min(table_lo_, id);
    table_hi_ = std::max(table_hi_, id);
    ++counters_.loaded;
    return true;
}

void TileStream::endFrame(int max_uploads) {
    // Queue this frame's missing tiles (coarse first, then in the order wanted); drop what
    // earlier frames queued and this one does not want.
    std::vector<int> order = wanted_;
    auto level = [this](int id) { return int(std::upper_bound(first_.begin(), first_.end(), id) - first_.begin()); };
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return level(a) > level(b); });
    std::vector<Loaded> ready;
    {
        std::lock_guard lock(mutex_);
        for (int id : queue_) in_flight_.erase(id);
        queue_.clear();
        counters_.requested = 0;
        for (int id : order) {
            if (page_of_[std::size_t(id)] >= 0) continue;
            ++counters_.requested;
            if (in_flight_.insert(id).second) queue_.push_back(id);  // not already being read or read
        }
        for (Loaded& l : loaded_) in_flight_.erase(l.id);  // taken below
        ready.swap(loaded_);
    }
    cv_.notify_all();
    // Upload coarse first; a tile whose parent is not resident (it was evicted meanwhile) or
    // that no page can take waits for a later frame, unless nobody wants it any more.
    std::stable_sort(ready.begin(), ready.end(), [&](const Loaded& a, const Loaded& b) { return level(a.id) > level(b.id); });
    std::vector<Loaded> keep;
    int uploads = 0;
    for (Loaded& l : ready) {
        const int parent = parentId(l.id);
        const bool ready_to_go = page_of_[std::size_t(l.id)] < 0 && (parent < 0 || page_of_[std::size_t(parent)] >= 0);
        if (ready_to_go && uploads < max_uploads && upload(l.id, l.tile)) {
            ++uploads;
            touch(l.id);
        } else if (page_of_[std::size_t(l.id)] < 0 && wanted_set_.count(l.id)) {
            keep.push_back(std::move(l));
        }
    }
    if (!keep.empty()) {
        std::lock_guard lock(mutex_);
        for (Loaded& l : keep) {
            in_flight_.insert(l.id);
            loaded_.push_back(std::move(l));
        }
    }
    if (table_hi_ >= table_lo_) {
        glNamedBufferSubData(table_.id(), GLintptr((kStreamHeaderInts + std::size_t(table_lo_)) * sizeof(int)),
                             GLsizeiptr(std::size_t(table_hi_ - table_lo_ + 1) * sizeof(int)), &page_of_[std::size_t(table_lo_)]);
        table_lo_ = std::numeric_limits<int>::max();
        table_hi_ = -1;
    }
    counters_.resident = std::int64_t(tile_of_page_.size() - free_.size());
}

void TileStream::settle() {
    for (int round = 0; round < 1000; ++round) {
        {
            std::unique_lock lock(mutex_);
            done_cv_.wait(lock, [&] { return queue_.empty() && in_flight_.size() == loaded_.size(); });
        }
        const std::int64_t before = counters_.resident;
        std::vector<int> wanted = wanted_;
        endFrame(std::numeric_limits<int>::max());
        bool all = true;
        for (int id : wanted) all = all && page_of_[std::size_t(id)] >= 0;
        std::lock_guard lock(mutex_);
        if (all || (queue_.empty() && loaded_.empty() && counters_.resident == before)) return;
    }
}

void TileStream::worker() {
    CacheTile t;
    std::string why;
    for (;;) {
        int id = -1;
        {
            std::unique_lock lock(mutex_);
            cv_.wait(lock, [&] { return stop_ || !queue_.empty(); });
            if (stop_) return;
            id = queue_.front();
            queue_.pop_front();
        }
        if (int ms = g_read_delay_ms.load(); ms > 0) std::this_thread::sleep_for(std::chrono::milliseconds(ms));
        const int level = int(std::upper_bound(first_.begin(), first_.end(), id) - first_.begin()) - 1;
        const int local = id - first_[std::size_t(level)];
        const int tiles_x = cache_->levels()[std::size_t(level)].tiles_x;
        const bool ok = cache_->read(level, local % tiles_x, local / tiles_x, t, why);
        {
            std::lock_guard lock(mutex_);
            if (ok)
                loaded_.push_back({id, t});
            else
                in_flight_.erase(id);  // a damaged tile stays drawn from its ancestor
        }
        done_cv_.notify_all();
    }
}

double TileStream::sample(double tx, double tz) const { return sampler_->sample(tx, tz); }

std::string TileStream::checkConsistency() const {
    for (std::size_t p = 0; p < tile_of_page_.size(); ++p) {
        const int id = tile_of_page_[p];
        if (id < 0) continue;
        if (page_of_[std::size_t(id)] != int(p)) return "page " + std::to_string(p) + " and tile " + std::to_string(id) + " disagree";
        const int parent = parentId(id);
        if (parent >= 0 && page_of_[std::size_t(parent)] < 0)
            return "tile " + std::to_string(id) + " is resident without its parent " + std::to_string(parent);
    }
    std::size_t resident = 0;
    for (int page : page_of_) resident += page >= 0;
    if (resident != tile_of_page_.size() - free_.size()) return "resident tiles and used pages differ";
    std::vector<int> gpu(page_of_.size());
    glGetNamedBufferSubData(table_.id(), GLintptr(kStreamHeaderInts * sizeof(int)), GLsizeiptr(gpu.size() * sizeof(int)), gpu.data());
    for (std::size_t i = 0; i < gpu.size(); ++i)
        if (gpu[i] != page_of_[i])
            return "the GPU's page table has " + std::to_string(gpu[i]) + " for tile " + std::to_string(i) + ", the CPU's " +
                   std::to_string(page_of_[i]);
    return {};
}

std::size_t TileStream::memoryBytes() const {
    std::size_t bytes = cache_->memoryBytes() + page_of_.capacity() * sizeof(int) +
                        tile_of_page_.size() * (3 * sizeof(int) + sizeof(std::uint32_t) + 1);
    bytes += sampler_->memoryBytes();
    return bytes + gpuMemoryBytes();  // the GL's copies live in host memory on llvmpipe; counted once here
}

std::size_t TileStream::gpuMemoryBytes() const { return heights_.bytes() + normals_.bytes() + std::size_t(table_.size()); }

}  // namespace vista
