// Terrain streaming ([terrain.stream], terrain/tile_stream.h): a 1025^2 island drawn from its tile
// cache (built on first load) through the GPU page pool. Once the tiles settle the image matches
// the in-memory terrain's; the first frame, drawn from the coarsest levels only, does not (so the
// comparison can fail) but has no hole. A slow disk (a test hook) never shows a hole along a fast
// flight; a tiny pool evicts and stays consistent (hierarchy, page table on the GPU). The grid
// errors stored in the cache are the in-memory ones, so both select the same nodes; a TIFF's
// cache is built on first load without holding the map, the same file the command writes.
#include "renderer_fixture.h"
#include "app/image_metrics.h"
#include "app/terrain_cache_cmd.h"
#include "terrain/dem.h"
#include "terrain/tile_cache.h"
#include "terrain/tile_stream.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>

using namespace vista;

namespace {

FrameRenderer& renderer() { return test::fileRenderer(); }

// The island at size² samples (1025 or 4097), made once per process.
const std::filesystem::path& islandFile(int size = 1025) {
    static test::TempDir dir("terrain-stream");
    static std::map<int, std::filesystem::path> files;
    auto [it, made] = files.try_emplace(size, dir.path / ("island" + std::to_string(size) + ".png"));
    if (made) REQUIRE(saveHeightmapPng16(it->second, generateIsland(IslandParams{size, 7})).empty());
    return it->second;
}

// The island size_m across (by default 4096 m: 4 m texels at 1025², 1 m at 4097²).
Settings islandScene(bool stream, int pool_pages = 2048, int size = 1025, float size_m = 4096.0f) {
    Settings s;
    test::terrainOnly(s);
    s.sky.enabled = false;  // uncovered pixels keep alpha 0: holes can be counted
    s.terrain.heightmap = islandFile(size).string();
    s.terrain.size_m = size_m;
    s.terrain.height_scale_m = 600.0f;
    s.terrain.stream.enabled = stream;
    s.terrain.stream.cache = (islandFile(size).parent_path() /
                              ("island" + std::to_string(size) + "-" + std::to_string(int(size_m)) + ".vtc")).string();
    s.terrain.stream.pool_pages = pool_pages;
    s.terrain.stream.prefetch_frames = 0;
    return s;
}

struct Frame {
    std::vector<float> rgba;
    int holes = 0;
    std::map<std::string, double> counters;
};

Frame render(const Settings& s, const ViewParams& view) {
    REQUIRE(renderer().prepare(s).empty());
    renderer().resetHistory();
    test::RenderedFrame r = test::renderFrame(renderer(), s, view);
    Frame f;
    f.rgba = std::move(r.rgba);
    for (std::size_t i = 3; i < f.rgba.size(); i += 4) f.holes += f.rgba[i] == 0.0f;
    f.counters = r.report.counters;
    return f;
}

// PSNR (dB) of b against a over RGB, the peak the reference's brightest channel.
double psnr(const Frame& a, const Frame& b) {
    double peak = 0.0, mse = 0.0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < a.rgba.size(); ++i)
        if (i % 4 != 3) {
            peak = std::max(peak, double(a.rgba[i]));
            mse += (double(a.rgba[i]) - double(b.rgba[i])) * (double(a.rgba[i]) - double(b.rgba[i]));
            ++n;
        }
    return psnrFromMse(mse / double(std::max<std::size_t>(n, 1)), std::max(peak, 1e-6));
}

std::string bytes(const std::filesystem::path& f) {
    std::ifstream in(f, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// Looking down at the island from 700 m: the map (sea floor included) fills the view.
ViewParams overview() { return ViewParams{{0.0, 700.0, 0.0}, 30.0, -60.0, 60.0, 0.5, 160, 90}; }

}  // namespace

TEST_CASE("gl: a streamed terrain matches the in-memory one once its tiles settle, and never shows a hole before") {
    // 1025² and 4097² (the size) at 4 m texels (the 65,537² target's), and 4097² at 1 m.
    for (auto [size, size_m] : {std::pair{1025, 4096.0f}, std::pair{4097, 16384.0f}, std::pair{4097, 4096.0f}}) {
        CAPTURE(size);
        CAPTURE(size_m);
        TileStream::setReadDelayForTests(0);
        const Frame memory = render(islandScene(false, 2048, size, size_m), overview());
        REQUIRE(memory.holes == 0);
        const MinMaxQuadtree tree = renderer().terrain()->quadtree();
        const GridErrors exact = renderer().terrain()->gridErrors();

        const Settings s = islandScene(true, 2048, size, size_m);
        const Frame first = render(s, overview());  // builds the cache, opens the pool: coarsest levels only
        Terrain* t = renderer().terrain();
        REQUIRE(t);
        REQUIRE(t->streamed());
        CHECK(t->heightmap().samples.empty());  // the map is not kept
        // The quadtree from the cache's index: the in-memory one's boxes, one float step wider at most.
        REQUIRE(t->quadtree().levels() == tree.levels());
        for (int l = 0; l < tree.levels(); ++l)
            for (int z = 0; z < tree.nodesPerSide(l).y; ++z)
                for (int x = 0; x < tree.nodesPerSide(l).x; ++x) {
                    const glm::vec2 a = tree.minMax(l, x, z), b = t->quadtree().minMax(l, x, z);
                    REQUIRE(b.x <= a.x);
                    REQUIRE(b.y >= a.y);
                    REQUIRE(a.x - b.x <= 1e-3f);
                    REQUIRE(b.y - a.y <= 1e-3f);
                }
        // The grid errors from the cache: the exact ones computed in memory, bit for bit, so the
        // selection picks the same nodes.
        const GridErrors& streamed = t->gridErrors();
        REQUIRE(streamed.levels() == exact.levels());
        REQUIRE(streamed.cells() == exact.cells());
        for (int l = 0; l < exact.levels(); ++l)
            for (int z = 0; z < exact.cells().y; ++z)
                for (int x = 0; x < exact.cells().x; ++x) REQUIRE(streamed.at(l, x, z) == exact.at(l, x, z));
        CHECK(first.counters.at("terrain.nodes") == memory.counters.at("terrain.nodes"));
        CHECK(first.holes == 0);
        CHECK(first.counters.at("terrain.stream.missing") > 0);

        t->stream()->settle();
        const Frame settled = render(s, overview());
        CHECK(settled.holes == 0);
        CHECK(settled.counters.at("terrain.nodes") == memory.counters.at("terrain.nodes"));
        CHECK(settled.counters.at("terrain.stream.missing") == 0);
        CHECK(settled.counters.at("terrain.stream.missing_error_px") == 0.0);
        CHECK(t->stream()->checkConsistency() == "");
        const double db_settled = psnr(memory, settled), db_first = psnr(memory, first);
        std::printf("stream %d², %g m texels: PSNR against in-memory: first frame %.1f dB, settled %.1f dB; missing %g -> %g nodes, "
                    "%.2f px added; resident %g pages; memory %.2f MB streamed; %g nodes streamed, %g in memory\n",
                    size, size_m / double(size - 1), db_first, db_settled, first.counters.at("terrain.stream.missing"),
                    settled.counters.at("terrain.stream.missing"), first.counters.at("terrain.stream.missing_error_px"),
                    settled.counters.at("terrain.stream.resident"), double(t->memoryBytes()) / 1e6,
                    settled.counters.at("terrain.nodes"), memory.counters.at("terrain.nodes"));
        CHECK(db_first < db_settled - 3.0);  // the comparison sees the coarser first frame
        // At 4 m texels the images agree: 58.6 dB at 1025², 44.4 dB at 4097². At 1 m texels
        // (4097² over 4 km) measured 31.6 dB: the geometry is the same (the same nodes from the same grid errors), but a node
        // shades with the normals of its own level's tile, where in memory every pixel reads the
        // full map's, whose detail below the node's spacing shows at 1 m texels (docs/dem.md).
        CHECK(db_settled >= (size_m / double(size - 1) == 4.0 ? 40.0 : 30.0));
    }
}

TEST_CASE("gl: the first streamed load of a TIFF builds its cache a band of rows at a time, as vista terrain-cache does, and rebuilds a version 1 cache") {
    TileStream::setReadDelayForTests(0);
    test::TempDir dir("terrain-stream-tiff");
    const std::filesystem::path tiff = dir.path / "island.tif", cache = dir.path / "island.tif.vtc";
    auto writeTiff = [](const std::filesystem::path& file, const Heightmap& map) {
        auto out = OIIO::ImageOutput::create("tiff");
        REQUIRE(out);
        REQUIRE(out->open(file.string(), OIIO::ImageSpec(map.width, map.height, 1, OIIO::TypeDesc::FLOAT)));
        REQUIRE(out->write_image(OIIO::TypeDesc::FLOAT, map.samples.data()));
        REQUIRE(out->close());
    };
    writeTiff(tiff, generateIsland(IslandParams{257, 3}));
    Settings s = islandScene(true, 512);
    s.terrain.heightmap = tiff.string();
    s.terrain.size_m = 1024.0f;
    s.terrain.stream.cache.clear();  // next to the map
    const std::int64_t whole = wholeHeightmapLoads();
    REQUIRE(renderer().prepare(s).empty());
    REQUIRE(renderer().terrain()->streamed());
    CHECK(wholeHeightmapLoads() == whole);  // the map was never held whole
    REQUIRE(std::filesystem::exists(cache));

    // The file the command writes, byte for byte.
    TerrainCacheOptions o;
    o.input = tiff;
    o.out = dir.path / "command.vtc";
    o.tile = s.terrain.grid;
    o.size_m = s.terrain.size_m;
    o.height_scale_m = s.terrain.height_scale_m;
    o.height_offset_m = s.terrain.height_offset_m;
    o.progress = false;
    REQUIRE(runTerrainCache(o) == 0);
    const std::string built = bytes(cache);
    CHECK(built == bytes(o.out));

    // A cache of version 1 (its error estimates asked for finer nodes than the map needs) is
    // refused and rebuilt on the next load.
    std::string v1 = built;
    const std::uint32_t version = 1;
    std::memcpy(&v1[8], &version, sizeof version);
    std::ofstream(cache, std::ios::binary | std::ios::trunc) << v1;
    std::string why;
    CHECK_FALSE(TileCache::open(cache, why));
    CHECK(why.find("version 1") != std::string::npos);
    s.terrain.stream.pool_pages = 511;  // another pool: the terrain loads again
    REQUIRE(renderer().prepare(s).empty());
    REQUIRE(renderer().terrain()->streamed());
    CHECK(wholeHeightmapLoads() == whole);
    CHECK(bytes(cache) == built);

    // loadChecked's height range holds row by row: a height beyond 100 km names the map and its
    // texel, and leaves no cache behind.
    Heightmap spike = generateIsland(IslandParams{65, 3});
    spike.samples[40 * 65 + 9] = 1e6f;
    const std::filesystem::path bad = dir.path / "spike.tif";
    writeTiff(bad, spike);
    s.terrain.heightmap = bad.string();
    const InputErrors errors = renderer().prepare(s);
    REQUIRE(errors.size() == 1);
    CHECK(errors[0].file == bad.string());
    CHECK(errors[0].message.find("at texel (9, 40) is outside the accepted") != std::string::npos);
    CHECK_FALSE(std::filesystem::exists(dir.path / "spike.tif.vtc"));
    CHECK(wholeHeightmapLoads() == whole);

    // A raw .r16 a row at a time too, the command's file (given the same size).
    const Heightmap small = generateIsland(IslandParams{65, 3});
    std::string raw;
    for (float v : small.samples) {
        const unsigned q = unsigned(std::lround(v * 65535.0f));
        raw += char(q & 0xff);
        raw += char(q >> 8);
    }
    const std::filesystem::path r16 = dir.path / "island.r16";
    std::ofstream(r16, std::ios::binary) << raw;
    s.terrain.heightmap = r16.string();
    s.terrain.raw_width = s.terrain.raw_height = 65;
    REQUIRE(renderer().prepare(s).empty());
    REQUIRE(renderer().terrain()->streamed());
    CHECK(wholeHeightmapLoads() == whole);
    o.input = r16;
    o.out = dir.path / "r16-command.vtc";
    o.raw_width = o.raw_height = 65;
    REQUIRE(runTerrainCache(o) == 0);
    CHECK(bytes(dir.path / "island.r16.vtc") == bytes(o.out));
}

TEST_CASE("gl: the first streamed load of a DEM builds its cache a row at a time, as vista terrain-cache does") {
    TileStream::setReadDelayForTests(0);
    test::TempDir dir("terrain-stream-dem");
    // An ESRI ASCII grid: georeferenced (8 m cells), read by GDAL.
    const Heightmap island = generateIsland(IslandParams{129, 3});
    auto writeGrid = [&](const std::filesystem::path& file, int hole) {
        std::ofstream out(file);
        out << "ncols 129\nnrows 129\nxllcorner 0\nyllcorner 0\ncellsize 8\nNODATA_value -9999\n";
        for (int i = 0; i < 129 * 129; ++i) out << (i == hole ? -9999.0 : 300.0 * island.samples[std::size_t(i)] - 20.0) << (i % 129 == 128 ? "\n" : " ");
    };
    const std::filesystem::path dem = dir.path / "island.asc", cache = dir.path / "island.asc.vtc";
    writeGrid(dem, -1);
    Settings s = islandScene(true, 512);
    s.terrain.dem = dem.string();
    s.terrain.stream.cache.clear();  // next to the map
    const std::int64_t whole = wholeDemLoads();
    REQUIRE(renderer().prepare(s).empty());
    REQUIRE(renderer().terrain()->streamed());
    CHECK(wholeDemLoads() == whole);  // read a row at a time
    REQUIRE(std::filesystem::exists(cache));
    TerrainCacheOptions o;
    o.input = dem;
    o.out = dir.path / "command.vtc";
    o.tile = s.terrain.grid;
    o.progress = false;
    REQUIRE(runTerrainCache(o) == 0);
    CHECK(wholeDemLoads() == whole);
    CHECK(bytes(cache) == bytes(o.out));

    // A nodata cell to fill: the fill spreads across the map, so this DEM is loaded whole (the
    // same cache as the command's).
    const std::filesystem::path holes = dir.path / "holes.asc";
    writeGrid(holes, 64 * 129 + 64);
    s.terrain.dem = holes.string();
    REQUIRE(renderer().prepare(s).empty());
    REQUIRE(renderer().terrain()->streamed());
    CHECK(wholeDemLoads() == whole + 1);
    o.input = holes;
    o.out = dir.path / "holes-command.vtc";
    REQUIRE(runTerrainCache(o) == 0);
    CHECK(bytes(dir.path / "holes.asc.vtc") == bytes(o.out));
}

TEST_CASE("gl: a streamed terrain on a slow disk never shows a hole along a fast flight") {
    TileStream::setReadDelayForTests(20);  // ms per tile: loads lag the camera by many frames
    Settings s = islandScene(true, 1024);
    s.terrain.stream.prefetch_frames = 4;
    int missing = 0;
    for (int i = 0; i < 8; ++i) {
        // 180 m per frame at 800 m above sea level (over the peaks), looking down ahead.
        const ViewParams view{{-600.0 + 150.0 * i, 800.0, 400.0 - 100.0 * i}, 250.0, -70.0, 60.0, 0.5, 160, 90};
        const Frame f = render(s, view);
        INFO("frame " << i << ": missing " << f.counters.at("terrain.stream.missing"));
        CHECK(f.holes == 0);
        missing += int(f.counters.at("terrain.stream.missing"));
    }
    CHECK(missing > 0);  // the disk was slow: nodes were drawn from coarser tiles
    CHECK(renderer().terrain()->stream()->checkConsistency() == "");
    // The hole count can fail: looking up at the empty sky leaves pixels uncovered.
    const Frame up = render(s, ViewParams{{0.0, 800.0, 0.0}, 0.0, 30.0, 60.0, 0.5, 160, 90});
    CHECK(up.holes > 0);
    TileStream::setReadDelayForTests(0);
}

TEST_CASE("gl: the first frame's missing-tile error stays a finite bound with the camera among the nodes") {
    TileStream::setReadDelayForTests(0);
    // A fresh pool (another size reopens the stream): the first frame draws the coarsest levels only.
    render(islandScene(true, 1500), overview());
    const double ground = renderer().terrain()->heightAt(0.0, 0.0);
    const Settings s = islandScene(true, 1499);
    // 3 m above the ground at the island's middle, looking along it: the camera stands inside the
    // boxes of the nodes around it, whose nearest point is ~0 m away.
    const ViewParams low{{0.0, ground + 3.0, 0.0}, 40.0, -5.0, 60.0, 0.5, 160, 90};
    const Frame f = render(s, low);
    const TileCache& cache = renderer().terrain()->stream()->cache();
    const double top_error = cache.entry(int(cache.levels().size()) - 1, 0, 0).error_m;  // bounds every tile's
    const double px = f.counters.at("terrain.stream.missing_error_px");
    INFO("missing " << f.counters.at("terrain.stream.missing") << ", " << px << " px, top error " << top_error << " m");
    CHECK(f.counters.at("terrain.stream.missing") > 0);
    CHECK(px > 0.0);
    // No point nearer than the near plane (0.5 m) is drawn: at most the error seen from there,
    // at 90 px over a 60 degree field of view.
    CHECK(px <= top_error * (90.0 / (2.0 * std::tan(glm::radians(30.0)))) / 0.5 * 1.001);
    CHECK(missingTileErrorPx(2.0, 100.0, 0.0, 0.5) == 400.0);
    CHECK(missingTileErrorPx(2.0, 100.0, 4.0, 0.5) == 50.0);
}

TEST_CASE("gl: a streamed terrain with a tiny pool evicts and stays consistent") {
    TileStream::setReadDelayForTests(0);
    const Settings s = islandScene(true, 96);  // the three coarsest levels (21 tiles) and 75 more
    std::int64_t evicted = 0;
    for (int i = 0; i < 6; ++i) {
        const ViewParams view{{-700.0 + 280.0 * i, 800.0, 300.0}, 90.0 * i, -70.0, 60.0, 0.5, 160, 90};
        render(s, view);
        renderer().terrain()->stream()->settle();  // uploads (and evicts) all it can; counted since the frame began
        evicted += renderer().terrain()->stream()->counters().evicted;
        const Frame f = render(s, view);
        CHECK(f.holes == 0);
        CHECK(f.counters.at("terrain.stream.resident") <= 96);
        REQUIRE(renderer().terrain()->stream()->checkConsistency() == "");
    }
    CHECK(evicted > 0);
}

TEST_CASE("gl: streaming refuses what it cannot serve, naming the key or file and what is accepted") {
    Settings s = islandScene(true);
    s.grass.enabled = true;  // the grass reads the whole map's height texture
    InputErrors errors = renderer().prepare(s);
    REQUIRE(errors.size() == 1);
    CHECK(errors[0].file == "[terrain.stream] enabled");
    CHECK(errors[0].message.find("[grass] enabled") != std::string::npos);

    // An up-to-date cache with tiles of another size than the grid is refused, not replaced.
    TileCacheKey key;
    REQUIRE(tileCacheKey(islandFile(), key).empty());
    const std::filesystem::path other = islandFile().parent_path() / "tile64.vtc";
    const TerrainMapping mapping{4096.0, 600.0, 0.0, 1025, 1025};
    REQUIRE(buildTileCache(loadHeightmap(islandFile(), 0, 0, errors), mapping, key, 64, other, true).empty());
    s = islandScene(true);
    s.terrain.stream.cache = other.string();
    errors = renderer().prepare(s);
    REQUIRE(errors.size() == 1);
    CHECK(errors[0].file == other.string());
    CHECK(errors[0].message.find("--tile 32") != std::string::npos);
    std::string why;
    CHECK(TileCache::open(other, why)->tileSize() == 64);  // still there
}
