// The terrain tile cache (terrain/tile_cache.h): a round trip equals the pyramid built in
// memory, tile errors bound what each level misses of the full map, and a truncated, damaged
// or stale cache is found.
#include "../temp_dir.h"
#include "app/scene_check.h"
#include "app/terrain_cache_cmd.h"
#include "terrain/terrain.h"
#include "terrain/heightmap_rows.h"
#include "terrain/tile_cache.h"

#include <OpenImageIO/imageio.h>
#include <doctest/doctest.h>
#include <unistd.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>

using namespace vista;
namespace fs = std::filesystem;

namespace {

using test::TempDir;

// A small island: the generator the default scene's map comes from, at a non-2^n+1 size too.
Heightmap island(int size) {
    IslandParams p;
    p.size = size;
    p.seed = 7;
    p.octaves = 6;
    p.erosion_passes = 1;
    return generateIsland(p);
}

TerrainMapping mappingOf(const Heightmap& map) { return TerrainMapping{2000.0, 400.0, -50.0, map.width, map.height, 1500.0}; }

std::string build(const Heightmap& map, const fs::path& file, int tile, bool force = false) {
    TileCacheKey key{123, 456, 789};
    return buildTileCache(map, mappingOf(map), key, tile, file, force);
}

std::vector<char> fileBytes(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

TEST_CASE("tile cache: the pyramid's levels halve down to one tile") {
    std::vector<TileCacheLevel> l = tileCacheLevels(257, 129, 32);
    REQUIRE(l.size() == 4);
    CHECK(l[0].width == 257);
    CHECK(l[0].tiles_x == 8);
    CHECK(l[0].tiles_z == 4);
    CHECK(l[3].width == 33);
    CHECK(l[3].height == 17);
    CHECK(l[3].tiles_x == 1);
    // A size that is not 2^n + 1 keeps its last sample at every level.
    Heightmap m{6, 2, {0, 1, 2, 3, 4, 5, 10, 11, 12, 13, 14, 15}};
    Heightmap h = halveLevel(m);
    CHECK(h.width == 4);
    CHECK(h.samples == std::vector<float>{0, 2, 4, 5, 10, 12, 14, 15});
}

TEST_CASE("tile cache: a round trip equals the pyramid in memory, reading one tile at a time") {
    TempDir dir("roundtrip");
    // 130: the last two tile rows are ready with the same (last) map row.
    for (int size : {129, 130, 150}) {
        CAPTURE(size);
        const Heightmap map = island(size);
        const TerrainMapping mapping = mappingOf(map);
        const fs::path file = dir / ("map" + std::to_string(size) + ".vtc");
        REQUIRE(build(map, file, 32) == "");
        std::string why;
        auto cache = TileCache::open(file, why);
        REQUIRE_MESSAGE(cache, why);
        CHECK(cache->key() == TileCacheKey{123, 456, 789});
        CHECK(cache->mapping().sizeX() == 2000.0);
        CHECK(cache->mapping().sizeZ() == 1500.0);
        CHECK(cache->mapping().height_offset_m == -50.0);
        // The index is all a reader holds: far less than the map.
        CHECK(cache->memoryBytes() < map.samples.size() * sizeof(float) / 8);

        Heightmap level = map;
        for (std::size_t l = 0; l < cache->levels().size(); ++l) {
            const TileCacheLevel& info = cache->levels()[l];
            REQUIRE(level.width == info.width);
            const double step = double(1 << l);
            const auto normals = levelNormals(level, mapping.texelSizeX() * step, mapping.texelSizeZ() * step, mapping.height_scale_m);
            for (int tz = 0; tz < info.tiles_z; ++tz)
                for (int tx = 0; tx < info.tiles_x; ++tx) {
                    CacheTile disk;
                    REQUIRE_MESSAGE(cache->read(int(l), tx, tz, disk, why), why);
                    const CacheTile mem = cutTile(level, normals, 32, tx, tz, mapping);
                    CHECK(disk.width == mem.width);
                    CHECK(disk.height == mem.height);
                    CHECK(disk.heights == mem.heights);  // bit for bit
                    CHECK(disk.normals == mem.normals);
                    CHECK(disk.min_m == mem.min_m);
                    CHECK(disk.max_m == mem.max_m);
                    if (l == 0) CHECK(disk.error_m == 0.0f);
                    // The error bounds the full map against this level's bilinear surface over the tile.
                    double worst = 0.0;
                    const int x0 = tx * 32 << l, z0 = tz * 32 << l;
                    for (int z = z0; z <= std::min(z0 + (32 << l), map.height - 1); ++z)
                        for (int x = x0; x <= std::min(x0 + (32 << l), map.width - 1); ++x) {
                            // Level coordinates of the full map's sample; uniform spacing for 2^n + 1 sizes.
                            if (size != 129) continue;
                            const double u = double(x) / step, v = double(z) / step;
                            worst = std::max(worst, std::abs(double(map.at(x, z)) - level.sample(u, v)) * mapping.height_scale_m);
                        }
                    CHECK(double(disk.error_m) >= worst - 1e-3);
                }
            if (l + 1 < cache->levels().size()) level = halveLevel(level);
        }
        // The coarsest tile is the map's whole range.
        CacheTile top;
        REQUIRE(cache->read(int(cache->levels().size()) - 1, 0, 0, top, why));
        CHECK(top.error_m > 0.0f);
        CHECK_FALSE(cache->read(0, 99, 0, top, why));
        CHECK(why.find("does not exist") != std::string::npos);
    }
}

TEST_CASE("tile cache: the stored grid errors equal those computed from the map in memory, bit for bit") {
    TempDir dir("errors");
    // 2^n + 1, one more (a last interval of one sample at every level), a tile that is no power of 2.
    for (auto [size, tile] : {std::pair{129, 32}, {130, 32}, {150, 32}, {150, 12}, {33, 32}}) {
        CAPTURE(size);
        CAPTURE(tile);
        const Heightmap map = island(size);
        const fs::path file = dir / "map.vtc";
        REQUIRE(build(map, file, tile, true) == "");
        std::string why;
        auto cache = TileCache::open(file, why);
        REQUIRE_MESSAGE(cache, why);
        GridErrors stored;
        REQUIRE_MESSAGE(cache->gridErrors(stored, why), why);
        // The quadtree with leaves of a tile has one level per cache level.
        const MinMaxQuadtree tree(map, mappingOf(map), tile);
        REQUIRE(stored.levels() == tree.levels());
        REQUIRE(stored.levels() == int(cache->levels().size()));
        const GridErrors memory(map, mappingOf(map), tile, tree.levels());
        REQUIRE(stored.cells() == memory.cells());
        bool some = false;
        for (int l = 0; l < memory.levels(); ++l) {
            CHECK(stored.maxAt(l) == memory.maxAt(l));
            for (int z = 0; z < memory.cells().y; ++z)
                for (int x = 0; x < memory.cells().x; ++x) {
                    REQUIRE(stored.at(l, x, z) == memory.at(l, x, z));
                    some = some || memory.at(l, x, z) > 0.0f;
                }
        }
        CHECK(some == (memory.levels() > 1));  // one tile: level 0 only, no error
    }
}

TEST_CASE("tile cache: built from an image read a band of rows at a time, the same file as from the map in memory") {
    TempDir dir("rows");
    const Heightmap map = island(150);
    for (const std::string name : {"map.png", "map.tif"}) {
        CAPTURE(name);
        const fs::path image = dir / name;
        REQUIRE(saveHeightmapPng16(dir / "map.png", map).empty());
        if (name == "map.tif") {
            InputErrors errors;
            Heightmap png = loadHeightmap(dir / "map.png", 0, 0, errors);
            REQUIRE(saveHeightmapExr(dir / "map.exr", png).empty());  // float samples, as a TIFF keeps them
        }
        InputErrors errors;
        const Heightmap loaded = loadHeightmap(name == "map.png" ? image : dir / "map.exr", 0, 0, errors);
        REQUIRE(errors.empty());
        if (name == "map.tif") {
            // A float TIFF through OpenImageIO.
            auto out = OIIO::ImageOutput::create("tiff");
            REQUIRE(out);
            REQUIRE(out->open(image.string(), OIIO::ImageSpec(loaded.width, loaded.height, 1, OIIO::TypeDesc::FLOAT)));
            REQUIRE(out->write_image(OIIO::TypeDesc::FLOAT, loaded.samples.data()));
            REQUIRE(out->close());
        }
        std::string why;
        auto rows = HeightmapRows::open(image, why);
        REQUIRE_MESSAGE(rows, why);
        CHECK(rows->width() == 150);
        REQUIRE(build(loaded, dir / "memory.vtc", 32, true) == "");
        const TerrainMapping mapping = mappingOf(loaded);
        REQUIRE(buildTileCache(rows->width(), rows->height(), [&](int z, float* row) { return rows->read(z, row); }, mapping,
                               TileCacheKey{123, 456, 789}, 32, dir / "rows.vtc", true) == "");
        CHECK(fileBytes(dir / "memory.vtc") == fileBytes(dir / "rows.vtc"));
    }
    // A raw .r16 (little-endian uint16) a row at a time: loadHeightmap's samples, the same cache.
    {
        InputErrors errors;
        const Heightmap png = loadHeightmap(dir / "map.png", 0, 0, errors);
        std::vector<unsigned char> raw;
        for (float v : png.samples) {
            const unsigned q = unsigned(std::lround(v * 65535.0f));
            raw.push_back((unsigned char)(q & 0xff));
            raw.push_back((unsigned char)(q >> 8));
        }
        std::ofstream(dir / "map.r16", std::ios::binary).write(reinterpret_cast<const char*>(raw.data()), std::streamsize(raw.size()));
        const Heightmap whole = loadHeightmap(dir / "map.r16", 150, 150, errors);
        REQUIRE(errors.empty());
        std::string why;
        auto rows = HeightmapRows::open(dir / "map.r16", why, 150, 150);
        REQUIRE_MESSAGE(rows, why);
        std::vector<float> row(150);
        int differing = 0;
        for (int z = 0; z < 150; ++z) {
            REQUIRE(rows->read(z, row.data()) == "");
            for (int x = 0; x < 150; ++x) differing += row[std::size_t(x)] != whole.at(x, z);
        }
        CHECK(differing == 0);
        REQUIRE(build(whole, dir / "raw-memory.vtc", 32, true) == "");
        auto again = HeightmapRows::open(dir / "map.r16", why, 150, 150);
        REQUIRE(buildTileCache(150, 150, [&](int z, float* r) { return again->read(z, r); }, mappingOf(whole),
                               TileCacheKey{123, 456, 789}, 32, dir / "raw-rows.vtc", true) == "");
        CHECK(fileBytes(dir / "raw-memory.vtc") == fileBytes(dir / "raw-rows.vtc"));
        // A wrong size is left to loadHeightmap, which names it.
        CHECK_FALSE(HeightmapRows::open(dir / "map.r16", why, 150, 149));
        CHECK_FALSE(HeightmapRows::open(dir / "map.r16", why));
    }
    // What the rows cannot read is left to loadHeightmap: EXR (headers checked in memory), RGB.
    std::string why;
    CHECK_FALSE(HeightmapRows::open(dir / "map.exr", why));
    CHECK_FALSE(HeightmapRows::open(dir / "none.png", why));
    CHECK(why.find("none.png") != std::string::npos);
}

TEST_CASE("tile cache: a truncated, damaged or foreign cache is found, and an existing one kept without force") {
    TempDir dir("corrupt");
    const Heightmap map = island(65);
    const fs::path file = dir / "map.vtc";
    REQUIRE(build(map, file, 16) == "");
    CHECK(build(map, file, 16).find("already exists") != std::string::npos);  // not replaced without force
    REQUIRE(build(map, file, 16, true) == "");
    const auto size = fs::file_size(file);
    std::string bytes;
    {
        std::ifstream in(file, std::ios::binary);
        bytes.assign(std::istreambuf_iterator<char>(in), {});
    }
    auto write = [&](const std::string& name, const std::string& content) {
        std::ofstream(dir / name, std::ios::binary) << content;
        return dir / name;
    };
    std::string why;
    CHECK_FALSE(TileCache::open(write("cut.vtc", bytes.substr(0, size / 2)), why));
    CHECK(why.find("truncated") != std::string::npos);
    CHECK_FALSE(TileCache::open(write("short.vtc", bytes.substr(0, size - 1)), why));
    CHECK(why.find("truncated") != std::string::npos);
    CHECK_FALSE(TileCache::open(write("foreign.vtc", "PNG not a cache"), why));
    CHECK(why.find("not a vista tile cache") != std::string::npos);
    std::string header = bytes;
    header[60] ^= 0x40;  // inside the header's mapping
    CHECK_FALSE(TileCache::open(write("header.vtc", header), why));
    CHECK(why.find("fail their hash") != std::string::npos);
    // A cache of version 1 (per-tile error estimates only) is refused, naming both versions.
    std::string v1 = bytes;
    std::uint32_t version = 1;
    std::memcpy(&v1[8], &version, sizeof version);
    CHECK_FALSE(TileCache::open(write("v1.vtc", v1), why));
    CHECK(why.find("of version 1; this vista reads version 2") != std::string::npos);
    // Damaged grid errors (just before the index, which follows the tiles) open, but are refused when read.
    auto good = TileCache::open(file, why);
    REQUIRE(good);
    const TileCache::Entry& last = good->entry(int(good->levels().size()) - 1, 0, 0);
    const std::size_t errors_at = std::size_t(last.offset) + std::size_t(last.width) * last.height * 8;  // heights, normals
    std::string errors = bytes;
    errors[errors_at + 2] ^= 0x10;
    auto damaged = TileCache::open(write("errors.vtc", errors), why);
    REQUIRE(damaged);
    GridErrors e;
    CHECK(good->gridErrors(e, why));
    CHECK_FALSE(damaged->gridErrors(e, why));
    CHECK(why.find("grid errors are damaged") != std::string::npos);
    // A damaged tile opens (the index is fine) but that tile is refused when read.
    std::string tile = bytes;
    tile[200] ^= 0x01;
    auto cache = TileCache::open(write("tile.vtc", tile), why);
    REQUIRE(cache);
    CacheTile t;
    CHECK_FALSE(cache->read(0, 0, 0, t, why));
    CHECK(why.find("tile (0, 0, 0) is damaged") != std::string::npos);
    CHECK(cache->read(0, 1, 0, t, why));
}

TEST_CASE("tile cache: the key follows the input's size, time and first bytes") {
    TempDir dir("key");
    const fs::path input = dir / "input.bin";
    std::ofstream(input) << "first version";
    TileCacheKey a, b, c;
    REQUIRE(tileCacheKey(input, a) == "");
    CHECK(a.size == 13);
    std::ofstream(input) << "other version";
    fs::last_write_time(input, fs::last_write_time(input) + std::chrono::seconds(5));
    REQUIRE(tileCacheKey(input, b) == "");
    CHECK(b.size == a.size);
    CHECK(b.header_hash != a.header_hash);
    CHECK_FALSE(a == b);
    REQUIRE(tileCacheKey(input, c) == "");
    CHECK(b == c);
    CHECK(tileCacheKey(dir / "missing.bin", c) != "");
    CHECK(defaultTileCachePath("data/dem/x.tif") == fs::path("data/dem/x.tif.vtc"));
}

TEST_CASE("tile cache: vista check reads a streamed terrain from its cache, or its input row by row, never whole") {
    TempDir dir("check");
    const Heightmap map = island(97);
    auto writeTiff = [](const fs::path& file, const Heightmap& m) {
        auto out = OIIO::ImageOutput::create("tiff");
        REQUIRE(out);
        REQUIRE(out->open(file.string(), OIIO::ImageSpec(m.width, m.height, 1, OIIO::TypeDesc::FLOAT)));
        REQUIRE(out->write_image(OIIO::TypeDesc::FLOAT, m.samples.data()));
        REQUIRE(out->close());
    };
    const fs::path tiff = dir / "map.tif", cache = dir / "map.tif.vtc";
    writeTiff(tiff, map);
    Settings s;
    s.terrain.heightmap = tiff.string();
    s.terrain.size_m = 2000.0f;
    s.terrain.height_scale_m = 400.0f;
    s.terrain.height_offset_m = -50.0f;
    s.terrain.origin = {100.0, 5.0, -40.0};
    s.terrain.grid = 32;
    s.terrain.stream.enabled = true;
    s.terrain.stream.cache.clear();  // next to the map
    s.grade.enabled = false;
    const std::int64_t whole = wholeHeightmapLoads();

    // No cache yet: the map is read through row by row, nothing is written, no ground.
    CheckedTerrain checked;
    CHECK(validateSceneInputs(s, &checked).empty());
    CHECK_FALSE(checked.ground);
    CHECK_FALSE(fs::exists(cache));
    CHECK(wholeHeightmapLoads() == whole);

    // With the cache: its ground, equal to the map's held whole.
    TerrainCacheOptions o;
    o.input = tiff;
    o.tile = 32;
    o.size_m = s.terrain.size_m;
    o.height_scale_m = s.terrain.height_scale_m;
    o.height_offset_m = s.terrain.height_offset_m;
    o.progress = false;
    REQUIRE(runTerrainCache(o) == 0);
    CHECK(validateSceneInputs(s, &checked).empty());
    REQUIRE(checked.ground);
    CHECK(wholeHeightmapLoads() == whole);
    const TerrainMapping mapping{2000.0, 400.0, -50.0, map.width, map.height};
    for (double x : {-900.0, -333.3, 0.0, 451.7, 1099.0, 5000.0})
        for (double z : {-1040.0, -12.5, 230.2, 959.9, -7000.0}) {
            CAPTURE(x);
            CAPTURE(z);
            CHECK(checked.ground(x, z) == doctest::Approx(terrainHeightAt(map, mapping, s.terrain.origin, x, z)).epsilon(1e-6));  // Heightmap::sample is in float
        }

    // A bad row is found as loading would find it (naming the texel), and no cache is written.
    Heightmap spike = map;
    spike.samples[std::size_t(40 * 97 + 9)] = 1e6f;
    const fs::path bad = dir / "spike.tif";
    writeTiff(bad, spike);
    s.terrain.heightmap = bad.string();
    const InputErrors errors = validateSceneInputs(s, &checked);
    REQUIRE(errors.size() == 1);
    CHECK(errors[0].file == bad.string());
    CHECK(errors[0].message.find("at texel (9, 40) is outside the accepted") != std::string::npos);
    CHECK_FALSE(fs::exists(dir / "spike.tif.vtc"));
    CHECK(wholeHeightmapLoads() == whole);
}
