// HeightmapRows: OpenImageIO's scanline reads, 64 rows at a time, with loadHeightmap's checks
// (one 2D grey image, finite samples), or a raw .r16's rows.
#include "terrain/heightmap_rows.h"

#include "terrain/heightmap.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>

namespace vista {

struct HeightmapRows::Input {
    std::unique_ptr<OIIO::ImageInput> image;
    std::ifstream raw;  // a .r16's little-endian uint16 samples, when image is null
    std::vector<unsigned char> bytes;
};

std::unique_ptr<HeightmapRows> HeightmapRows::open(const std::filesystem::path& file, std::string& why, int raw_width,
                                                   int raw_height) {
    std::string ext = file.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (ext == ".exr") {
        why = file.string() + ": read whole (" + ext + ")";
        return nullptr;
    }
    if (isRawHeightmap(file)) {
        // The size as loadHeightmap checks it (which names a mismatch when this declines).
        std::error_code ec;
        const std::uintmax_t size = std::filesystem::file_size(file, ec);
        if (ec || raw_width < 2 || raw_height < 2 || size != std::uintmax_t(raw_width) * std::uintmax_t(raw_height) * 2) {
            why = file.string() + ": not a raw .r16 of raw_width x raw_height samples";
            return nullptr;
        }
        std::unique_ptr<HeightmapRows> rows(new HeightmapRows);
        rows->name_ = file.string();
        rows->width_ = raw_width;
        rows->height_ = raw_height;
        rows->in_ = std::make_unique<Input>();
        rows->in_->raw.open(file, std::ios::binary);
        if (!rows->in_->raw) {
            why = file.string() + ": cannot be opened";
            return nullptr;
        }
        return rows;
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
    rows->in_ = std::make_unique<Input>();
    rows->in_->image = std::move(image);
    return rows;
}

HeightmapRows::~HeightmapRows() {
    if (in_ && in_->image) in_->image->close();
}

std::string HeightmapRows::read(int z, float* row) {
    if (!in_->image) {  // .r16: as loadHeightmap's decodeRaw16
        std::vector<unsigned char>& b = in_->bytes;
        b.resize(std::size_t(width_) * 2);
        in_->raw.seekg(std::streamoff(z) * std::streamoff(b.size()));
        if (!in_->raw.read(reinterpret_cast<char*>(b.data()), std::streamsize(b.size())))
            return name_ + ": cannot read row " + std::to_string(z) + " (the file is truncated or damaged)";
        for (int x = 0; x < width_; ++x)
            row[x] = float(unsigned(b[2 * std::size_t(x)]) | unsigned(b[2 * std::size_t(x) + 1]) << 8) / 65535.0f;
        return {};
    }
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
