// `vista gen-heightmap`: writes the procedural island (generateIsland) to a 16-bit PNG or a
// float EXR, e.g. to regenerate data/heightmaps/island.png.
#pragma once

#include <cstdint>
#include <filesystem>

namespace vista {

// Generates IslandParams{size, seed} and writes it to `out` (.png: 16-bit grey, .exr: float).
// Prints one line saying what was written and returns 0; on bad input (size outside
// 2..16385, unknown extension, unwritable output) prints "vista: <reason>" to stderr and
// returns 2.
// force: replace an existing --out file (refused otherwise).
int runGenHeightmap(int size, std::uint32_t seed, const std::filesystem::path& out, bool force = false);

}  // namespace vista
