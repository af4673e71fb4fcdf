// libFuzzer target: DEMs through GDAL from memory (terrain/dem.h decodeDem). The first byte
// picks the format (GeoTIFF, ESRI ASCII grid, SRTM .hgt), the second the nodata mode, the rest
// is the file. Any bytes must be refused with a reason or give a map whose size matches its
// samples, all in [0, 1], with a finite positive texel spacing and height range, without
// crashing or allocating past the limit. Only those three drivers may open the bytes: a VRT
// could name any file on the machine.
#include "terrain/dem.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 3) return 0;
    static const char* const kNames[] = {"fuzz.tif", "fuzz.asc", "N46E007.hgt"};
    static const char* const kDrivers[] = {"GTiff", "AAIGrid", "SRTMHGT"};
    const int format = data[0] % 3;
    const vista::DemNodata nodata = data[1] & 1 ? vista::DemNodata::Refuse : vista::DemNodata::Fill;
    const std::span<const unsigned char> bytes(data + 2, size - 2);
    vista::InputErrors errors;
    // 16 MiB of samples at most, so a header claiming a huge raster is refused, never allocated.
    const vista::Dem dem = vista::decodeDem(bytes, kNames[format], nodata, 1.0, errors, 16u << 20, {kDrivers[format]});
    if (errors.empty()) {
        const vista::Heightmap& map = dem.map;
        if (map.width < 2 || map.height < 2) std::abort();
        if (map.samples.size() != std::size_t(map.width) * std::size_t(map.height)) std::abort();
        for (float v : map.samples)
            if (!(v >= 0.0f && v <= 1.0f)) std::abort();
        if (!(dem.info.texel_x_m > 0.0) || !(dem.info.texel_z_m > 0.0) || !std::isfinite(dem.info.texel_x_m) ||
            !std::isfinite(dem.info.texel_z_m) || !(dem.info.max_m >= dem.info.min_m))
            std::abort();
    } else if (!dem.map.samples.empty() || errors.front().message.empty()) {
        std::abort();
    }
    return 0;
}
