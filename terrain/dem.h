// Digital elevation models through GDAL ([terrain] dem): GeoTIFF, SRTM .hgt, ESRI ASCII grids,
// VRT mosaics and whatever else GDAL reads as a single-band raster. The texel spacing in metres
// comes from the geotransform, heights from the band's units, scale and offset, and nodata cells
// are filled from their neighbours or refused. Errors name the file and what is accepted.
#pragma once

#include "config/input_error.h"
#include "terrain/cdlod.h"
#include "terrain/heightmap.h"
#include "terrain/terrain_settings.h"

#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace vista {

struct DemInfo {
    std::string driver;              // GDAL's short name (GTiff, SRTMHGT, AAIGrid, VRT, ...)
    std::string crs;                 // the CRS's name, or "none" (units taken as metres)
    bool geographic = false;         // degrees, mapped to metres around centre_lat_deg
    double centre_lat_deg = 0.0;     // geographic only
    double texel_x_m = 0.0, texel_z_m = 0.0;  // spacing between samples, metres
    double min_m = 0.0, max_m = 0.0;          // height range, metres (after units and dem_vertical_scale)
    double metres_per_unit = 1.0;    // vertical unit of the band
    std::size_t nodata = 0;          // cells that had no data (filled, when dem_nodata = fill)
};

// A DEM as the terrain takes it: samples normalised to [0, 1] over [min_m, max_m], so the
// material bands (sand_top, grass_top, ...) are fractions of the data's height range.
struct Dem {
    Heightmap map;
    DemInfo info;
};

// Reads and checks file; on failure returns an empty map and appends errors (file, reason,
// what is accepted). vertical_scale multiplies heights (exaggeration). max_bytes bounds the
// samples' memory (as floats), checked before any is read.
Dem loadDem(const std::filesystem::path& file, DemNodata nodata, double vertical_scale, InputErrors& errors,
            std::uint64_t max_bytes = std::uint64_t(4) << 30);
// Tests: how many times loadDem has read a DEM in this process (each holds it whole), so a test
// can show that a path reads it a row at a time instead (DemRows).
std::int64_t wholeDemLoads();
// The same for a file's bytes held in memory (the fuzz target): name's extension is kept so
// drivers that go by it see it; only the drivers listed may open it (empty: any).
Dem decodeDem(std::span<const unsigned char> bytes, const std::string& name, DemNodata nodata, double vertical_scale,
              InputErrors& errors, std::uint64_t max_bytes, const std::vector<std::string>& drivers);

// A DEM read a row at a time, so that the tile cache of a DEM larger than memory is built
// without holding it (vista terrain-cache, a streamed terrain's first load): open() makes
// loadDem's checks and a first pass over the rows for the height range and the nodata count;
// read() gives the rows as loadDem's samples, bit for bit. A DEM whose nodata cells are to be
// filled is not read this way (the fill spreads across the map): open() returns null without
// an error and sets fill_whole, and the caller loads it whole.
class DemRows {
public:
    static std::unique_ptr<DemRows> open(const std::filesystem::path& file, DemNodata nodata, double vertical_scale,
                                         InputErrors& errors, bool& fill_whole);
    ~DemRows();
    DemRows(const DemRows&) = delete;
    DemRows& operator=(const DemRows&) = delete;

    int width() const;
    int height() const;
    const DemInfo& info() const;
    // Row z (0 north) into row (width samples, normalised as loadDem's). "" on success, else why,
    // naming the file.
    std::string read(int z, float* row);

private:
    DemRows();
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// Fills the cells where known is 0 from their neighbours, ring by ring inwards ("onion
// peeling"): each cell of a ring takes the mean of its already known 4-neighbours. Every cell
// is reached when any is known; returns false when none is.
bool fillFromNeighbours(std::vector<float>& samples, std::vector<std::uint8_t>& known, int width, int height);

// Metres between two samples dlon_deg / dlat_deg apart at latitude lat_deg on an ellipsoid
// (semi-major axis a_m, flattening f): the prime-vertical radius times cos(lat) in x, the
// meridional radius in z. Exact for an infinitesimal step; a DEM uses its centre latitude.
void geographicTexelMetres(double dlon_deg, double dlat_deg, double lat_deg, double a_m, double f, double& x_m,
                           double& z_m);

// The mapping of a DEM's terrain: extents from the spacing, heights from the range.
TerrainMapping demMapping(const DemInfo& info, int width, int height);

}  // namespace vista
