// HeightmapRows: OpenImageIO's scanline reads, 64 rows at a time, with loadHeightmap's checks
// (one 2D grey image, finite samples).
#include "terrain/heightmap_rows.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cctype>
#include <cmath>

namespace vista {

struct HeightmapRows::Input {
    std::unique_ptr<OIIO::ImageInput> image;
};

std::unique_ptr<HeightmapRows> HeightmapRows::open(const std::filesystem::path& file, std::string& why) {
    std::string ext = file.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (ext == ".exr" || ext == ".r16") {
        why = file.string() + ": read whole (" + ext + ")";
        return nullptr;
    }
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    auto image = OIIO::ImageInput::open(file.string(), &config);
    if (!image) {
        why = file.string() + ": cannot read (" + OIIO::geterror() + ")";
        return nullptr;
    }
    const OIIO::ImageSpec& spec = image->spec();
    if (spec.nchannels != 1 || spec.depth > 1 || spec.width < 2 || spec.height < 2) {
        why = file.string() + ": not one channel of at least 2x2 samples";
        return nullptr;
    }
    std::unique_ptr<HeightmapRows> rows(new HeightmapRows);
    rows->name_ = file.string();
    rows->width_ = spec.width;
    rows->height_ = spec.height;
    rows->in_ = std::make_unique<Input>(Input{std::move(image)});
    return rows;
}

HeightmapRows::~HeightmapRows() {
    if (in_ && in_->image) in_->image->close();
}

std::string HeightmapRows::read(int z, float* row) {
    constexpr int kBand = 64;
    if (z < band_first_ || z >= band_first_ + band_rows_) {
        band_first_ = z;
        band_rows_ = std::min(kBand, height_ - z);
        band_.resize(std::size_t(band_rows_) * std::size_t(width_));
        OIIO::ImageInput& in = *in_->image;
        // has_error: some readers (TIFF) fill a truncated file's missing rows with 0 and still return true.
        if (!in.read_scanlines(0, 0, z, z + band_rows_, 0, 0, 1, OIIO::TypeDesc::FLOAT, band_.data()) || in.has_error()) {
            const std::string e = in.geterror();
            band_rows_ = 0;
            return name_ + ": cannot read (" + (e.empty() ? "the file is truncated or damaged" : e) + ")";
        }
    }
    const float* from = &band_[std::size_t(z - band_first_) * std::size_t(width_)];
    for (int x = 0; x < width_; ++x) {
        if (!std::isfinite(from[x]))
            return name_ + ": has a non-finite sample (" + std::to_string(from[x]) + ") at texel (" + std::to_string(x) + ", " +
                   std::to_string(z) + "); heights must be finite numbers";
        row[x] = from[x];
    }
    return {};
}

}  // namespace vista
