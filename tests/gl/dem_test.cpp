// DEM terrain under OSMesa: a GeoTIFF written by GDAL renders like the same heights given as a
// heightmap with the matching size and height range; a raster that is not square in metres has
// its own extent in z (no holes, heights where the geotransform puts them); a bad DEM is
// refused with exit code 2, by `vista capture` and `vista check` alike.
#include "app/capture.h"
#include "app/frame.h"
#include "app/scene.h"
#include "renderer_fixture.h"
#include "renderer/half.h"
#include "terrain/dem.h"
#include "terrain/heightmap.h"

#include <gdal.h>
#include <ogr_srs_api.h>

#include <cmath>
#include <cstdlib>
#include <fstream>

using namespace vista;

namespace {

// A w x h float32 GeoTIFF in UTM 33N with square texels of texel_m, heights f(x, z) in metres.
void writeDem(const std::filesystem::path& file, int w, int h, double texel_m, const std::function<double(int, int)>& f) {
    GDALAllRegister();
    GDALDatasetH ds = GDALCreate(GDALGetDriverByName("GTiff"), file.c_str(), w, h, 1, GDT_Float32, nullptr);
    REQUIRE(ds);
    double gt[6] = {400000.0, texel_m, 0.0, 5100000.0, 0.0, -texel_m};
    GDALSetGeoTransform(ds, gt);
    OGRSpatialReferenceH srs = OSRNewSpatialReference(nullptr);
    REQUIRE(OSRImportFromEPSG(srs, 32633) == OGRERR_NONE);
    GDALSetSpatialRef(ds, srs);
    OSRDestroySpatialReference(srs);
    std::vector<double> v(std::size_t(w) * std::size_t(h));
    for (int z = 0; z < h; ++z)
        for (int x = 0; x < w; ++x) v[std::size_t(z) * std::size_t(w) + std::size_t(x)] = f(x, z);
    REQUIRE(GDALRasterIO(GDALGetRasterBand(ds, 1), GF_Write, 0, 0, w, h, v.data(), w, h, GDT_Float64, 0, 0) == CE_None);
    GDALClose(ds);
}

double hills(int x, int z) { return 250.0 + 120.0 * std::sin(x * 0.21) * std::cos(z * 0.17) + 2.0 * z; }

Settings terrainOnly() {
    Settings s;
    s.sky.enabled = false;
    s.debug.grid = false;
    return s;
}

std::vector<std::uint16_t> render(FrameRenderer& r, const Settings& s, const ViewParams& view) {
    InputErrors errors = r.prepare(s);
    for (const auto& e : errors) MESSAGE(e.str());
    REQUIRE(errors.empty());
    std::vector<std::uint16_t> hdr;
    FrameRequest request;
    request.capture_hdr = &hdr;
    r.resetHistory();  // each frame the first of a run: the same TAA jitter and no history
    r.render(s, view, 0.0, request);
    return hdr;
}

int holes(const std::vector<std::uint16_t>& hdr) {
    int n = 0;
    for (std::size_t i = 3; i < hdr.size(); i += 4) n += hdr[i] == 0;
    return n;
}

}  // namespace

TEST_CASE("gl: a GeoTIFF DEM renders like its heights given as a heightmap with the same size and range") {
    test::TempDir dir("dem-same");
    const int n = 65;
    const double texel = 20.0;
    writeDem(dir.path / "hills.tif", n, n, texel, hills);
    double lo = 1e30, hi = -1e30;
    Heightmap map{n, n, std::vector<float>(std::size_t(n) * n)};
    for (int z = 0; z < n; ++z)
        for (int x = 0; x < n; ++x) {
            lo = std::min(lo, double(float(hills(x, z))));
            hi = std::max(hi, double(float(hills(x, z))));
        }
    for (int z = 0; z < n; ++z)
        for (int x = 0; x < n; ++x) map.samples[std::size_t(z * n + x)] = float((double(float(hills(x, z))) - lo) / (hi - lo));
    REQUIRE(saveHeightmapExr(dir.path / "hills.exr", map).empty());

    Settings from_dem = terrainOnly();
    from_dem.terrain.dem = (dir.path / "hills.tif").string();
    Settings from_map = terrainOnly();
    from_map.terrain.heightmap = (dir.path / "hills.exr").string();
    from_map.terrain.size_m = float(texel * (n - 1));
    from_map.terrain.height_scale_m = float(hi - lo);
    from_map.terrain.height_offset_m = float(lo);

    FrameRenderer& r = test::compiledFileRenderer();
    const ViewParams view{{-500.0, 700.0, 600.0}, 40.0, -30.0, 60.0, 0.5, 96, 54};
    std::vector<std::uint16_t> a = render(r, from_dem, view);
    REQUIRE(r.terrain());
    CHECK(r.terrain()->mapping().sizeX() == doctest::Approx(1280.0));
    CHECK(r.terrain()->heightAt(-640.0, -640.0) == doctest::Approx(hills(0, 0)).epsilon(1e-5));
    CHECK(r.terrain()->heightAt(640.0, 640.0) == doctest::Approx(hills(n - 1, n - 1)).epsilon(1e-5));
    std::vector<std::uint16_t> b = render(r, from_map, view);
    REQUIRE(a.size() == b.size());
    CHECK(holes(a) < int(a.size() / 8));  // the terrain is in view
    int differing = 0;
    double max_diff = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        const double d = std::abs(halfToFloat(a[i]) - halfToFloat(b[i]));
        max_diff = std::max(max_diff, d);
        differing += d > 0.01;
    }
    CAPTURE(max_diff);
    CHECK(differing <= int(a.size() / 500));
}

TEST_CASE("gl: a DEM that is not square in metres has its own z extent and no holes") {
    test::TempDir dir("dem-rect");
    // 65 x 33 samples of 10 m: 640 m east-west, 320 m north-south.
    writeDem(dir.path / "strip.tif", 65, 33, 10.0, hills);
    Settings s = terrainOnly();
    s.terrain.dem = (dir.path / "strip.tif").string();
    FrameRenderer& r = test::compiledFileRenderer();
    // Looking straight down at the middle of the strip, which fills the view only in x.
    std::vector<std::uint16_t> hdr = render(r, s, ViewParams{{0.0, 900.0, 0.0}, 0.0, -89.9, 20.0, 0.5, 96, 54});
    REQUIRE(r.terrain());
    const TerrainMapping& m = r.terrain()->mapping();
    CHECK(m.sizeX() == doctest::Approx(640.0));
    CHECK(m.sizeZ() == doctest::Approx(320.0));
    CHECK(m.texelSizeZ() == doctest::Approx(10.0));
    // The north-east corner texel and one inside, where the geotransform puts them.
    CHECK(r.terrain()->heightAt(320.0, -160.0) == doctest::Approx(hills(64, 0)).epsilon(1e-5));
    CHECK(r.terrain()->heightAt(-310.0, 150.0) == doctest::Approx(hills(1, 31)).epsilon(1e-5));
    // 20 deg vertical fov from about 600 m above the ground: the view is ~210 m by ~380 m, inside the strip.
    CHECK(holes(hdr) == 0);
    // A wider view of a flat strip shows all of it: ground across the middle, nothing at the
    // image's edges, and the ground twice as long in x as in z (in pixels, square pixels).
    writeDem(dir.path / "flat.tif", 65, 33, 10.0, [](int, int) { return 300.0; });
    s.terrain.dem = (dir.path / "flat.tif").string();
    hdr = render(r, s, ViewParams{{0.0, 900.0, 0.0}, 0.0, -89.9, 50.0, 0.5, 96, 54});
    auto ground = [&](int x, int y) { return hdr[(std::size_t(y) * 96 + std::size_t(x)) * 4 + 3] != 0; };
    int row = 0, column = 0;
    for (int x = 0; x < 96; ++x) row += ground(x, 27);
    for (int y = 0; y < 54; ++y) column += ground(48, y);
    CHECK(ground(48, 27));
    CHECK_FALSE(ground(0, 27));
    CHECK_FALSE(ground(95, 27));
    CHECK_FALSE(ground(48, 0));
    CHECK_FALSE(ground(48, 53));
    CAPTURE(row);
    CAPTURE(column);
    CHECK(double(row) / double(column) == doctest::Approx(2.0).epsilon(0.1));
}

TEST_CASE("gl: a bad DEM is refused with exit code 2 by capture and check, naming the file") {
    test::TempDir dir("dem-bad");
    const std::filesystem::path junk = dir.path / "junk.tif";
    {
        std::ofstream(junk) << "not a raster";
    }
    CaptureJob job;
    REQUIRE(loadScene(defaultScenePath(), {}, job.settings).empty());
    job.settings.terrain.dem = junk.string();
    job.settings.capture.out = (dir.path / "out").string();
    job.settings.capture.frames = 1;
    job.progress = false;
    CHECK(runCapture(job).exit_code == 2);
    const std::string command = std::string(VISTA_EXECUTABLE) + " check --set terrain.dem=" + junk.string() + " > " +
                                (dir.path / "check.txt").string() + " 2>&1";
    const int status = std::system(command.c_str());
    CHECK(WEXITSTATUS(status) == 2);
    std::ifstream in(dir.path / "check.txt");
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    CHECK(text.find(junk.string() + ": cannot be read as a DEM by GDAL") != std::string::npos);
}

TEST_CASE("gl: vista terrain-cache builds once, then finds the cache up to date, stale or truncated") {
    test::TempDir dir("dem-cache");
    const std::filesystem::path dem = dir.path / "hills.tif", cache = dir.path / "hills.vtc";
    writeDem(dem, 129, 129, 10.0, hills);
    auto run = [&](const std::string& args) {
        const std::filesystem::path log = dir.path / "log.txt";
        const std::string command = std::string(VISTA_EXECUTABLE) + " terrain-cache " + dem.string() + " --out " +
                                    cache.string() + " --tile 32 " + args + " > " + log.string() + " 2>&1";
        const int status = std::system(command.c_str());
        std::ifstream in(log);
        return std::make_pair(WEXITSTATUS(status), std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>()));
    };
    auto [code, text] = run("");
    CHECK(code == 0);
    CHECK(text.find("wrote " + cache.string() + ": 129x129 samples, 21 tiles of 32") != std::string::npos);
    std::tie(code, text) = run("");
    CHECK(code == 0);
    CHECK(text.find("up to date") != std::string::npos);
    // A changed input (another time and other first bytes) rebuilds.
    writeDem(dem, 129, 129, 10.0, [](int x, int z) { return hills(x, z) + 1.0; });
    std::filesystem::last_write_time(dem, std::filesystem::last_write_time(dem) + std::chrono::seconds(3));
    std::tie(code, text) = run("");
    CHECK(code == 0);
    CHECK(text.find("another version") != std::string::npos);
    CHECK(text.find("wrote") != std::string::npos);
    // A truncated cache is found and rebuilt.
    std::filesystem::resize_file(cache, std::filesystem::file_size(cache) / 2);
    std::tie(code, text) = run("");
    CHECK(code == 0);
    CHECK(text.find("truncated") != std::string::npos);
    CHECK(text.find("wrote") != std::string::npos);
    // Bad input is exit code 2 naming what is wrong.
    const std::string command = std::string(VISTA_EXECUTABLE) + " terrain-cache " + dem.string() + " --tile 1 > " +
                                (dir.path / "bad.txt").string() + " 2>&1";
    CHECK(WEXITSTATUS(std::system(command.c_str())) == 2);
    std::ifstream bad(dir.path / "bad.txt");
    CHECK(std::string((std::istreambuf_iterator<char>(bad)), std::istreambuf_iterator<char>()).find("--tile 1 is out of range") !=
          std::string::npos);
}
