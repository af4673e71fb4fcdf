// `vista gen-heightmap`: generates the procedural island and writes it as a 16-bit PNG or a
// float EXR, reporting what it wrote.
#include "terrain/gen_heightmap.h"

#include "terrain/heightmap.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <string>

namespace vista {
namespace {

// Single-channel float EXR, written under a temporary name and renamed like every output.
std::string saveHeightmapExr(const std::filesystem::path& file, const Heightmap& map) {
    std::filesystem::path tmp = file;
    tmp += ".part";
    auto out = OIIO::ImageOutput::create("openexr");
    if (!out) return file.string() + ": OpenImageIO has no openexr writer (" + OIIO::geterror() + ")";
    OIIO::ImageSpec spec(map.width, map.height, 1, OIIO::TypeDesc::FLOAT);
    spec.channelnames = {"Y"};
    spec.attribute("compression", "zip");
    if (!out->open(tmp.string(), spec)) return file.string() + ": " + out->geterror();
    bool ok = out->write_image(OIIO::TypeDesc::FLOAT, map.samples.data());
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

int fail(const std::string& why) {
    std::fprintf(stderr, "vista: %s\n", why.c_str());
    return 2;
}

}  // namespace

int runGenHeightmap(int size, std::uint32_t seed, const std::filesystem::path& out) {
    if (size < 2 || size > 16385) return fail("--size " + std::to_string(size) + " is out of range; accepted: 2..16385");
    std::string ext = out.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (ext != ".png" && ext != ".exr")
        return fail(out.string() + ": unknown heightmap format \"" + ext + "\"; accepted: .png (16-bit), .exr (float)");
    // Catch a missing output directory before spending seconds generating.
    std::filesystem::path dir = out.parent_path().empty() ? std::filesystem::path(".") : out.parent_path();
    std::error_code ec;
    if (!std::filesystem::is_directory(dir, ec))
        return fail(out.string() + ": output directory " + dir.string() + " does not exist");

    auto start = std::chrono::steady_clock::now();
    Heightmap map = generateIsland(IslandParams{size, seed});
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    std::string why = ext == ".exr" ? saveHeightmapExr(out, map) : saveHeightmapPng16(out, map);
    if (!why.empty()) return fail(why);
    auto [lo, hi] = std::minmax_element(map.samples.begin(), map.samples.end());
    std::size_t land = std::size_t(std::count_if(map.samples.begin(), map.samples.end(), [](float v) { return v >= 0.12f; }));
    std::printf("wrote %s: %dx%d island, seed %u, min %.4f max %.4f, land %.1f%% (above 0.12), generated in %.2f s\n",
                out.string().c_str(), size, size, seed, double(*lo), double(*hi), 100.0 * double(land) / double(map.samples.size()),
                seconds);
    return 0;
}

}  // namespace vista
