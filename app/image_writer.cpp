// PNG/EXR output: encoded in memory (an OpenImageIO IOProxy), then written atomically, so a
// full disk is a checked write error rather than a truncated file that OpenImageIO's own
// buffered writer would report as success.
#include "app/image_writer.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

namespace vista {
namespace {

std::string writeImage(const std::filesystem::path& file, const char* format, int width, int height,
                       OIIO::TypeDesc type, const void* rgba, std::size_t pixel_bytes, bool force) {
    auto out = OIIO::ImageOutput::create(format);
    if (!out) return file.string() + ": OpenImageIO has no " + format + " writer (" + OIIO::geterror() + ")";
    std::vector<unsigned char> bytes;
    OIIO::Filesystem::IOVecOutput memory(bytes);
    out->set_ioproxy(&memory);
    OIIO::ImageSpec spec(width, height, 3, type);
    if (type == OIIO::TypeDesc::HALF) spec.attribute("compression", "zip");
    if (!out->open(file.string(), spec)) return file.string() + ": " + out->geterror();
    // Source pixels are RGBA: stride over the alpha channel.
    bool ok = out->write_image(type, rgba, OIIO::stride_t(pixel_bytes));
    ok = out->close() && ok;
    if (!ok) return file.string() + ": " + out->geterror();
    return writeFileAtomic(file, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()), force);
}

}  // namespace

std::string writePng(const std::filesystem::path& file, int width, int height, const std::vector<unsigned char>& rgba,
                     bool force) {
    return writeImage(file, "png", width, height, OIIO::TypeDesc::UINT8, rgba.data(), 4, force);
}

std::string writeExr(const std::filesystem::path& file, int width, int height, const std::vector<std::uint16_t>& rgba,
                     bool force) {
    return writeImage(file, "openexr", width, height, OIIO::TypeDesc::HALF, rgba.data(), 4 * sizeof(std::uint16_t), force);
}

}  // namespace vista
