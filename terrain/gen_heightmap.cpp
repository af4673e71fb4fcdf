// `vista gen-heightmap`: generates the procedural island and writes it as a 16-bit PNG or a
// float EXR (in memory), or a float TIFF (row by row, any size up to kMaxGenSize), reporting
// what it wrote.
#include "terrain/gen_heightmap.h"

#include "terrain/heightmap.h"
#include "config/file_io.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <limits>
#include <string>

namespace vista {
namespace {

int fail(const std::string& why, int code = 2) {
    std::fprintf(stderr, "vista: %s\n", why.c_str());
    return code;
}

// What the line after writing says of the heights.
struct HeightStats {
    float lo = std::numeric_limits<float>::infinity(), hi = -std::numeric_limits<float>::infinity();
    std::size_t land = 0, count = 0;
    void add(const float* v, std::size_t n) {
        for (std::size_t i = 0; i < n; ++i) {
            lo = std::min(lo, v[i]);
            hi = std::max(hi, v[i]);
            land += v[i] >= 0.12f ? 1 : 0;
        }
        count += n;
    }
};

// The island as a float TIFF, a row at a time (BigTIFF past 4 GB), through a temporary next to
// out that replaces it only when complete.
std::string writeTiffRows(const IslandParams& params, const std::filesystem::path& out, HeightStats& stats) {
    const int n = params.size;
    const std::filesystem::path tmp = out.parent_path() / ("." + out.filename().string() + ".partial");
    const std::filesystem::path scratch = out.parent_path() / ("." + out.filename().string() + ".scratch");
    auto file = OIIO::ImageOutput::create("tiff");
    if (!file) return out.string() + ": OpenImageIO has no TIFF writer (" + OIIO::geterror() + ")";
    OIIO::ImageSpec spec(n, n, 1, OIIO::TypeDesc::FLOAT);
    spec.attribute("compression", "none");
    if (double(n) * double(n) * sizeof(float) > 3.5e9) spec.attribute("tiff:bigtiff", 1);
    if (!file->open(tmp.string(), spec)) return out.string() + ": " + file->geterror();
    int last_percent = -1;
    std::string why = generateIslandRows(
        params, scratch,
        [&](int z, const float* row) -> std::string {
            stats.add(row, std::size_t(n));
            if (!file->write_scanline(z, 0, OIIO::TypeDesc::FLOAT, row)) return out.string() + ": " + file->geterror();
            return {};
        },
        [&](double done) {
            if (int percent = int(done * 100.0); percent != last_percent && n > 4097) {
                last_percent = percent;
                std::fprintf(stderr, "\rvista: gen-heightmap %3d%%", percent);
                if (percent == 100) std::fprintf(stderr, "\n");
            }
        });
    if (!file->close() && why.empty()) why = out.string() + ": " + file->geterror();
    std::error_code ec;
    if (why.empty()) std::filesystem::rename(tmp, out, ec);
    if (ec) why = out.string() + ": cannot replace (" + ec.message() + ")";
    if (!why.empty()) std::filesystem::remove(tmp, ec);
    return why;
}

}  // namespace

int runGenHeightmap(int size, std::uint32_t seed, const std::filesystem::path& out, bool force) {
    std::string ext = out.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    const bool rows = ext == ".tif" || ext == ".tiff";
    if (size < 2 || size > kMaxGenSize)
        return fail("--size " + std::to_string(size) + " is out of range; accepted: 2.." + std::to_string(kMaxGenSize) +
                    " (.tif; .png and .exr up to " + std::to_string(kMaxGenSizeInMemory) + ")");
    if (ext != ".png" && ext != ".exr" && !rows)
        return fail(out.string() + ": unknown heightmap format \"" + ext +
                    "\"; accepted: .png (16-bit), .exr (float), .tif (float, written row by row)");
    if (!rows && size > kMaxGenSizeInMemory)
        return fail("--size " + std::to_string(size) + " is out of range for " + ext + " (encoded in memory); accepted: 2.." +
                    std::to_string(kMaxGenSizeInMemory) + ", or up to " + std::to_string(kMaxGenSize) +
                    " as .tif (written row by row)");
    // Catch a missing folder or an existing file before spending seconds generating.
    if (std::string problem = checkOutputFile(out, force, "--out"); !problem.empty()) return fail(problem);
    // Progress on stderr: a 16385-sample island takes minutes on two cores.
    std::fprintf(stderr, "vista: generating a %dx%d island...\n", size, size);

    auto start = std::chrono::steady_clock::now();
    HeightStats stats;
    std::string why;
    if (rows) {
        why = writeTiffRows(IslandParams{size, seed}, out, stats);
    } else {
        Heightmap map = generateIsland(IslandParams{size, seed});
        stats.add(map.samples.data(), map.samples.size());
        why = ext == ".exr" ? saveHeightmapExr(out, map, force) : saveHeightmapPng16(out, map, force);
    }
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!why.empty()) return fail(why, 1);
    std::printf("wrote %s: %dx%d island, seed %u, min %.4f max %.4f, land %.1f%% (above 0.12), generated in %.2f s\n",
                out.string().c_str(), size, size, seed, double(stats.lo), double(stats.hi),
                100.0 * double(stats.land) / double(stats.count), seconds);
    return 0;
}

}  // namespace vista
