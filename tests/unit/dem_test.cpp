// DEMs through GDAL (terrain/dem.h): GeoTIFFs, an SRTM tile, an ESRI ASCII grid and a VRT of
// four tiles written by GDAL inside the test load with the right spacing and heights; nodata is
// filled or refused; unsupported input is refused naming the file and the reason; a DEM read a
// row at a time (for its tile cache) gives the samples and the cache of the DEM loaded whole.
#include "../temp_dir.h"
#include "terrain/dem.h"
#include "terrain/tile_cache.h"

#include <doctest/doctest.h>
#include <gdal.h>
#include <gdal_utils.h>
#include <ogr_srs_api.h>
#include <unistd.h>

#include <cmath>
#include <fstream>
#include <optional>

using namespace vista;
namespace fs = std::filesystem;

namespace {

using test::TempDir;

struct Raster {
    Raster(int w, int h, int b, GDALDataType t, std::vector<double> v, std::optional<std::array<double, 6>> gt, int crs,
           std::optional<double> no = std::nullopt, std::string u = {})
        : width(w), height(h), bands(b), type(t), values(std::move(v)), geotransform(gt), epsg(crs), nodata(no), unit(std::move(u)) {}
    int width = 0, height = 0, bands = 1;
    GDALDataType type = GDT_Float32;
    std::vector<double> values;  // row-major, row 0 first (as stored)
    std::optional<std::array<double, 6>> geotransform;
    int epsg = 0;                // 0: no CRS
    std::optional<double> nodata;
    std::string unit;
};

void writeRaster(const fs::path& file, const Raster& r, const char* driver_name = "GTiff") {
    GDALAllRegister();
    GDALDriverH driver = GDALGetDriverByName(driver_name);
    REQUIRE(driver);
    GDALDatasetH ds = GDALCreate(driver, file.c_str(), r.width, r.height, r.bands, r.type, nullptr);
    REQUIRE(ds);
    if (r.geotransform) {
        std::array<double, 6> gt = *r.geotransform;
        GDALSetGeoTransform(ds, gt.data());
    }
    if (r.epsg) {
        OGRSpatialReferenceH srs = OSRNewSpatialReference(nullptr);
        REQUIRE(OSRImportFromEPSG(srs, r.epsg) == OGRERR_NONE);
        GDALSetSpatialRef(ds, srs);
        OSRDestroySpatialReference(srs);
    }
    for (int b = 1; b <= r.bands; ++b) {
        GDALRasterBandH band = GDALGetRasterBand(ds, b);
        if (r.nodata) GDALSetRasterNoDataValue(band, *r.nodata);
        if (!r.unit.empty()) GDALSetRasterUnitType(band, r.unit.c_str());
        std::vector<double> v = r.values;
        REQUIRE(GDALRasterIO(band, GF_Write, 0, 0, r.width, r.height, v.data(), r.width, r.height, GDT_Float64, 0, 0) == CE_None);
    }
    GDALClose(ds);
}

Dem loadOk(const fs::path& file, DemNodata nodata = DemNodata::Fill, double scale = 1.0) {
    InputErrors errors;
    Dem dem = loadDem(file, nodata, scale, errors);
    for (const auto& e : errors) MESSAGE(e.str());
    REQUIRE(errors.empty());
    REQUIRE(dem.map.width > 1);
    return dem;
}

std::string loadError(const fs::path& file, DemNodata nodata = DemNodata::Fill) {
    InputErrors errors;
    Dem dem = loadDem(file, nodata, 1.0, errors);
    CHECK(dem.map.samples.empty());
    REQUIRE(errors.size() == 1);
    CHECK(errors[0].file == file.string());
    return errors[0].message;
}

std::vector<char> bytesOf(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Height in metres of texel (x, z) of a loaded DEM.
double metres(const Dem& dem, int x, int z) {
    TerrainMapping m = demMapping(dem.info, dem.map.width, dem.map.height);
    return m.height_offset_m + m.height_scale_m * double(dem.map.at(x, z));
}

// Samples of a w x h ramp: distinct heights everywhere, so a flip or a shift shows.
std::vector<double> ramp(int w, int h, double base = 100.0) {
    std::vector<double> v;
    for (int z = 0; z < h; ++z)
        for (int x = 0; x < w; ++x) v.push_back(base + 3.0 * x + 50.0 * z);
    return v;
}

}  // namespace

TEST_CASE("dem: geographic texel size from the ellipsoid radii matches published degree lengths") {
    // The published series for WGS84 (metres per degree of latitude and of longitude), an
    // independent reference good to a few centimetres.
    auto lat_m = [](double p) { return 111132.954 - 559.822 * std::cos(2 * p) + 1.175 * std::cos(4 * p); };
    auto lon_m = [](double p) { return 111412.84 * std::cos(p) - 93.5 * std::cos(3 * p) + 0.118 * std::cos(5 * p); };
    for (double lat : {0.0, 30.0, 45.0, 60.0, -46.5}) {
        CAPTURE(lat);
        double x = 0.0, z = 0.0;
        geographicTexelMetres(1.0, 1.0, lat, 6378137.0, 1.0 / 298.257223563, x, z);
        const double p = lat * 3.14159265358979323846 / 180.0;
        CHECK(z == doctest::Approx(lat_m(p)).epsilon(1e-6));
        CHECK(x == doctest::Approx(lon_m(p)).epsilon(1e-6));
    }
}

TEST_CASE("dem: nodata is filled ring by ring from known neighbours") {
    // 5 x 1: known 0 at the left, 8 at the right; the ring next to them first, then the middle.
    std::vector<float> s{0, -1, -1, -1, 8};
    std::vector<std::uint8_t> known{1, 0, 0, 0, 1};
    REQUIRE(fillFromNeighbours(s, known, 5, 1));
    CHECK(s[1] == 0.0f);
    CHECK(s[3] == 8.0f);
    CHECK(s[2] == 4.0f);  // mean of its two neighbours, both filled in the ring before
    // A hole in a 3 x 3: the centre takes the mean of its 4 neighbours.
    std::vector<float> g{1, 2, 3, 4, -9, 6, 7, 8, 9};
    std::vector<std::uint8_t> k{1, 1, 1, 1, 0, 1, 1, 1, 1};
    REQUIRE(fillFromNeighbours(g, k, 3, 3));
    CHECK(g[4] == 5.0f);
    std::vector<std::uint8_t> none(9, 0);
    CHECK_FALSE(fillFromNeighbours(g, none, 3, 3));
}

TEST_CASE("dem: a UTM GeoTIFF (int16) loads with its texel spacing and heights") {
    TempDir dir("utm");
    Raster r{4, 3, 1, GDT_Int16, ramp(4, 3), std::array<double, 6>{500000, 30, 0, 4500000, 0, -30}, 32633};
    writeRaster(dir / "utm.tif", r);
    Dem dem = loadOk(dir / "utm.tif");
    CHECK(dem.info.driver == "GTiff");
    CHECK_FALSE(dem.info.geographic);
    CHECK(dem.info.crs.find("UTM zone 33N") != std::string::npos);
    CHECK(dem.info.texel_x_m == 30.0);
    CHECK(dem.info.texel_z_m == 30.0);
    CHECK(dem.info.min_m == 100.0);
    CHECK(dem.info.max_m == 100.0 + 9.0 + 100.0);
    TerrainMapping m = demMapping(dem.info, dem.map.width, dem.map.height);
    CHECK(m.sizeX() == 90.0);
    CHECK(m.sizeZ() == 60.0);
    CHECK(m.texelSizeX() == 30.0);
    CHECK(m.texelSizeZ() == 30.0);
    for (int z = 0; z < 3; ++z)
        for (int x = 0; x < 4; ++x) CHECK(metres(dem, x, z) == doctest::Approx(100.0 + 3.0 * x + 50.0 * z).epsilon(1e-6));
    // Vertical exaggeration scales heights, not spacing.
    Dem twice = loadOk(dir / "utm.tif", DemNodata::Fill, 2.0);
    CHECK(twice.info.max_m == 2.0 * dem.info.max_m);
    CHECK(twice.info.texel_x_m == 30.0);
}

TEST_CASE("dem: a WGS84 GeoTIFF (float32) gets metres from the latitude at its centre, heights in feet converted") {
    TempDir dir("wgs84");
    const double step = 1.0 / 3600.0;  // one arc-second
    Raster r{6, 5, 1, GDT_Float32, ramp(6, 5, 1000.25), std::array<double, 6>{15.0, step, 0, 46.0, 0, -step}, 4326};
    r.unit = "ft";
    writeRaster(dir / "wgs84.tif", r);
    Dem dem = loadOk(dir / "wgs84.tif");
    CHECK(dem.info.geographic);
    CHECK(dem.info.centre_lat_deg == doctest::Approx(46.0 - 2.5 * step));
    double x = 0.0, z = 0.0;
    geographicTexelMetres(step, step, dem.info.centre_lat_deg, 6378137.0, 1.0 / 298.257223563, x, z);
    CHECK(dem.info.texel_x_m == doctest::Approx(x).epsilon(1e-12));
    CHECK(dem.info.texel_z_m == doctest::Approx(z).epsilon(1e-12));
    CHECK(dem.info.texel_z_m == doctest::Approx(30.87).epsilon(1e-3));  // 1" of latitude
    CHECK(dem.info.texel_x_m == doctest::Approx(21.52).epsilon(1e-3));  // 1" of longitude at 46 N
    for (int zz = 0; zz < 5; ++zz)
        for (int xx = 0; xx < 6; ++xx)
            CHECK(metres(dem, xx, zz) == doctest::Approx(0.3048 * (1000.25 + 3.0 * xx + 50.0 * zz)).epsilon(1e-6));
}

TEST_CASE("dem: south-up and east-to-west rasters are turned north-up") {
    TempDir dir("flip");
    Raster r{3, 2, 1, GDT_Float32, ramp(3, 2), std::array<double, 6>{1000, -10, 0, 0, 0, 10}, 32633};
    writeRaster(dir / "flip.tif", r);
    Dem dem = loadOk(dir / "flip.tif");
    // Stored row 0 is the southern one and column 0 the eastern one.
    CHECK(metres(dem, 0, 0) == doctest::Approx(100.0 + 3.0 * 2 + 50.0 * 1));
    CHECK(metres(dem, 2, 1) == doctest::Approx(100.0));
}

TEST_CASE("dem: nodata is filled from neighbours or refused by dem_nodata") {
    TempDir dir("nodata");
    std::vector<double> v = ramp(5, 5);
    v[2 * 5 + 2] = -9999.0;  // a hole in the middle
    v[0] = -9999.0;          // and a corner
    Raster r{5, 5, 1, GDT_Float32, v, std::array<double, 6>{0, 2, 0, 0, 0, -2}, 32633, -9999.0};
    writeRaster(dir / "holes.tif", r);
    Dem dem = loadOk(dir / "holes.tif");
    CHECK(dem.info.nodata == 2);
    CHECK(dem.info.min_m > 0.0);  // -9999 never reaches the heights
    auto h = [](int x, int z) { return 100.0 + 3.0 * x + 50.0 * z; };
    CHECK(metres(dem, 2, 2) == doctest::Approx((h(1, 2) + h(3, 2) + h(2, 1) + h(2, 3)) / 4.0).epsilon(1e-6));
    CHECK(metres(dem, 0, 0) == doctest::Approx((h(1, 0) + h(0, 1)) / 2.0).epsilon(1e-6));
    const std::string why = loadError(dir / "holes.tif", DemNodata::Refuse);
    CHECK(why.find("2 nodata sample(s), the first at texel (0, 0)") != std::string::npos);
    CHECK(why.find("dem_nodata") != std::string::npos);
    // NaN is nodata too in a float DEM.
    v[0] = std::nan("");
    r.values = v;
    r.nodata.reset();
    writeRaster(dir / "nan.tif", r);
    CHECK(loadOk(dir / "nan.tif").info.nodata == 1);
    r.values.assign(25, -9999.0);
    r.nodata = -9999.0;
    writeRaster(dir / "empty.tif", r);
    CHECK(loadError(dir / "empty.tif").find("no data at all") != std::string::npos);
}

TEST_CASE("dem: a VRT mosaic of four tiles loads as one map") {
    TempDir dir("vrt");
    // Four 4 x 4 tiles of one 8 x 8 ramp, 25 m texels.
    std::vector<std::string> names;
    for (int tz = 0; tz < 2; ++tz)
        for (int tx = 0; tx < 2; ++tx) {
            std::vector<double> v;
            for (int z = 0; z < 4; ++z)
                for (int x = 0; x < 4; ++x) v.push_back(10.0 + (tx * 4 + x) + 100.0 * (tz * 4 + z));
            Raster r{4, 4, 1, GDT_Int16, v,
                     std::array<double, 6>{300000.0 + tx * 100.0, 25, 0, 5000000.0 - tz * 100.0, 0, -25}, 32633};
            names.push_back((dir / ("tile" + std::to_string(tz) + std::to_string(tx) + ".tif")).string());
            writeRaster(names.back(), r);
        }
    std::vector<const char*> sources;
    for (const auto& n : names) sources.push_back(n.c_str());
    const fs::path vrt = dir / "mosaic.vrt";
    int usage_error = 0;
    GDALDatasetH ds = GDALBuildVRT(vrt.c_str(), int(sources.size()), nullptr, sources.data(), nullptr, &usage_error);
    REQUIRE(ds);
    GDALClose(ds);
    Dem dem = loadOk(vrt);
    CHECK(dem.info.driver == "VRT");
    CHECK(dem.map.width == 8);
    CHECK(dem.map.height == 8);
    CHECK(dem.info.texel_x_m == 25.0);
    for (int z = 0; z < 8; ++z)
        for (int x = 0; x < 8; ++x) CHECK(metres(dem, x, z) == doctest::Approx(10.0 + x + 100.0 * z));
}

TEST_CASE("dem: read a row at a time, the same samples and the same tile cache as loaded whole") {
    TempDir dir("rows");
    // Heights that differ everywhere (a flip or a shift shows), in a UTM int16 raster, a south-up,
    // east-to-west float one with a vertical unit, scale and exaggeration, and a VRT of two tiles.
    const int w = 70, h = 41;
    std::vector<double> v;
    for (int z = 0; z < h; ++z)
        for (int x = 0; x < w; ++x) v.push_back(std::round(200.0 + 40.0 * std::sin(0.31 * x) * std::cos(0.17 * z) + 2.0 * x + 3.0 * z));
    writeRaster(dir / "utm.tif", Raster{w, h, 1, GDT_Int16, v, std::array<double, 6>{500000, 30, 0, 4500000, 0, -30}, 32633});
    Raster flipped{w, h, 1, GDT_Float32, v, std::array<double, 6>{1000, -10, 0, 0, 0, 10}, 32633};
    flipped.unit = "ft";
    writeRaster(dir / "flip.tif", flipped);
    std::vector<std::string> names;
    for (int tx = 0; tx < 2; ++tx) {
        std::vector<double> half;
        for (int z = 0; z < h; ++z)
            for (int x = 0; x < w / 2; ++x) half.push_back(v[std::size_t(z * w + tx * (w / 2) + x)]);
        names.push_back((dir / ("half" + std::to_string(tx) + ".tif")).string());
        writeRaster(names.back(), Raster{w / 2, h, 1, GDT_Int16, half,
                                         std::array<double, 6>{300000.0 + tx * 25.0 * (w / 2), 25, 0, 5000000.0, 0, -25}, 32633});
    }
    std::vector<const char*> sources{names[0].c_str(), names[1].c_str()};
    int usage_error = 0;
    GDALDatasetH vrt = GDALBuildVRT((dir / "mosaic.vrt").c_str(), 2, nullptr, sources.data(), nullptr, &usage_error);
    REQUIRE(vrt);
    GDALClose(vrt);
    for (const auto& [name, scale] : {std::pair{"utm.tif", 1.0}, std::pair{"flip.tif", 1.5}, std::pair{"mosaic.vrt", 1.0}}) {
        CAPTURE(name);
        const Dem dem = loadOk(dir / name, DemNodata::Fill, scale);
        InputErrors errors;
        bool fill_whole = true;
        auto rows = DemRows::open(dir / name, DemNodata::Fill, scale, errors, fill_whole);
        REQUIRE(rows);
        CHECK(errors.empty());
        CHECK_FALSE(fill_whole);
        REQUIRE(rows->width() == dem.map.width);
        REQUIRE(rows->height() == dem.map.height);
        CHECK(rows->info().min_m == dem.info.min_m);
        CHECK(rows->info().max_m == dem.info.max_m);
        CHECK(rows->info().texel_x_m == dem.info.texel_x_m);
        CHECK(rows->info().texel_z_m == dem.info.texel_z_m);
        std::vector<float> row(std::size_t(rows->width()));
        int differing = 0;
        for (int z = 0; z < rows->height(); ++z) {
            REQUIRE(rows->read(z, row.data()) == "");
            for (int x = 0; x < rows->width(); ++x) differing += row[std::size_t(x)] != dem.map.at(x, z);
        }
        CHECK(differing == 0);
        // The cache from the rows is the cache from the map held whole, byte for byte.
        const TerrainMapping mapping = demMapping(dem.info, dem.map.width, dem.map.height);
        const TileCacheKey key{1, 2, 3};
        REQUIRE(buildTileCache(dem.map, mapping, key, 16, dir / "whole.vtc", true) == "");
        auto again = DemRows::open(dir / name, DemNodata::Fill, scale, errors, fill_whole);
        REQUIRE(again);
        REQUIRE(buildTileCache(again->width(), again->height(), [&](int z, float* r) { return again->read(z, r); }, mapping, key,
                               16, dir / "rows.vtc", true) == "");
        CHECK(bytesOf(dir / "whole.vtc") == bytesOf(dir / "rows.vtc"));
    }
    // Nodata: refused as loadDem refuses it, or left to the whole load that fills it.
    v[3] = -9999.0;
    writeRaster(dir / "holes.tif", Raster{w, h, 1, GDT_Float32, v, std::array<double, 6>{0, 2, 0, 0, 0, -2}, 32633, -9999.0});
    InputErrors errors;
    bool fill_whole = false;
    CHECK_FALSE(DemRows::open(dir / "holes.tif", DemNodata::Fill, 1.0, errors, fill_whole));
    CHECK(errors.empty());
    CHECK(fill_whole);
    CHECK_FALSE(DemRows::open(dir / "holes.tif", DemNodata::Refuse, 1.0, errors, fill_whole));
    CHECK_FALSE(fill_whole);
    REQUIRE(errors.size() == 1);
    CHECK(errors[0].file == (dir / "holes.tif").string());
    CHECK(errors[0].message == loadError(dir / "holes.tif", DemNodata::Refuse));
    // What is not a DEM is named as loadDem names it: no georeferencing, no file.
    errors.clear();
    writeRaster(dir / "plain.tif", Raster{4, 3, 1, GDT_Float32, ramp(4, 3), std::nullopt, 0});
    CHECK_FALSE(DemRows::open(dir / "plain.tif", DemNodata::Fill, 1.0, errors, fill_whole));
    REQUIRE(errors.size() == 1);
    CHECK(errors[0].message.find("no geotransform") != std::string::npos);
    errors.clear();
    CHECK_FALSE(DemRows::open(dir / "none.tif", DemNodata::Fill, 1.0, errors, fill_whole));
    REQUIRE(errors.size() == 1);
    CHECK(errors[0].file == (dir / "none.tif").string());
}

TEST_CASE("dem: an SRTM .hgt tile and an ESRI ASCII grid load") {
    TempDir dir("formats");
    // SRTM3: 1201 x 1201 int16, 3 arc-second spacing, named after its south-west corner.
    std::vector<double> v(1201 * 1201);
    for (int z = 0; z < 1201; ++z)
        for (int x = 0; x < 1201; ++x) v[std::size_t(z) * 1201 + std::size_t(x)] = 200 + x / 10 + z / 20;
    Raster tif{1201, 1201, 1, GDT_Int16, v, std::array<double, 6>{7.0 - 1.5 / 3600, 3.0 / 3600, 0, 47.0 + 1.5 / 3600, 0, -3.0 / 3600}, 4326};
    writeRaster(dir / "src.tif", tif);
    GDALDatasetH src = GDALOpen((dir / "src.tif").c_str(), GA_ReadOnly);
    REQUIRE(src);
    GDALDatasetH hgt = GDALCreateCopy(GDALGetDriverByName("SRTMHGT"), (dir / "N46E007.hgt").c_str(), src, FALSE, nullptr,
                                      nullptr, nullptr);
    REQUIRE(hgt);
    GDALClose(hgt);
    GDALClose(src);
    Dem dem = loadOk(dir / "N46E007.hgt");
    CHECK(dem.info.driver == "SRTMHGT");
    CHECK(dem.map.width == 1201);
    CHECK(dem.info.centre_lat_deg == doctest::Approx(46.5));
    CHECK(dem.info.texel_z_m == doctest::Approx(92.6).epsilon(1e-3));
    CHECK(metres(dem, 1200, 1200) == doctest::Approx(200 + 120 + 60));

    std::ofstream(dir / "grid.asc") << "ncols 3\nnrows 2\nxllcorner 1000\nyllcorner 2000\ncellsize 5\nNODATA_value -1\n"
                                       "1 2 3\n4 -1 6\n";
    Dem asc = loadOk(dir / "grid.asc");
    CHECK(asc.info.driver == "AAIGrid");
    CHECK(asc.info.crs.find("none") == 0);
    CHECK(asc.info.texel_x_m == 5.0);
    CHECK(asc.info.nodata == 1);
    CHECK(metres(asc, 2, 1) == doctest::Approx(6.0));
    CHECK(metres(asc, 1, 1) == doctest::Approx((4.0 + 6.0 + 2.0) / 3.0));
}

TEST_CASE("dem: unsupported input is refused naming the file and the reason") {
    TempDir dir("bad");
    const std::array<double, 6> gt{0, 10, 0, 0, 0, -10};
    Raster rotated{3, 3, 1, GDT_Float32, ramp(3, 3), std::array<double, 6>{0, 10, 2, 0, 1, -10}, 32633};
    writeRaster(dir / "rotated.tif", rotated);
    CHECK(loadError(dir / "rotated.tif").find("rotated or sheared") != std::string::npos);

    Raster rgb{3, 3, 3, GDT_Byte, ramp(3, 3, 0), gt, 32633};
    writeRaster(dir / "rgb.tif", rgb);
    CHECK(loadError(dir / "rgb.tif").find("has 3 bands") != std::string::npos);

    Raster plain{3, 3, 1, GDT_Float32, ramp(3, 3), std::nullopt, 0};
    writeRaster(dir / "plain.tif", plain);
    CHECK(loadError(dir / "plain.tif").find("no geotransform") != std::string::npos);

    Raster furlongs{3, 3, 1, GDT_Float32, ramp(3, 3), gt, 32633, std::nullopt, "furlong"};
    writeRaster(dir / "furlongs.tif", furlongs);
    CHECK(loadError(dir / "furlongs.tif").find("'furlong'") != std::string::npos);

    Raster wide{3, 3, 1, GDT_Float32, ramp(3, 3), std::array<double, 6>{0, 10, 0, 60, 0, -10}, 4326};
    writeRaster(dir / "wide.tif", wide);
    CHECK(loadError(dir / "wide.tif").find("reproject") != std::string::npos);

    Raster tiny{1, 5, 1, GDT_Float32, ramp(1, 5), gt, 32633};
    writeRaster(dir / "tiny.tif", tiny);
    CHECK(loadError(dir / "tiny.tif").find("at least 2x2") != std::string::npos);

    Raster huge{3, 3, 1, GDT_Float32, {1, 2, 3, 4, 5, 6, 7, 8, 2e6}, gt, 32633};
    writeRaster(dir / "huge.tif", huge);
    CHECK(loadError(dir / "huge.tif").find("accepted: within") != std::string::npos);

    std::ofstream(dir / "junk.tif") << "this is not a TIFF";
    CHECK(loadError(dir / "junk.tif").find("cannot be read as a DEM by GDAL") != std::string::npos);
    CHECK(!loadError(dir / "missing.tif").empty());
    CHECK(!loadError(dir.path).empty());  // a directory

    // Bytes in memory (the fuzz path) go through the same checks.
    InputErrors errors;
    const std::string junk = "II*\0garbage";
    Dem dem = decodeDem(std::span<const unsigned char>(reinterpret_cast<const unsigned char*>(junk.data()), junk.size()),
                        "fuzz.tif", DemNodata::Fill, 1.0, errors, 1u << 20, {"GTiff"});
    CHECK(dem.map.samples.empty());
    REQUIRE(errors.size() == 1);
    CHECK(errors[0].file == "fuzz.tif");
}
