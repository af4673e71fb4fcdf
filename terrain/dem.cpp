// DEM loading through GDAL: georeferencing to metres, vertical units, nodata, and the checks
// that turn unsupported input into errors naming the file and the reason.
#include "terrain/dem.h"

#include "config/file_io.h"

#include <cpl_conv.h>
#include <cpl_error.h>
#include <cpl_vsi.h>
#include <gdal.h>
#include <ogr_srs_api.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <limits>
#include <mutex>

namespace vista {
namespace {

// A geographic DEM is mapped flat around its centre latitude: the east-west scale is
// cos(latitude), which changes by about tan(lat) * span across the map. Beyond this span the
// map's edges would be off by more than a few percent: such data must be reprojected.
constexpr double kMaxGeographicSpanDeg = 10.0;
constexpr double kMaxGeographicLatDeg = 85.0;

// loadDem's calls (wholeDemLoads).
std::atomic<std::int64_t> whole_loads{0};

void initGdal() {
    static std::once_flag once;
    std::call_once(once, [] {
        GDALAllRegister();
        // Never write .aux.xml side files next to the user's data.
        CPLSetConfigOption("GDAL_PAM_ENABLED", "NO");
    });
}

// GDAL's errors are collected (the last message becomes part of ours), never printed.
struct QuietErrors {
    QuietErrors() {
        CPLPushErrorHandler(CPLQuietErrorHandler);
        CPLErrorReset();
    }
    ~QuietErrors() { CPLPopErrorHandler(); }
    QuietErrors(const QuietErrors&) = delete;
    QuietErrors& operator=(const QuietErrors&) = delete;
    static std::string last(const char* otherwise) {
        const char* msg = CPLGetLastErrorMsg();
        return msg && *msg ? std::string(msg) : std::string(otherwise);
    }
};

}  // namespace

// Named (not anonymous): DemRows::Impl holds them.
namespace dem_io {

struct Dataset {
    GDALDatasetH h = nullptr;
    explicit Dataset(GDALDatasetH handle) : h(handle) {}
    ~Dataset() {
        if (h) GDALClose(h);
    }
    Dataset(const Dataset&) = delete;
    Dataset& operator=(const Dataset&) = delete;
};

}  // namespace dem_io

namespace {

using dem_io::Dataset;


std::string lowercase(std::string s) {
    for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

std::string number(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", v);
    return text;
}

// Metres per vertical unit of a band, 0 when the unit is not known.
double verticalUnit(const std::string& unit) {
    const std::string u = lowercase(unit);
    if (u.empty() || u == "m" || u == "metre" || u == "meter" || u == "metres" || u == "meters") return 1.0;
    if (u == "ft" || u == "foot" || u == "feet" || u == "international foot") return 0.3048;
    if (u == "us survey foot" || u == "ftus" || u == "us_survey_foot" || u == "foot_us") return 1200.0 / 3937.0;
    if (u == "km" || u == "kilometre" || u == "kilometer") return 1000.0;
    if (u == "cm" || u == "centimetre" || u == "centimeter") return 0.01;
    return 0.0;
}

// Horizontal spacing in metres from the geotransform and the CRS.
std::string texelMetres(GDALDatasetH ds, const double gt[6], int height, DemInfo& info) {
    OGRSpatialReferenceH srs = GDALGetSpatialRef(ds);
    if (!srs) {
        info.crs = "none (geotransform units taken as metres)";
        info.texel_x_m = std::abs(gt[1]);
        info.texel_z_m = std::abs(gt[5]);
        return {};
    }
    const char* name = OSRGetName(srs);
    info.crs = name && *name ? name : "unnamed";
    if (OSRIsGeographic(srs)) {
        info.geographic = true;
        const double lat_north = gt[3], lat_south = gt[3] + gt[5] * double(height);
        info.centre_lat_deg = 0.5 * (lat_north + lat_south);
        const double span = std::abs(lat_north - lat_south), lat_max = std::max(std::abs(lat_north), std::abs(lat_south));
        if (!(lat_max <= kMaxGeographicLatDeg) || !(span <= kMaxGeographicSpanDeg))
            return "covers latitudes " + number(std::min(lat_north, lat_south)) + ".." + number(std::max(lat_north, lat_south)) +
                   " degrees in a geographic CRS (" + info.crs + "); accepted: a span of at most " +
                   number(kMaxGeographicSpanDeg) + " degrees within +-" + number(kMaxGeographicLatDeg) +
                   " (mapped flat around the centre latitude); reproject it first (gdalwarp -t_srs EPSG:<UTM zone>)";
        char* unit_name = nullptr;
        const double radians_per_unit = OSRGetAngularUnits(srs, &unit_name);
        const double degrees_per_unit = radians_per_unit * 180.0 / 3.14159265358979323846;
        OGRErr err = OGRERR_NONE;
        const double a = OSRGetSemiMajor(srs, &err);
        const double inv_f = OSRGetInvFlattening(srs, &err);
        geographicTexelMetres(std::abs(gt[1]) * degrees_per_unit, std::abs(gt[5]) * degrees_per_unit, info.centre_lat_deg,
                              a > 0.0 ? a : 6378137.0, inv_f > 0.0 ? 1.0 / inv_f : 0.0, info.texel_x_m, info.texel_z_m);
        return {};
    }
    if (OSRIsProjected(srs) || OSRIsLocal(srs)) {
        char* unit_name = nullptr;
        const double metres = OSRGetLinearUnits(srs, &unit_name);
        if (!(metres > 0.0)) return "has a CRS (" + info.crs + ") whose linear unit is not known; accepted: metres or feet";
        info.texel_x_m = std::abs(gt[1]) * metres;
        info.texel_z_m = std::abs(gt[5]) * metres;
        return {};
    }
    return "has a CRS (" + info.crs + ") that is neither geographic nor projected; accepted: a projected CRS (UTM, ...) or "
           "geographic latitude/longitude";
}

}  // namespace

// Named (not anonymous): DemRows::Impl holds them.
namespace dem_io {

// A band's samples as metres (its scale and offset, the vertical unit, the exaggeration); its
// nodata value and non-finite samples are holes.
struct SampleUnits {
    double k = 1.0, b = 0.0;
    float nodata = std::numeric_limits<float>::quiet_NaN();
    bool known(float v) const { return std::isfinite(v) && v != nodata; }
    float metres(float v) const { return float(b + k * double(v)); }
};

SampleUnits sampleUnits(GDALRasterBandH band, const DemInfo& info, double vertical_scale) {
    int has_nodata = 0, has_scale = 0, has_offset = 0;
    const double nodata = GDALGetRasterNoDataValue(band, &has_nodata);
    const double scale = GDALGetRasterScale(band, &has_scale), offset = GDALGetRasterOffset(band, &has_offset);
    SampleUnits u;
    if (has_nodata && std::isfinite(nodata) && std::abs(nodata) <= double(std::numeric_limits<float>::max()))
        u.nodata = float(nodata);
    u.k = (has_scale ? scale : 1.0) * info.metres_per_unit * vertical_scale;
    u.b = (has_offset ? offset : 0.0) * info.metres_per_unit * vertical_scale;
    return u;
}

// Where a sample of the file goes in the terrain's map: its rows run north to south, its
// columns west to east.
struct Orientation {
    int width = 0, height = 0;
    bool flip_x = false, flip_z = false;
    Orientation() = default;
    Orientation(int w, int h, const double gt[6]) : width(w), height(h), flip_x(gt[1] < 0.0), flip_z(gt[5] > 0.0) {}
    int fileRow(int z) const { return flip_z ? height - 1 - z : z; }
    int column(int x) const { return flip_x ? width - 1 - x : x; }
};

}  // namespace dem_io

namespace {

using dem_io::Orientation;
using dem_io::SampleUnits;
using dem_io::sampleUnits;


// Reads the band as metres into map (row 0 north, column 0 west) and marks the nodata cells.
std::string readHeights(GDALDatasetH ds, GDALRasterBandH band, const double gt[6], double vertical_scale, Heightmap& map,
                        std::vector<std::uint8_t>& known, DemInfo& info) {
    const int width = GDALGetRasterXSize(ds), height = GDALGetRasterYSize(ds);
    std::vector<float> raw(std::size_t(width) * std::size_t(height));
    if (GDALRasterIO(band, GF_Read, 0, 0, width, height, raw.data(), width, height, GDT_Float32, 0, 0) != CE_None)
        return "cannot read its samples (" + QuietErrors::last("the file is truncated or damaged") + ")";
    const SampleUnits units = sampleUnits(band, info, vertical_scale);
    const Orientation o(width, height, gt);
    map.width = width;
    map.height = height;
    map.samples.assign(raw.size(), 0.0f);
    known.assign(raw.size(), 0);
    for (int z = 0; z < height; ++z)
        for (int x = 0; x < width; ++x) {
            const float v = raw[std::size_t(o.fileRow(z)) * std::size_t(width) + std::size_t(x)];
            if (!units.known(v)) continue;
            const std::size_t to = std::size_t(z) * std::size_t(width) + std::size_t(o.column(x));
            map.samples[to] = units.metres(v);
            known[to] = 1;
        }
    return {};
}

std::string texelName(std::size_t index, int width) {
    return "texel (" + std::to_string(index % std::size_t(width)) + ", " + std::to_string(index / std::size_t(width)) + ")";
}

// The checks before any sample is read, in the order a user would fix them; fills info and gt.
std::string checkDem(GDALDatasetH ds, std::uint64_t max_bytes, DemInfo& info, double gt[6]) {
    GDALDriverH driver = GDALGetDatasetDriver(ds);
    info.driver = driver ? GDALGetDriverShortName(driver) : "unknown";
    const int bands = GDALGetRasterCount(ds);
    if (bands != 1)
        return "has " + std::to_string(bands) + " bands (" + info.driver + "); a DEM needs exactly 1 (elevation)";
    const int width = GDALGetRasterXSize(ds), height = GDALGetRasterYSize(ds);
    if (width < 2 || height < 2)
        return "is " + std::to_string(width) + "x" + std::to_string(height) + " samples; a DEM needs at least 2x2";
    // Georeferencing before the size: a plain image larger than a DEM may be (a gen-heightmap
    // TIFF) is told to be a heightmap, which vista terrain-cache reads a band of rows at a time.
    if (GDALGetGeoTransform(ds, gt) != CE_None)
        return "has no geotransform (no georeferencing, " + info.driver +
               "); a DEM needs one to give its texel spacing; use [terrain] heightmap with size_m for a plain image";
    const std::uint64_t bytes = std::uint64_t(width) * std::uint64_t(height) * sizeof(float);
    if (bytes > max_bytes)
        return "is " + std::to_string(width) + "x" + std::to_string(height) + " samples, " + std::to_string(bytes) +
               " bytes as floats, over the limit of " + std::to_string(max_bytes) + " bytes";
    for (int i = 0; i < 6; ++i)
        if (!std::isfinite(gt[i])) return "has a geotransform with a non-finite term; accepted: finite numbers";
    if (gt[2] != 0.0 || gt[4] != 0.0)
        return "has a rotated or sheared geotransform (row/column terms " + number(gt[2]) + ", " + number(gt[4]) +
               "); accepted: north-up rasters (those terms 0); warp it first (gdalwarp)";
    if (gt[1] == 0.0 || gt[5] == 0.0) return "has a geotransform with a zero texel size; accepted: non-zero sizes";
    if (std::string why = texelMetres(ds, gt, height, info); !why.empty()) return why;
    if (!(info.texel_x_m > 0.0) || !(info.texel_z_m > 0.0) || !std::isfinite(info.texel_x_m) || !std::isfinite(info.texel_z_m) ||
        info.texel_x_m * double(width - 1) > 1.0e7 || info.texel_z_m * double(height - 1) > 1.0e7)
        return "has texels of " + number(info.texel_x_m) + " x " + number(info.texel_z_m) +
               " m; accepted: an extent of at most 10,000 km ([terrain] size_m's range)";

    GDALRasterBandH band = GDALGetRasterBand(ds, 1);
    const std::string unit = GDALGetRasterUnitType(band) ? GDALGetRasterUnitType(band) : "";
    info.metres_per_unit = verticalUnit(unit);
    if (info.metres_per_unit == 0.0)
        return "has heights in '" + unit + "'; accepted vertical units: metres (or none), feet, US survey feet, km, cm";
    return {};
}

// The nodata count's verdict: "" when the map can be used (filled, when there are holes).
std::string nodataProblem(const DemInfo& info, std::size_t samples, std::size_t first, int width, DemNodata mode) {
    if (info.nodata == samples) return "has no data at all (every sample is nodata or not finite)";
    if (info.nodata > 0 && mode == DemNodata::Refuse)
        return "has " + std::to_string(info.nodata) + " nodata sample(s), the first at " + texelName(first, width) +
               "; [terrain] dem_nodata = refuse; accepted: fill (from their neighbours) or refuse";
    return {};
}

std::string heightRangeProblem(const DemInfo& info) {
    if (!(std::abs(info.min_m) <= kHeightLimitM) || !(std::abs(info.max_m) <= kHeightLimitM))
        return "has heights " + number(info.min_m) + ".." + number(info.max_m) + " m (after units and dem_vertical_scale); "
               "accepted: within +-" + number(kHeightLimitM) + " m";
    return {};
}

// A height in metres normalised to [0, 1] over the range, in double: the material bands are
// fractions of it.
float normalised(float metres, const DemInfo& info) {
    const double range = info.max_m - info.min_m;
    return range > 0.0 ? float((double(metres) - info.min_m) / range) : 0.0f;
}

// Everything after the file is open.
std::string readDem(GDALDatasetH ds, DemNodata nodata_mode, double vertical_scale, std::uint64_t max_bytes, Dem& dem) {
    DemInfo& info = dem.info;
    double gt[6];
    if (std::string why = checkDem(ds, max_bytes, info, gt); !why.empty()) return why;
    GDALRasterBandH band = GDALGetRasterBand(ds, 1);
    std::vector<std::uint8_t> known;
    if (std::string why = readHeights(ds, band, gt, vertical_scale, dem.map, known, info); !why.empty()) return why;

    std::size_t first = 0;
    for (std::size_t i = 0; i < known.size(); ++i)
        if (!known[i] && info.nodata++ == 0) first = i;
    if (std::string why = nodataProblem(info, known.size(), first, dem.map.width, nodata_mode); !why.empty()) return why;
    if (info.nodata > 0) fillFromNeighbours(dem.map.samples, known, dem.map.width, dem.map.height);

    auto [lo, hi] = std::minmax_element(dem.map.samples.begin(), dem.map.samples.end());
    info.min_m = *lo;
    info.max_m = *hi;
    if (std::string why = heightRangeProblem(info); !why.empty()) return why;
    for (float& v : dem.map.samples) v = normalised(v, info);
    return {};
}

Dem finish(Dem dem, const std::string& why, const std::string& name, InputErrors& errors) {
    if (why.empty()) return dem;
    errors.push_back({name, 0, why});
    return {};
}

Dem openAndRead(const std::string& gdal_path, const std::string& name, DemNodata nodata, double vertical_scale,
                InputErrors& errors, std::uint64_t max_bytes, const std::vector<std::string>& drivers) {
    initGdal();
    QuietErrors quiet;
    std::vector<const char*> allowed;
    for (const std::string& d : drivers) allowed.push_back(d.c_str());
    allowed.push_back(nullptr);
    Dataset ds(GDALOpenEx(gdal_path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY, drivers.empty() ? nullptr : allowed.data(),
                          nullptr, nullptr));
    Dem dem;
    if (!ds.h)
        return finish({}, "cannot be read as a DEM by GDAL (" + QuietErrors::last("not a raster format GDAL knows") + ")", name,
                      errors);
    std::string why = readDem(ds.h, nodata, vertical_scale, max_bytes, dem);
    return finish(std::move(dem), why, name, errors);
}

}  // namespace

void geographicTexelMetres(double dlon_deg, double dlat_deg, double lat_deg, double a_m, double f, double& x_m,
                           double& z_m) {
    const double rad = 3.14159265358979323846 / 180.0, phi = lat_deg * rad;
    const double e2 = f * (2.0 - f), s = std::sin(phi), w = 1.0 - e2 * s * s;
    const double n = a_m / std::sqrt(w);               // prime vertical radius of curvature
    const double m = a_m * (1.0 - e2) / (w * std::sqrt(w));  // meridional radius of curvature
    x_m = dlon_deg * rad * n * std::cos(phi);
    z_m = dlat_deg * rad * m;
}

bool fillFromNeighbours(std::vector<float>& samples, std::vector<std::uint8_t>& known, int width, int height) {
    const std::size_t w = std::size_t(width);
    std::vector<std::size_t> ring, next;
    auto neighbours = [&](std::size_t i, auto&& fn) {
        const std::size_t x = i % w, z = i / w;
        if (x > 0) fn(i - 1);
        if (x + 1 < w) fn(i + 1);
        if (z > 0) fn(i - w);
        if (z + 1 < std::size_t(height)) fn(i + w);
    };
    // The first ring: unknown cells next to a known one.
    std::vector<std::uint8_t> queued(known.size(), 0);
    for (std::size_t i = 0; i < known.size(); ++i)
        if (!known[i]) {
            bool edge = false;
            neighbours(i, [&](std::size_t j) { edge = edge || known[j]; });
            if (edge) {
                ring.push_back(i);
                queued[i] = 1;
            }
        }
    if (ring.empty()) return std::find(known.begin(), known.end(), 0) == known.end();
    while (!ring.empty()) {
        // Means first, then mark: a ring's cells see only the rings before it, so the result
        // does not depend on the order within a ring.
        std::vector<float> value(ring.size());
        for (std::size_t r = 0; r < ring.size(); ++r) {
            double sum = 0.0;
            int count = 0;
            neighbours(ring[r], [&](std::size_t j) {
                if (known[j] == 1) {
                    sum += samples[j];
                    ++count;
                }
            });
            value[r] = float(sum / count);
        }
        next.clear();
        for (std::size_t r = 0; r < ring.size(); ++r) {
            samples[ring[r]] = value[r];
            known[ring[r]] = 1;
        }
        for (std::size_t i : ring)
            neighbours(i, [&](std::size_t j) {
                if (!known[j] && !queued[j]) {
                    queued[j] = 1;
                    next.push_back(j);
                }
            });
        ring.swap(next);
    }
    return true;
}

TerrainMapping demMapping(const DemInfo& info, int width, int height) {
    TerrainMapping m;
    m.size_m = info.texel_x_m * double(width - 1);
    m.size_z_m = info.texel_z_m * double(height - 1);
    m.height_offset_m = info.min_m;
    m.height_scale_m = info.max_m - info.min_m;
    m.width = width;
    m.height = height;
    return m;
}

Dem loadDem(const std::filesystem::path& file, DemNodata nodata, double vertical_scale, InputErrors& errors,
            std::uint64_t max_bytes) {
    // A FIFO, a directory or a missing file is refused before GDAL sees it (a VRT's sources are GDAL's to check).
    if (std::string why = inputFileProblem(file, std::numeric_limits<std::uintmax_t>::max()); !why.empty()) {
        errors.push_back({file.string(), 0, why});
        return {};
    }
    ++whole_loads;
    return openAndRead(file.string(), file.string(), nodata, vertical_scale, errors, max_bytes, {});
}

std::int64_t wholeDemLoads() { return whole_loads.load(); }

Dem decodeDem(std::span<const unsigned char> bytes, const std::string& name, DemNodata nodata, double vertical_scale,
              InputErrors& errors, std::uint64_t max_bytes, const std::vector<std::string>& drivers) {
    if (bytes.empty()) {
        errors.push_back({name, 0, "is empty; a DEM needs a raster file"});
        return {};
    }
    initGdal();
    static std::atomic<unsigned> counter{0};
    // GDAL's in-memory file system; the buffer is not copied and stays ours (bTakeOwnership false).
    const std::string path = "/vsimem/vista_dem_" + std::to_string(counter++) + "/" +
                             std::filesystem::path(name).filename().string();
    VSILFILE* f = VSIFileFromMemBuffer(path.c_str(), const_cast<GByte*>(reinterpret_cast<const GByte*>(bytes.data())),
                                       vsi_l_offset(bytes.size()), FALSE);
    if (!f) {
        errors.push_back({name, 0, "cannot be held in memory for GDAL"});
        return {};
    }
    VSIFCloseL(f);
    Dem dem = openAndRead(path, name, nodata, vertical_scale, errors, max_bytes, drivers);
    VSIUnlink(path.c_str());
    return dem;
}

struct DemRows::Impl {
    std::string name;
    Dataset ds{nullptr};
    GDALRasterBandH band = nullptr;
    DemInfo info;
    SampleUnits units;
    Orientation orientation;
    std::vector<float> raw;  // one row of the file

    // Row fz of the file as stored; "" or why.
    std::string readFileRow(int fz) {
        QuietErrors quiet;
        if (GDALRasterIO(band, GF_Read, 0, fz, orientation.width, 1, raw.data(), orientation.width, 1, GDT_Float32, 0, 0) !=
            CE_None)
            return name + ": cannot read row " + std::to_string(fz) + " (" +
                   QuietErrors::last("the file is truncated or damaged") + ")";
        return {};
    }
};

DemRows::DemRows() : impl_(std::make_unique<Impl>()) {}
DemRows::~DemRows() = default;
int DemRows::width() const { return impl_->orientation.width; }
int DemRows::height() const { return impl_->orientation.height; }
const DemInfo& DemRows::info() const { return impl_->info; }

std::unique_ptr<DemRows> DemRows::open(const std::filesystem::path& file, DemNodata nodata, double vertical_scale,
                                       InputErrors& errors, bool& fill_whole) {
    fill_whole = false;
    if (std::string why = inputFileProblem(file, std::numeric_limits<std::uintmax_t>::max()); !why.empty()) {
        errors.push_back({file.string(), 0, why});
        return nullptr;
    }
    initGdal();
    std::unique_ptr<DemRows> rows(new DemRows());
    Impl& d = *rows->impl_;
    d.name = file.string();
    auto fail = [&](const std::string& why) {
        errors.push_back({d.name, 0, why});
        return nullptr;
    };
    double gt[6];
    {
        QuietErrors quiet;
        d.ds.h = GDALOpenEx(d.name.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY, nullptr, nullptr, nullptr);
        if (!d.ds.h) return fail("cannot be read as a DEM by GDAL (" + QuietErrors::last("not a raster format GDAL knows") + ")");
        if (std::string why = checkDem(d.ds.h, std::numeric_limits<std::uint64_t>::max(), d.info, gt); !why.empty())
            return fail(why);
    }
    d.band = GDALGetRasterBand(d.ds.h, 1);
    d.units = sampleUnits(d.band, d.info, vertical_scale);
    d.orientation = Orientation(GDALGetRasterXSize(d.ds.h), GDALGetRasterYSize(d.ds.h), gt);
    const Orientation& o = d.orientation;
    d.raw.resize(std::size_t(o.width));
    // The first pass: the height range and the nodata cells (the first in the map's order).
    float lo = std::numeric_limits<float>::infinity(), hi = -lo;
    std::size_t first = std::numeric_limits<std::size_t>::max();
    for (int fz = 0; fz < o.height; ++fz) {
        if (std::string why = d.readFileRow(fz); !why.empty()) return fail(why.substr(d.name.size() + 2));
        const std::size_t row_start = std::size_t(o.flip_z ? o.height - 1 - fz : fz) * std::size_t(o.width);
        for (int x = 0; x < o.width; ++x) {
            const float v = d.raw[std::size_t(x)];
            if (!d.units.known(v)) {
                ++d.info.nodata;
                first = std::min(first, row_start + std::size_t(o.column(x)));
                continue;
            }
            const float m = d.units.metres(v);
            lo = std::min(lo, m);
            hi = std::max(hi, m);
        }
    }
    const std::size_t samples = std::size_t(o.width) * std::size_t(o.height);
    if (std::string why = nodataProblem(d.info, samples, first, o.width, nodata); !why.empty()) return fail(why);
    if (d.info.nodata > 0) {
        fill_whole = true;
        return nullptr;
    }
    d.info.min_m = lo;
    d.info.max_m = hi;
    if (std::string why = heightRangeProblem(d.info); !why.empty()) return fail(why);
    return rows;
}

std::string DemRows::read(int z, float* row) {
    Impl& d = *impl_;
    const Orientation& o = d.orientation;
    if (std::string why = d.readFileRow(o.fileRow(z)); !why.empty()) return why;
    for (int x = 0; x < o.width; ++x) {
        const float v = d.raw[std::size_t(x)];
        if (!d.units.known(v))
            return d.name + ": " + texelName(std::size_t(z) * std::size_t(o.width) + std::size_t(o.column(x)), o.width) +
                   " has no data on the second reading (the file changed while it was read)";
        row[o.column(x)] = normalised(d.units.metres(v), d.info);
    }
    return {};
}

}  // namespace vista
