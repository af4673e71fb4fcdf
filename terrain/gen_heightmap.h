// `vista gen-heightmap`: writes the procedural island (generateIsland) to a 16-bit PNG, a float
// EXR or, for maps larger than memory, a float TIFF written row by row (generateIslandRows).
#pragma once

#include <cstdint>
#include <filesystem>

namespace vista {

// The largest --size: 65,537 = 2^16 + 1 samples a side (4 m texels over 262 km; a 17.2 GB
// float TIFF, about 48 GB of tile cache at tile 32). Beyond it a map's samples no longer fit
// 32-bit counts of cache tiles and quadtree nodes with room to spare, and the CPU time (an hour
// per 65k map on two cores) is the practical limit anyway.
inline constexpr int kMaxGenSize = 65537;
// .png and .exr are encoded in memory: up to this size (the map and its encoding, ~2 GB).
inline constexpr int kMaxGenSizeInMemory = 16385;

// Generates IslandParams{size, seed} and writes it to `out` (.png: 16-bit grey, .exr: float,
// .tif/.tiff: float, written a row at a time through a scratch file of size² floats next to it,
// so the map is never held: any size up to kMaxGenSize). Prints one line saying what was written
// and returns 0; on bad input (size outside 2..kMaxGenSize, or over kMaxGenSizeInMemory for .png
// and .exr, unknown extension, unwritable output) prints "vista: <reason>" to stderr and returns 2.
// force: replace an existing --out file (refused otherwise).
int runGenHeightmap(int size, std::uint32_t seed, const std::filesystem::path& out, bool force = false);

}  // namespace vista
