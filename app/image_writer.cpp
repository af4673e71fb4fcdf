// PNG/EXR output with atomic rename.
#include "app/image_writer.h"

#include <OpenImageIO/imageio.h>

namespace vista {
namespace {

std::string writeImage(const std::filesystem::path& file, const char* format, int width, int height,
                       OIIO::TypeDesc type, const void* rgba, std::size_t pixel_bytes) {
    std::filesystem::path tmp = file;
    tmp += ".part";
    auto out = OIIO::ImageOutput::create(format);
    if (!out) return file.string() + ": OpenImageIO has no " + format + " writer (" + OIIO::geterror() + ")";
    OIIO::ImageSpec spec(width, height, 3, type);
    if (type == OIIO::TypeDesc::HALF) spec.attribute("compression", "zip");
    if (!out->open(tmp.string(), spec)) return file.string() + ": " + out->geterror();
    // Source pixels are RGBA: stride over the alpha channel.
    bool ok = out->write_image(type, rgba, OIIO::stride_t(pixel_bytes));
    ok = out->close() && ok;
    if (!ok) {
        std::filesystem::remove(tmp);
        return file.string() + ": " + out->geterror();
    }
    std::error_code ec;
    std::filesystem::rename(tmp, file, ec);
    if (ec) return file.string() + ": cannot rename from " + tmp.string() + " (" + ec.message() + ")";
    return {};
}

}  // namespace

std::string writePng(const std::filesystem::path& file, int width, int height, const std::vector<unsigned char>& rgba) {
    return writeImage(file, "png", width, height, OIIO::TypeDesc::UINT8, rgba.data(), 4);
}

std::string writeExr(const std::filesystem::path& file, int width, int height, const std::vector<std::uint16_t>& rgba) {
    return writeImage(file, "openexr", width, height, OIIO::TypeDesc::HALF, rgba.data(), 4 * sizeof(std::uint16_t));
}

}  // namespace vista
