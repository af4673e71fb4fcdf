// A single-channel heightmap image read a band of rows at a time (OpenImageIO scanlines; a raw
// .r16 a row at a time), so a
// map larger than memory (a `gen-heightmap --size 65537` TIFF) becomes a tile cache without
// ever being held whole (`vista terrain-cache`, terrain/tile_cache.h).
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace vista {

class HeightmapRows {
public:
    // Opens file when it is an image of one channel, one subimage, not EXR (EXR headers are
    // checked in memory by loadHeightmap), or a raw .r16 of raw_width x raw_height samples (its
    // size checked); null with why otherwise (then loadHeightmap reads it, or names the problem).
    static std::unique_ptr<HeightmapRows> open(const std::filesystem::path& file, std::string& why, int raw_width = 0,
                                               int raw_height = 0);
    ~HeightmapRows();
    HeightmapRows(const HeightmapRows&) = delete;
    HeightmapRows& operator=(const HeightmapRows&) = delete;

    int width() const { return width_; }
    int height() const { return height_; }
    // Row z as loadHeightmap's samples (integer formats normalised to [0, 1]); rows come in
    // order (z = 0, 1, ...). "" on success, else why (naming the file and, for a non-finite
    // sample, its texel).
    std::string read(int z, float* row);

private:
    HeightmapRows() = default;
    struct Input;
    std::unique_ptr<Input> in_;
    std::string name_;
    int width_ = 0, height_ = 0;
    int band_first_ = 0, band_rows_ = 0;
    std::vector<float> band_;
};

}  // namespace vista
