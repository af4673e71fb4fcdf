// Heightmaps: loading (8/16-bit PNG, TIFF, float EXR through OpenImageIO; raw .r16 with an
// explicit size), validation with errors that name the file and the first bad texel, and
// a deterministic island generator (fBm + ridged noise, island falloff, erosion).
#pragma once

#include "config/input_error.h"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace vista {

// Samples in row-major order, row z = 0 first (north, -z in the world), x = 0 first (west).
// Integer formats are normalised to [0, 1]; float formats keep their values.
struct Heightmap {
    int width = 0, height = 0;
    std::vector<float> samples;

    float at(int x, int z) const { return samples[std::size_t(z) * std::size_t(width) + std::size_t(x)]; }
    // Bilinear sample at continuous texel coordinates, clamped to the edges.
    float sample(double x, double z) const;
};

// Loads and validates. raw_width/raw_height are required for .r16 (little-endian uint16)
// and ignored otherwise. On failure returns an empty Heightmap and appends errors (file,
// what is wrong, what is accepted). max_bytes bounds the memory a heightmap may take.
Heightmap loadHeightmap(const std::filesystem::path& file, int raw_width, int raw_height, InputErrors& errors,
                        std::uint64_t max_bytes = std::uint64_t(4) << 30);
// The same for a file's bytes held in memory (the fuzz target and tests): name's extension picks
// the format as above (.r16 raw, otherwise an image OpenImageIO decodes from memory), and errors
// name it. Every size and channel check runs before samples are allocated.
Heightmap decodeHeightmap(std::span<const unsigned char> bytes, const std::string& name, int raw_width, int raw_height,
                          InputErrors& errors, std::uint64_t max_bytes = std::uint64_t(4) << 30);

// Terrain heights, metres (offset + sample * scale), must lie within +-kHeightLimitM: the
// atmosphere ends 100 km up, and beyond it a height is a broken file, not terrain (a sample
// of 1e30 drew nothing at all).
constexpr double kHeightLimitM = 100000.0;
// Appends an error naming file when a height lies outside that range; true when all fit.
bool checkHeightRange(const Heightmap& map, double scale_m, double offset_m, const std::string& file, InputErrors& errors);
// The same for row z of a map read a row at a time (width samples): "" when all fit, else what
// is wrong (the first such texel, how many in that row).
std::string heightRowProblem(const float* row, int width, int z, double scale_m, double offset_m);

// Whether file is a raw .r16 (little-endian uint16 samples; its size comes from raw_width/raw_height).
bool isRawHeightmap(const std::filesystem::path& file);

// Tests: how many times loadHeightmap has run in this process (each holds a whole map), so a
// test can show that a path reads a map a band of rows at a time instead.
std::int64_t wholeHeightmapLoads();

// Writes a 16-bit single-channel PNG of values clamped to [0, 1], atomically (config/file_io.h);
// force: replace an existing file (the default for library callers such as tests that
// regenerate a map; `vista gen-heightmap` passes its --force). "" on success, else why.
std::string saveHeightmapPng16(const std::filesystem::path& file, const Heightmap& map, bool force = true);
// Writes a single-channel float EXR ("Y") the same way.
std::string saveHeightmapExr(const std::filesystem::path& file, const Heightmap& map, bool force = true);

struct IslandParams {
    int size = 1025;          // samples per side (any size >= 2; 2^n + 1 suits the quadtree)
    std::uint32_t seed = 1;
    int octaves = 9;
    float ridge = 0.45f;      // 0: plain fBm, 1: ridged noise only
    float falloff = 0.72f;    // radius (fraction of half the map) where the island meets the sea
    int erosion_passes = 4;   // thermal erosion iterations
};

// A deterministic island in [0, 1]: sea floor near 0, shoreline around 0.12, peaks near 1.
// Same params, same bits on every machine.
Heightmap generateIsland(const IslandParams& params);

// The same island without holding it (maps larger than memory, `vista gen-heightmap --size
// 65537`): the same bits as generateIsland, handed to row(z, samples) for z = 0, 1, ... in order
// (its non-empty return stops the run and is returned). The raw and eroded heights pass through
// scratch_file (size² floats; created, unlinked at once, so it never outlives the process), and
// a window of rows through memory. progress(0..1) now and then. "" on success, else why.
std::string generateIslandRows(const IslandParams& params, const std::filesystem::path& scratch_file,
                               const std::function<std::string(int z, const float* samples)>& row,
                               const std::function<void(double)>& progress = {});

}  // namespace vista
