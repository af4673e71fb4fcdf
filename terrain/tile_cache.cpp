// Tile cache: the pyramid's maths (halving, normals, per-tile min/max and error), the file
// writer (the map's rows streamed through every level's band of rows into an AtomicWriter: never
// the map in memory) and the reader
// (index in memory, tiles read with pread and checked one by one).
//
// File layout, little-endian as the machine writes it (the key has the input's mtime, so a
// cache is never carried between machines anyway):
//   Header  magic "VTCACHE1", version, tile, key, width, height, level count, mapping
//   Tiles   per tile: heights (float), normals (RGBA8 snorm), in the order the writer makes
//           them (a tile row of a level as soon as its rows are in: the levels interleave)
//   Errors  the exact grid errors (terrain/lod_error.h GridErrors; m), leaf cells of a tile:
//           per cell row (level-0 tile row), levels 1.. in order, a float per cell (version 2)
//   Index   one Entry per tile: offset, hash, size, min/max, error
//   Trailer index offset, FNV-1a of header + index, FNV-1a of the errors, end marker "VTCEND01"
#include "terrain/tile_cache.h"

#include "config/file_io.h"
#include "terrain/lod_error.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <deque>
#include <limits>
#include <thread>

namespace vista {
namespace {

constexpr char kMagic[8] = {'V', 'T', 'C', 'A', 'C', 'H', 'E', '1'};
constexpr char kEnd[8] = {'V', 'T', 'C', 'E', 'N', 'D', '0', '1'};
constexpr std::uint32_t kVersion = 2;  // 2: the exact grid errors
constexpr std::size_t kKeyBytes = 64 << 10;  // bytes of the input hashed into its key

struct Header {
    char magic[8];
    std::uint32_t version, tile;
    TileCacheKey key;
    std::int32_t width, height, levels, pad;
    double size_x, size_z, height_scale, height_offset;
};

struct Trailer {
    std::uint64_t index_offset, hash, errors_hash;
    char end[8];
};

std::uint64_t fnv1a(const void* data, std::size_t size, std::uint64_t hash = 0xcbf29ce484222325ull) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) hash = (hash ^ p[i]) * 0x100000001b3ull;
    return hash;
}

std::int8_t snorm8(double v) { return std::int8_t(std::lround(std::clamp(v, -1.0, 1.0) * 127.0)); }

// Position in level-l samples of level-(l + 1) sample i: every other one, the last one kept.
int parentPosition(int i, int width) { return std::min(2 * i, width - 1); }

// Height of level-l sample x (one axis) from the coarser level: linear between the coarser
// samples around it. Returns the fraction and the coarser indices.
void around(int x, int coarse_width, int width, int& i0, int& i1, double& f) {
    i0 = std::min(x / 2, coarse_width - 1);
    if (parentPosition(i0, width) > x) --i0;
    i1 = std::min(i0 + 1, coarse_width - 1);
    const int p0 = parentPosition(i0, width), p1 = parentPosition(i1, width);
    f = p1 > p0 ? double(x - p0) / double(p1 - p0) : 0.0;
}

// Largest |fine - coarse interpolated| (in sample units) over the fine samples of coarse tile
// (tx, tz): those between its first and last coarse samples, borders included (shared). Level
// is a Heightmap or a Band (at(x, z), width, height).
template <class Level>
float tileError(const Level& fine, const Level& coarse, int tile, int tx, int tz) {
    const int x_end = parentPosition(std::min(tx * tile + tile, coarse.width - 1), fine.width);
    const int z_end = parentPosition(std::min(tz * tile + tile, coarse.height - 1), fine.height);
    float worst = 0.0f;
    for (int z = parentPosition(tz * tile, fine.height); z <= z_end; ++z) {
        int z0, z1;
        double fz;
        around(z, coarse.height, fine.height, z0, z1, fz);
        for (int x = parentPosition(tx * tile, fine.width); x <= x_end; ++x) {
            int x0, x1;
            double fx;
            around(x, coarse.width, fine.width, x0, x1, fx);
            const double top = coarse.at(x0, z0) + (coarse.at(x1, z0) - coarse.at(x0, z0)) * fx;
            const double bottom = coarse.at(x0, z1) + (coarse.at(x1, z1) - coarse.at(x0, z1)) * fx;
            worst = std::max(worst, float(std::abs(double(fine.at(x, z)) - (top + (bottom - top) * fz))));
        }
    }
    return worst;
}

// The normal of sample (x, z) (central differences, one-sided at the edges) as RGBA8 snorm.
template <class Level>
void normalAt(const Level& level, int x, int z, double texel_x_m, double texel_z_m, double height_scale_m, std::int8_t* n) {
    const int xl = std::max(x - 1, 0), xr = std::min(x + 1, level.width - 1);
    const int zu = std::max(z - 1, 0), zd = std::min(z + 1, level.height - 1);
    const double dx = (double(level.at(xr, z)) - level.at(xl, z)) * height_scale_m / (double(xr - xl) * texel_x_m);
    const double dz = (double(level.at(x, zd)) - level.at(x, zu)) * height_scale_m / (double(zd - zu) * texel_z_m);
    const double len = std::sqrt(dx * dx + 1.0 + dz * dz);
    n[0] = snorm8(-dx / len);
    n[1] = snorm8(1.0 / len);
    n[2] = snorm8(-dz / len);
    n[3] = 0;
}

// Tile (tx, tz) of a level: its samples, normal(x, z, out) of each, min/max (m).
template <class Level, class Normal>
CacheTile cut(const Level& level, const Normal& normal, int tile, int tx, int tz, const TerrainMapping& mapping) {
    CacheTile t;
    const int x0 = tx * tile, z0 = tz * tile;
    t.width = std::min(tile + 1, level.width - x0);
    t.height = std::min(tile + 1, level.height - z0);
    t.heights.resize(std::size_t(t.width) * std::size_t(t.height));
    t.normals.resize(t.heights.size() * 4);
    float lo = level.at(x0, z0), hi = lo;
    for (int z = 0; z < t.height; ++z)
        for (int x = 0; x < t.width; ++x) {
            const std::size_t to = std::size_t(z) * std::size_t(t.width) + std::size_t(x);
            t.heights[to] = level.at(x0 + x, z0 + z);
            normal(x0 + x, z0 + z, &t.normals[to * 4]);
            lo = std::min(lo, t.heights[to]);
            hi = std::max(hi, t.heights[to]);
        }
    const double a = mapping.height_offset_m + mapping.height_scale_m * double(lo);
    const double b = mapping.height_offset_m + mapping.height_scale_m * double(hi);
    t.min_m = float(std::min(a, b));
    t.max_m = float(std::max(a, b));
    return t;
}

// The rows of one level the writer still needs: [first, first + rows.size()).
struct Band {
    int width = 0, height = 0;
    int first = 0;
    int next_tile_row = 0;  // tile rows before it are written
    std::deque<std::vector<float>> rows;
    float at(int x, int z) const { return rows[std::size_t(z - first)][std::size_t(x)]; }
    int end() const { return first + int(rows.size()); }
    void dropBefore(int z) {
        for (; first < z && !rows.empty(); ++first) rows.pop_front();
    }
};

// One level's tile row read back from the file being written: its rows (heights only).
struct TileRowBack {
    int tz = -1, first = 0, width = 0;
    std::vector<float> rows, tile_heights;
    const float* row(int r) const { return &rows[std::size_t(r - first) * std::size_t(width)]; }

    // Reads tile row tz of a level (entries: the level's index) unless it is the one held; false
    // when a read fails.
    bool read(int fd, const std::vector<TileCache::Entry>& entries, const TileCacheLevel& level, int tile, int row_tz) {
        if (row_tz == tz) return true;
        tz = row_tz;
        first = tz * tile;
        width = level.width;
        const int count = std::min(tile + 1, level.height - first);
        rows.resize(std::size_t(count) * std::size_t(width));
        for (int tx = 0; tx < level.tiles_x; ++tx) {
            const TileCache::Entry& e = entries[std::size_t(tz) * std::size_t(level.tiles_x) + std::size_t(tx)];
            tile_heights.resize(std::size_t(e.width) * std::size_t(e.height));
            const ssize_t bytes = ssize_t(tile_heights.size() * sizeof(float));
            if (int(e.height) != count || ::pread(fd, tile_heights.data(), std::size_t(bytes), off_t(e.offset)) != bytes) {
                tz = -1;
                return false;
            }
            for (int z = 0; z < count; ++z)
                std::memcpy(&rows[std::size_t(z) * std::size_t(width) + std::size_t(tx) * std::size_t(tile)],
                            &tile_heights[std::size_t(z) * e.width], e.width * sizeof(float));
        }
        return true;
    }
};

// The exact grid errors (terrain/lod_error.h GridErrors, leaf cells of `tile` texels) of levels
// 1.., read back from the tiles just written (fd): per cell row, the map's rows under it (level-0
// tiles) against each level's grid rows around them (that level's tiles: level l's sample i is
// texel min(i * 2^l, size - 1), the grid's vertex). Levels split over the cores. emit(errors)
// per cell row in order: levels 1.. in order, cells.x floats each (m). "" or why.
std::string gridErrorsFromTiles(int fd, const std::vector<TileCacheLevel>& levels,
                                const std::vector<std::vector<TileCache::Entry>>& index, int tile, float scale,
                                const std::function<void(const std::vector<float>&)>& emit) {
    const TileCacheLevel& base = levels[0];
    const int nlevels = int(levels.size()), cells_x = base.tiles_x;
    std::vector<TileRowBack> back(levels.size());
    std::vector<float> errors(std::size_t(nlevels - 1) * std::size_t(cells_x));
    const unsigned threads = std::clamp(std::thread::hardware_concurrency(), 1u, 8u);
    std::vector<char> failed(threads);
    for (int cz = 0; cz < base.tiles_z; ++cz) {
        if (!back[0].read(fd, index[0], base, tile, cz)) return "cannot read back level 0 of the tiles just written";
        std::fill(errors.begin(), errors.end(), 0.0f);
        auto work = [&](unsigned t) {
            std::vector<float> scratch;
            for (int l = 1 + int(t); l < nlevels; l += int(threads)) {
                const int spacing = 1 << l;
                float* cells = &errors[std::size_t(l - 1) * std::size_t(cells_x)];
                for (int z = cz * tile; z <= std::min(cz * tile + tile, base.height - 1); ++z) {
                    const GridRowSpan span = gridRowSpan(z, base.height, spacing);
                    const int r = span.z0 / spacing;  // the grid rows are the level's rows r and r + 1
                    TileRowBack& grid = back[std::size_t(l)];
                    if (!grid.read(fd, index[std::size_t(l)], levels[std::size_t(l)], tile,
                                   std::min(r / tile, levels[std::size_t(l)].tiles_z - 1))) {
                        failed[t] = 1;
                        return;
                    }
                    gridRowErrors(back[0].row(z), grid.row(r), grid.row(r + 1), base.width, spacing, span.fz, tile, scratch,
                                  cells);
                }
                for (int cx = 0; cx < cells_x; ++cx) cells[cx] *= scale;
            }
        };
        std::vector<std::thread> pool;
        for (unsigned t = 1; t < threads; ++t) pool.emplace_back(work, t);
        work(0);
        for (std::thread& t : pool) t.join();
        if (std::find(failed.begin(), failed.end(), 1) != failed.end()) return "cannot read back the tiles just written";
        emit(errors);
    }
    return {};
}

}  // namespace

std::string tileCacheKey(const std::filesystem::path& input, TileCacheKey& key) {
    if (std::string why = checkInputFile(input, std::numeric_limits<std::uintmax_t>::max()); !why.empty()) return why;
    struct stat st {};
    if (::stat(input.c_str(), &st) != 0) return input.string() + ": cannot read (" + std::strerror(errno) + ")";
    key.size = std::uint64_t(st.st_size);
    key.mtime_ns = std::int64_t(st.st_mtim.tv_sec) * 1000000000 + st.st_mtim.tv_nsec;
    std::vector<char> head(std::min<std::size_t>(kKeyBytes, std::size_t(st.st_size)));
    int fd = ::open(input.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return input.string() + ": cannot read (" + std::strerror(errno) + ")";
    const ssize_t got = head.empty() ? 0 : ::pread(fd, head.data(), head.size(), 0);
    ::close(fd);
    if (got != ssize_t(head.size())) return input.string() + ": cannot read its first bytes";
    key.header_hash = fnv1a(head.data(), head.size());
    return {};
}

std::vector<TileCacheLevel> tileCacheLevels(int width, int height, int tile) {
    std::vector<TileCacheLevel> levels;
    for (int w = width, h = height;;) {
        TileCacheLevel l{w, h, std::max(1, (w - 2) / tile + 1), std::max(1, (h - 2) / tile + 1)};
        levels.push_back(l);
        if (w <= tile + 1 && h <= tile + 1) break;
        w = (w - 1 + 1) / 2 + 1;
        h = (h - 1 + 1) / 2 + 1;
    }
    return levels;
}

Heightmap halveLevel(const Heightmap& level) {
    Heightmap out;
    out.width = level.width / 2 + 1;
    out.height = level.height / 2 + 1;
    out.samples.resize(std::size_t(out.width) * std::size_t(out.height));
    for (int z = 0; z < out.height; ++z)
        for (int x = 0; x < out.width; ++x)
            out.samples[std::size_t(z) * std::size_t(out.width) + std::size_t(x)] =
                level.at(parentPosition(x, level.width), parentPosition(z, level.height));
    return out;
}

std::vector<std::int8_t> levelNormals(const Heightmap& level, double texel_x_m, double texel_z_m, double height_scale_m) {
    std::vector<std::int8_t> normals(level.samples.size() * 4);
    for (int z = 0; z < level.height; ++z)
        for (int x = 0; x < level.width; ++x)
            normalAt(level, x, z, texel_x_m, texel_z_m, height_scale_m,
                     &normals[(std::size_t(z) * std::size_t(level.width) + std::size_t(x)) * 4]);
    return normals;
}

CacheTile cutTile(const Heightmap& level, const std::vector<std::int8_t>& normals, int tile, int tx, int tz,
                  const TerrainMapping& mapping) {
    auto normal = [&](int x, int z, std::int8_t* n) {
        std::memcpy(n, &normals[(std::size_t(z) * std::size_t(level.width) + std::size_t(x)) * 4], 4);
    };
    return cut(level, normal, tile, tx, tz, mapping);
}

std::string buildTileCache(const Heightmap& map, const TerrainMapping& mapping, const TileCacheKey& key, int tile,
                           const std::filesystem::path& file, bool force, const std::function<void(int, int)>& progress) {
    if (map.width < 2 || map.height < 2 || map.samples.size() != std::size_t(map.width) * std::size_t(map.height))
        return file.string() + ": the map is empty or its size does not match its samples";
    auto rows = [&](int z, float* row) {
        std::memcpy(row, &map.samples[std::size_t(z) * std::size_t(map.width)], std::size_t(map.width) * sizeof(float));
        return std::string();
    };
    return buildTileCache(map.width, map.height, rows, mapping, key, tile, file, force, progress);
}

std::string buildTileCache(int width, int height, const TileCacheRows& rows, const TerrainMapping& mapping,
                           const TileCacheKey& key, int tile, const std::filesystem::path& file, bool force,
                           const std::function<void(int, int)>& progress) {
    if (tile < 2 || tile > 4096) return file.string() + ": tile size " + std::to_string(tile) + " is not accepted; accepted: 2..4096";
    if (width < 2 || height < 2) return file.string() + ": the map is empty";
    // Refused before any work when the file exists (without force) or its folder is missing.
    if (std::string why = checkOutputFile(file, force, "--out"); !why.empty()) return why;
    const std::vector<TileCacheLevel> levels = tileCacheLevels(width, height, tile);
    int total = 0;
    for (const auto& l : levels) total += l.tiles_x * l.tiles_z;

    AtomicWriter out(file, force);
    Header header{};
    std::memcpy(header.magic, kMagic, sizeof kMagic);
    header.version = kVersion;
    header.tile = std::uint32_t(tile);
    header.key = key;
    header.width = width;
    header.height = height;
    header.levels = std::int32_t(levels.size());
    header.size_x = mapping.sizeX();
    header.size_z = mapping.sizeZ();
    header.height_scale = mapping.height_scale_m;
    header.height_offset = mapping.height_offset_m;
    std::uint64_t offset = sizeof header;
    out.write(&header, sizeof header);

    // The map streams through: each level keeps the band of rows its next tile row needs (and
    // the next level's errors), and writes a tile row as soon as its rows are in, so the levels'
    // tiles interleave in the file (the index has their offsets). The grid errors in the index
    // get their finer tiles' errors added at the end.
    const std::size_t nlevels = levels.size();
    std::vector<std::vector<TileCache::Entry>> index(nlevels);
    std::vector<Band> bands(nlevels);
    for (std::size_t l = 0; l < nlevels; ++l) {
        index[l].resize(std::size_t(levels[l].tiles_x) * std::size_t(levels[l].tiles_z));
        bands[l].width = levels[l].width;
        bands[l].height = levels[l].height;
    }
    int done = 0;
    auto writeTileRow = [&](std::size_t l) {
        Band& band = bands[l];
        const TileCacheLevel& info = levels[l];
        const int tz = band.next_tile_row;
        const double step = double(std::int64_t(1) << l);
        const double tx_m = mapping.texelSizeX() * step, tz_m = mapping.texelSizeZ() * step;
        auto normal = [&](int x, int z, std::int8_t* n) { normalAt(band, x, z, tx_m, tz_m, mapping.height_scale_m, n); };
        for (int tx = 0; tx < info.tiles_x && out.ok(); ++tx) {
            CacheTile t = cut(band, normal, tile, tx, tz, mapping);
            TileCache::Entry& e = index[l][std::size_t(tz) * std::size_t(info.tiles_x) + std::size_t(tx)];
            e.offset = offset;
            e.width = std::uint32_t(t.width);
            e.height = std::uint32_t(t.height);
            e.min_m = t.min_m;
            e.max_m = t.max_m;
            // What this level misses of the finer one (the finer tiles' errors are added at the end).
            e.error_m = l == 0 ? 0.0f : float(double(tileError(bands[l - 1], band, tile, tx, tz)) * std::abs(mapping.height_scale_m));
            const std::size_t hb = t.heights.size() * sizeof(float), nb = t.normals.size();
            e.hash = fnv1a(t.normals.data(), nb, fnv1a(t.heights.data(), hb));
            out.write(t.heights.data(), hb);
            out.write(t.normals.data(), nb);
            offset += hb + nb;
            if (progress) progress(++done, total);
        }
        ++band.next_tile_row;
    };
    // Rows a level keeps: its next tile row's (and the row above, for normals), and the rows
    // under the next level's next tile row (its errors).
    auto trim = [&](std::size_t l) {
        int keep = bands[l].next_tile_row * tile - 1;
        if (l + 1 < nlevels) keep = std::min(keep, parentPosition(bands[l + 1].next_tile_row * tile, bands[l].height));
        bands[l].dropBefore(keep);
    };
    std::vector<float> row(static_cast<std::size_t>(width));
    std::vector<std::vector<float>> pending(nlevels);
    for (int z = 0; z < height && out.ok(); ++z) {
        if (std::string why = rows(z, row.data()); !why.empty()) return why;
        // The row enters level 0, and every coarser level that keeps it, finest first.
        pending[0] = row;
        std::size_t top = 0;
        for (std::size_t l = 0; l + 1 < nlevels; ++l) {
            const Band& fine = bands[l];
            if (bands[l + 1].end() >= bands[l + 1].height || parentPosition(bands[l + 1].end(), fine.height) != fine.end())
                break;  // not a row the next level keeps
            std::vector<float>& coarse = pending[l + 1];
            coarse.resize(std::size_t(bands[l + 1].width));
            for (int x = 0; x < bands[l + 1].width; ++x) coarse[std::size_t(x)] = pending[l][std::size_t(parentPosition(x, fine.width))];
            top = l + 1;
        }
        for (std::size_t l = 0; l <= top; ++l) {
            bands[l].rows.push_back(pending[l]);
            // A tile row needs its rows and the one below (normals); the last two may be ready at once.
            while (bands[l].next_tile_row < levels[l].tiles_z &&
                   bands[l].end() > std::min(bands[l].next_tile_row * tile + tile + 1, bands[l].height - 1))
                writeTileRow(l);
        }
        for (std::size_t l = 0; l < nlevels; ++l) trim(l);
    }

    for (std::size_t l = 0; l < nlevels && out.ok(); ++l)
        if (bands[l].next_tile_row != levels[l].tiles_z)
            return file.string() + ": level " + std::to_string(l) + " did not get all its rows (a bug)";
    for (std::size_t l = 1; l < nlevels; ++l) {
        // A tile's error: what its level misses of the finer one, plus the most its finer tiles miss.
        const TileCacheLevel &info = levels[l], &below = levels[l - 1];
        for (int tz = 0; tz < info.tiles_z; ++tz)
            for (int tx = 0; tx < info.tiles_x; ++tx) {
                float most = 0.0f;
                for (int cz = 2 * tz; cz <= std::min(2 * tz + 1, below.tiles_z - 1); ++cz)
                    for (int cx = 2 * tx; cx <= std::min(2 * tx + 1, below.tiles_x - 1); ++cx)
                        most = std::max(most, index[l - 1][std::size_t(cz) * std::size_t(below.tiles_x) + std::size_t(cx)].error_m);
                index[l][std::size_t(tz) * std::size_t(info.tiles_x) + std::size_t(tx)].error_m += most;
            }
    }
    // The exact grid errors, read back from the tiles (the map is not held), before the index.
    std::uint64_t errors_hash = fnv1a(nullptr, 0);
    if (out.ok()) {
        const int back = ::open(out.temporary().c_str(), O_RDONLY | O_CLOEXEC);
        if (back < 0) return file.string() + ": cannot read back " + out.temporary().string() + " (" + std::strerror(errno) + ")";
        std::string why = gridErrorsFromTiles(back, levels, index, tile, gridErrorScale(mapping), [&](const std::vector<float>& e) {
            const std::size_t bytes = e.size() * sizeof(float);
            out.write(e.data(), bytes);
            errors_hash = fnv1a(e.data(), bytes, errors_hash);
            offset += bytes;
        });
        ::close(back);
        if (!why.empty()) return file.string() + ": " + why;
    }
    std::uint64_t hash = fnv1a(&header, sizeof header);
    for (const auto& entries : index) {
        out.write(entries.data(), entries.size() * sizeof(TileCache::Entry));
        hash = fnv1a(entries.data(), entries.size() * sizeof(TileCache::Entry), hash);
    }
    Trailer trailer{offset, hash, errors_hash, {}};
    std::memcpy(trailer.end, kEnd, sizeof kEnd);
    out.write(&trailer, sizeof trailer);
    return out.commit();
}

std::unique_ptr<TileCache> TileCache::open(const std::filesystem::path& file, std::string& why) {
    if (why = checkInputFile(file, std::numeric_limits<std::uintmax_t>::max()); !why.empty()) return nullptr;
    std::unique_ptr<TileCache> c(new TileCache);
    c->file_ = file;
    c->fd_ = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
    const std::string name = file.string() + ": ";
    if (c->fd_ < 0) {
        why = name + "cannot read (" + std::strerror(errno) + ")";
        return nullptr;
    }
    struct stat st {};
    ::fstat(c->fd_, &st);
    const std::uint64_t size = std::uint64_t(st.st_size);
    Header header{};
    Trailer trailer{};
    auto readAt = [&](void* to, std::size_t bytes, std::uint64_t at) {
        return at + bytes <= size && ::pread(c->fd_, to, bytes, off_t(at)) == ssize_t(bytes);
    };
    if (!readAt(&header, sizeof header, 0) || std::memcmp(header.magic, kMagic, sizeof kMagic) != 0) {
        why = name + "is not a vista tile cache (no VTCACHE1 header)";
        return nullptr;
    }
    if (header.version != kVersion) {
        why = name + "is a tile cache of version " + std::to_string(header.version) + "; this vista reads version " +
              std::to_string(kVersion);
        return nullptr;
    }
    if (!readAt(&trailer, sizeof trailer, size - std::min<std::uint64_t>(size, sizeof trailer)) ||
        std::memcmp(trailer.end, kEnd, sizeof kEnd) != 0) {
        why = name + "is truncated (no end marker after " + std::to_string(size) + " bytes)";
        return nullptr;
    }
    if (header.tile < 2 || header.width < 2 || header.height < 2 || header.levels < 1 || header.levels > 64) {
        why = name + "has a damaged header";
        return nullptr;
    }
    c->tile_ = int(header.tile);
    c->levels_ = tileCacheLevels(header.width, header.height, c->tile_);
    std::size_t count = 0;
    for (const auto& l : c->levels_) {
        c->first_.push_back(count);
        count += std::size_t(l.tiles_x) * std::size_t(l.tiles_z);
    }
    const std::uint64_t index_bytes = std::uint64_t(count) * sizeof(Entry);
    if (int(c->levels_.size()) != header.levels || trailer.index_offset + index_bytes + sizeof trailer != size) {
        why = name + "is truncated or damaged (its index does not fit its " + std::to_string(size) + " bytes)";
        return nullptr;
    }
    const TileCacheLevel& base = c->levels_[0];
    const std::uint64_t errors_bytes =
        std::uint64_t(header.levels - 1) * std::uint64_t(base.tiles_x) * std::uint64_t(base.tiles_z) * sizeof(float);
    if (trailer.index_offset < sizeof header + errors_bytes) {
        why = name + "is truncated or damaged (its grid errors do not fit before its index)";
        return nullptr;
    }
    c->errors_offset_ = trailer.index_offset - errors_bytes;
    c->errors_hash_ = trailer.errors_hash;
    c->entries_.resize(count);
    if (!readAt(c->entries_.data(), index_bytes, trailer.index_offset) ||
        fnv1a(c->entries_.data(), index_bytes, fnv1a(&header, sizeof header)) != trailer.hash) {
        why = name + "is damaged (its header and index fail their hash)";
        return nullptr;
    }
    c->key_ = header.key;
    c->mapping_ = TerrainMapping{header.size_x, header.height_scale, header.height_offset, header.width, header.height,
                                 header.size_z};
    return c;
}

TileCache::~TileCache() {
    if (fd_ >= 0) ::close(fd_);
}

std::size_t TileCache::index(int level, int tx, int tz) const {
    return first_[std::size_t(level)] + std::size_t(tz) * std::size_t(levels_[std::size_t(level)].tiles_x) + std::size_t(tx);
}

bool TileCache::read(int level, int tx, int tz, CacheTile& out, std::string& why) const {
    const std::string where = file_.string() + ": tile (" + std::to_string(level) + ", " + std::to_string(tx) + ", " +
                              std::to_string(tz) + ")";
    if (level < 0 || level >= int(levels_.size()) || tx < 0 || tz < 0 || tx >= levels_[std::size_t(level)].tiles_x ||
        tz >= levels_[std::size_t(level)].tiles_z) {
        why = where + " does not exist";
        return false;
    }
    const Entry& e = entries_[index(level, tx, tz)];
    out.width = int(e.width);
    out.height = int(e.height);
    out.min_m = e.min_m;
    out.max_m = e.max_m;
    out.error_m = e.error_m;
    out.heights.resize(std::size_t(e.width) * std::size_t(e.height));
    out.normals.resize(out.heights.size() * 4);
    const std::size_t hb = out.heights.size() * sizeof(float), nb = out.normals.size();
    if (e.width > std::uint32_t(tile_ + 1) || e.height > std::uint32_t(tile_ + 1) ||
        ::pread(fd_, out.heights.data(), hb, off_t(e.offset)) != ssize_t(hb) ||
        ::pread(fd_, out.normals.data(), nb, off_t(e.offset + hb)) != ssize_t(nb) ||
        fnv1a(out.normals.data(), nb, fnv1a(out.heights.data(), hb)) != e.hash) {
        why = where + " is damaged (fails its hash); rebuild the cache with vista terrain-cache --force";
        return false;
    }
    return true;
}

bool TileCache::gridErrors(GridErrors& out, std::string& why) const {
    // Stored per cell row (levels 1.. each); GridErrors keeps them per level.
    const glm::ivec2 cells(levels_[0].tiles_x, levels_[0].tiles_z);
    const std::size_t per_level = std::size_t(cells.x) * std::size_t(cells.y);
    std::vector<std::vector<float>> levels(levels_.size(), std::vector<float>(per_level, 0.0f));
    std::vector<float> row(std::size_t(cells.x) * (levels_.size() - 1));
    const std::size_t bytes = row.size() * sizeof(float);
    std::uint64_t hash = fnv1a(nullptr, 0);
    for (int cz = 0; cz < cells.y && bytes > 0; ++cz) {
        if (::pread(fd_, row.data(), bytes, off_t(errors_offset_ + std::uint64_t(cz) * bytes)) != ssize_t(bytes)) {
            why = file_.string() + ": cannot read its grid errors (" + std::strerror(errno) + ")";
            return false;
        }
        hash = fnv1a(row.data(), bytes, hash);
        for (std::size_t l = 1; l < levels.size(); ++l)
            std::copy_n(&row[(l - 1) * std::size_t(cells.x)], cells.x, &levels[l][std::size_t(cz) * std::size_t(cells.x)]);
    }
    if (hash != errors_hash_) {
        why = file_.string() + ": its grid errors are damaged (fail their hash); rebuild the cache with vista terrain-cache --force";
        return false;
    }
    out = GridErrors(cells, std::move(levels));
    return true;
}

std::size_t TileCache::memoryBytes() const {
    return entries_.size() * sizeof(Entry) + first_.size() * sizeof(std::size_t) + levels_.size() * sizeof(TileCacheLevel);
}

std::filesystem::path defaultTileCachePath(const std::filesystem::path& input) {
    std::filesystem::path p = input;
    p += ".vtc";
    return p;
}

double TileCacheSampler::sample(double tx, double tz) {
    const TerrainMapping& m = cache_.mapping();
    tx = std::clamp(tx, 0.0, double(m.width - 1));
    tz = std::clamp(tz, 0.0, double(m.height - 1));
    const TileCacheLevel& l0 = cache_.levels()[0];
    const int x0 = std::min(int(tx), m.width - 2), z0 = std::min(int(tz), m.height - 2);
    const int cx = std::min(x0 / cache_.tileSize(), l0.tiles_x - 1), cz = std::min(z0 / cache_.tileSize(), l0.tiles_z - 1);
    const int id = cz * l0.tiles_x + cx;
    auto it = tiles_.find(id);
    if (it == tiles_.end()) {
        CacheTile t;
        std::string why;
        if (!cache_.read(0, cx, cz, t, why)) return 0.0;
        if (order_.size() >= 16) {
            tiles_.erase(order_.front());
            order_.pop_front();
        }
        order_.push_back(id);
        it = tiles_.emplace(id, std::move(t)).first;
    }
    const CacheTile& t = it->second;
    const int lx = x0 - cx * cache_.tileSize(), lz = z0 - cz * cache_.tileSize();
    auto at = [&](int x, int z) { return double(t.heights[std::size_t(z) * std::size_t(t.width) + std::size_t(x)]); };
    const double fx = tx - x0, fz = tz - z0;
    const double top = at(lx, lz) + (at(lx + 1, lz) - at(lx, lz)) * fx;
    const double bottom = at(lx, lz + 1) + (at(lx + 1, lz + 1) - at(lx, lz + 1)) * fx;
    return top + (bottom - top) * fz;
}

std::size_t TileCacheSampler::memoryBytes() const {
    std::size_t bytes = 0;
    for (const auto& [id, t] : tiles_) bytes += t.heights.capacity() * sizeof(float) + t.normals.capacity();
    return bytes;
}

}  // namespace vista
