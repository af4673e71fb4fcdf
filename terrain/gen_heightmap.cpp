// `vista gen-heightmap`: generates the procedural island and writes it as a 16-bit PNG or a
// float EXR, reporting what it wrote.
#include "terrain/gen_heightmap.h"

#include "terrain/heightmap.h"
#include "config/file_io.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <string>

namespace vista {
namespace {

int fail(const std::string& why, int code = 2) {
    std::fprintf(stderr, "vista: %s\n", why.c_str());
    return code;
}

}  // namespace

int runGenHeightmap(int size, std::uint32_t seed, const std::filesystem::path& out, bool force) {
    if (size < 2 || size > 16385) return fail("--size " + std::to_string(size) + " is out of range; accepted: 2..16385");
    std::string ext = out.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (ext != ".png" && ext != ".exr")
        return fail(out.string() + ": unknown heightmap format \"" + ext + "\"; accepted: .png (16-bit), .exr (float)");
    // Catch a missing folder or an existing file before spending seconds generating.
    if (std::string problem = checkOutputFile(out, force, "--out"); !problem.empty()) return fail(problem);
    // Progress on stderr: a 16385-sample island takes minutes on two cores.
    std::fprintf(stderr, "vista: generating a %dx%d island...\n", size, size);

    auto start = std::chrono::steady_clock::now();
    Heightmap map = generateIsland(IslandParams{size, seed});
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    std::string why = ext == ".exr" ? saveHeightmapExr(out, map, force) : saveHeightmapPng16(out, map, force);
    if (!why.empty()) return fail(why, 1);
    auto [lo, hi] = std::minmax_element(map.samples.begin(), map.samples.end());
    std::size_t land = std::size_t(std::count_if(map.samples.begin(), map.samples.end(), [](float v) { return v >= 0.12f; }));
    std::printf("wrote %s: %dx%d island, seed %u, min %.4f max %.4f, land %.1f%% (above 0.12), generated in %.2f s\n",
                out.string().c_str(), size, size, seed, double(*lo), double(*hi), 100.0 * double(land) / double(map.samples.size()),
                seconds);
    return 0;
}

}  // namespace vista
