// Heightmap loading and validation (OpenImageIO, raw .r16), 16-bit PNG output, and the
// deterministic island generator used for the default scene's terrain.
#include "terrain/heightmap.h"

#include "terrain/exr_header.h"
#include "config/file_io.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cctype>
#include <cmath>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <limits>
#include <thread>

#include <fcntl.h>
#include <unistd.h>

// Compilers fuse a*b+c into one FMA where the target has it (aarch64, x86 with -march=native),
// which changes the generator's bits between machines: keep every multiply and add separate.
#if defined(__clang__)
#pragma STDC FP_CONTRACT OFF
#elif defined(__GNUC__)
#pragma GCC optimize("fp-contract=off")
#endif

namespace vista {
namespace {

std::string lowercase(std::string s) {
    for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

std::string texelName(std::size_t index, int width) {
    return "texel (" + std::to_string(index % std::size_t(width)) + ", " + std::to_string(index / std::size_t(width)) + ")";
}

// Size limits shared by images and raw files; checked before any sample is allocated.
std::string checkSize(int width, int height, std::uint64_t max_bytes) {
    if (width < 2 || height < 2)
        return "is " + std::to_string(width) + "x" + std::to_string(height) + " samples; a heightmap needs at least 2x2";
    std::uint64_t bytes = std::uint64_t(width) * std::uint64_t(height) * sizeof(float);
    if (bytes > max_bytes)
        return "is " + std::to_string(width) + "x" + std::to_string(height) + " samples, " + std::to_string(bytes) +
               " bytes as floats, over the limit of " + std::to_string(max_bytes) + " bytes";
    return {};
}

// Raw .r16 needs its size given: the byte count must be exactly width*height*2 so a wrong
// raw_width/raw_height is caught instead of shearing the terrain.
std::string checkRawSize(int width, int height, std::uint64_t actual, std::uint64_t max_bytes) {
    if (width < 2 || height < 2)
        return "a raw .r16 heightmap needs raw_width and raw_height (each >= 2); got " + std::to_string(width) + "x" +
               std::to_string(height);
    if (std::string why = checkSize(width, height, max_bytes); !why.empty()) return why;
    std::uint64_t expected = std::uint64_t(width) * std::uint64_t(height) * 2;
    if (actual != expected)
        return "is " + std::to_string(actual) + " bytes but raw_width x raw_height = " + std::to_string(width) + "x" +
               std::to_string(height) + " 16-bit samples need " + std::to_string(expected) + " bytes";
    return {};
}

// Little-endian uint16 samples, normalised to [0, 1]; bytes holds exactly width*height of them.
void decodeRaw16(std::span<const unsigned char> bytes, int width, int height, Heightmap& map) {
    map.width = width;
    map.height = height;
    map.samples.resize(std::size_t(width) * std::size_t(height));
    for (std::size_t i = 0; i < map.samples.size(); ++i)
        map.samples[i] = float(unsigned(bytes[2 * i]) | unsigned(bytes[2 * i + 1]) << 8) / 65535.0f;
}

// The first size bytes of file (its size, already checked against a limit).
std::string readBytes(const std::filesystem::path& file, std::uint64_t size, std::vector<unsigned char>& bytes) {
    std::ifstream in(file, std::ios::binary);
    bytes.resize(size);
    if (!in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(size))) return "cannot read all " + std::to_string(size) + " bytes";
    return {};
}

std::string loadRaw16(const std::filesystem::path& file, int width, int height, std::uint64_t max_bytes, Heightmap& map) {
    std::error_code ec;
    std::uint64_t actual = width < 2 || height < 2 ? 0 : std::filesystem::file_size(file, ec);
    if (ec) return "cannot read (" + ec.message() + ")";
    if (std::string why = checkRawSize(width, height, actual, max_bytes); !why.empty()) return why;
    std::vector<unsigned char> bytes;
    if (std::string why = readBytes(file, actual, bytes); !why.empty()) return why;
    decodeRaw16(bytes, width, height, map);
    return {};
}

std::string errorOrTruncated(const std::string& error) { return error.empty() ? "the file is truncated or damaged" : error; }

// An opened image: its channels and size are checked before any sample is read.
std::string readImage(OIIO::ImageInput& in, std::uint64_t max_bytes, Heightmap& map) {
    const OIIO::ImageSpec& spec = in.spec();
    int channels = spec.nchannels;
    // A grey image saved as RGB(A) is common; anything else with colour is a mistake.
    if (channels != 1 && channels != 3 && channels != 4)
        return "has " + std::to_string(channels) + " channels; a heightmap needs 1 (grey)";
    if (spec.depth > 1) return "is a volume of " + std::to_string(spec.depth) + " slices; a heightmap needs one 2D image";
    if (std::string why = checkSize(spec.width, spec.height, max_bytes); !why.empty()) return why;
    std::vector<float> samples(std::size_t(spec.width) * std::size_t(spec.height));
    // One channel at a time, so an RGB(A) file needs two heightmaps of memory, not four.
    // has_error: some readers (TIFF) fill a truncated file's missing rows with 0 and still return true.
    if (!in.read_image(0, 0, 0, 1, OIIO::TypeDesc::FLOAT, samples.data()) || in.has_error())
        return "cannot read (" + errorOrTruncated(in.geterror()) + ")";
    if (channels > 1) {
        std::vector<float> other(samples.size());
        for (int c = 1; c < 3; ++c) {  // R, G, B; alpha is ignored
            if (!in.read_image(0, 0, c, c + 1, OIIO::TypeDesc::FLOAT, other.data()) || in.has_error())
                return "cannot read (" + errorOrTruncated(in.geterror()) + ")";
            for (std::size_t i = 0; i < samples.size(); ++i)
                if (!(other[i] == samples[i]) && !(std::isnan(other[i]) && std::isnan(samples[i])))
                    return "has " + std::to_string(channels) + " channels whose colours differ at " + texelName(i, spec.width) +
                           "; a heightmap needs 1 (grey), or RGB with equal channels";
        }
    }
    map.width = spec.width;
    map.height = spec.height;
    map.samples = std::move(samples);
    return {};
}

// Alpha is not coverage here: ask for the stored RGB, not RGB premultiplied by alpha.
OIIO::ImageSpec openConfig() {
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    return config;
}

std::string decodeImage(std::span<const unsigned char> bytes, const std::string& name, std::uint64_t max_bytes,
                        Heightmap& map) {
    // Only a format whose reader takes a memory reader: OpenImageIO would otherwise open name
    // from the disk instead.
    const std::string extension = std::filesystem::path(name).extension().string();
    auto in = extension.size() > 1 ? OIIO::ImageInput::create(extension.substr(1)) : nullptr;
    if (!in) return "is not a format OpenImageIO reads (by its extension '" + extension + "')";
    if (!in->supports("ioproxy")) return "cannot be read from memory (format " + std::string(in->format_name()) + ")";
    if (lowercase(extension) == ".exr")
        if (std::string why = checkExrHeaders(bytes, max_bytes); !why.empty()) return why;
    // Only the reader the extension names sees the bytes: ImageInput::open would, when that one
    // fails, try every format OpenImageIO has (DICOM, FITS, camera raw, ...) on them.
    OIIO::Filesystem::IOMemReader reader(bytes.data(), bytes.size());
    if (!in->set_ioproxy(&reader)) return "cannot be read from memory (" + in->geterror() + ")";
    // The reader goes in the configuration too: some formats' open() take it from there.
    OIIO::Filesystem::IOProxy* proxy = &reader;
    OIIO::ImageSpec config = openConfig();
    config.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
    OIIO::ImageSpec spec;
    if (!in->open(name, spec, config)) {
        const std::string error = in->geterror();
        return "cannot read as " + std::string(in->format_name()) + " (" + (error.empty() ? "not a valid file" : error) + ")";
    }
    std::string why = readImage(*in, max_bytes, map);
    in->close();
    return why;
}

std::string loadImage(const std::filesystem::path& file, std::uint64_t max_bytes, Heightmap& map) {
    // OpenEXR allocates what its headers declare before checking them: an EXR is read into
    // memory and its headers are checked first (decodeImage).
    if (lowercase(file.extension().string()) == ".exr") {
        std::error_code ec;
        const std::uint64_t size = std::filesystem::file_size(file, ec);
        if (ec) return "cannot read (" + ec.message() + ")";
        // Uncompressed float samples with a scan-line offset table, and headers, fit in this.
        if (size > 2 * max_bytes + (std::uint64_t(1) << 20))
            return "is " + std::to_string(size) + " bytes, more than an EXR heightmap within the limit of " +
                   std::to_string(max_bytes) + " bytes of samples can take";
        std::vector<unsigned char> bytes;
        if (std::string why = readBytes(file, size, bytes); !why.empty()) return why;
        return decodeImage(bytes, file.string(), max_bytes, map);
    }
    const OIIO::ImageSpec config = openConfig();
    auto in = OIIO::ImageInput::open(file.string(), &config);
    if (!in) return "cannot read (" + OIIO::geterror() + ")";
    return readImage(*in, max_bytes, map);
}

// The checks every heightmap passes after decoding: finite samples only.
Heightmap finish(Heightmap map, std::string why, const std::string& name, InputErrors& errors) {
    if (why.empty()) {
        std::size_t bad = 0, first = 0;
        for (std::size_t i = 0; i < map.samples.size(); ++i)
            if (!std::isfinite(map.samples[i]) && bad++ == 0) first = i;
        if (bad > 0)
            why = "has a non-finite sample (" + std::to_string(map.samples[first]) + ") at " + texelName(first, map.width) +
                  ", " + std::to_string(bad) + " non-finite in total; heights must be finite numbers";
    }
    if (!why.empty()) {
        errors.push_back({name, 0, why});
        return {};
    }
    return map;
}

// loadHeightmap's calls (wholeHeightmapLoads).
std::atomic<std::int64_t> whole_loads{0};

}  // namespace

bool isRawHeightmap(const std::filesystem::path& file) { return lowercase(file.extension().string()) == ".r16"; }

Heightmap loadHeightmap(const std::filesystem::path& file, int raw_width, int raw_height, InputErrors& errors,
                        std::uint64_t max_bytes) {
    ++whole_loads;
    Heightmap map;
    // A FIFO, /dev/zero (or a link to it) or a directory is refused before any read.
    if (std::string why = inputFileProblem(file, 2 * max_bytes + (std::uint64_t(1) << 20)); !why.empty()) {
        errors.push_back({file.string(), 0, why});
        return map;
    }
    std::string why = isRawHeightmap(file) ? loadRaw16(file, raw_width, raw_height, max_bytes, map)
                                           : loadImage(file, max_bytes, map);
    return finish(std::move(map), std::move(why), file.string(), errors);
}

Heightmap decodeHeightmap(std::span<const unsigned char> bytes, const std::string& name, int raw_width, int raw_height,
                          InputErrors& errors, std::uint64_t max_bytes) {
    Heightmap map;
    std::string why;
    if (isRawHeightmap(name)) {
        why = checkRawSize(raw_width, raw_height, bytes.size(), max_bytes);
        if (why.empty()) decodeRaw16(bytes, raw_width, raw_height, map);
    } else {
        why = decodeImage(bytes, name, max_bytes, map);
    }
    return finish(std::move(map), std::move(why), name, errors);
}

namespace {

// What is wrong with the first of samples (the map's from texel index `first`) whose height is
// out of range, and how many are; "" when all fit.
std::string heightRangeProblem(std::span<const float> samples, std::size_t first, int width, double scale_m, double offset_m,
                               const char* scope) {
    std::size_t bad = 0, at = 0;
    for (std::size_t i = 0; i < samples.size(); ++i)
        if (!(std::abs(offset_m + double(samples[i]) * scale_m) <= kHeightLimitM) && bad++ == 0) at = i;
    if (bad == 0) return {};
    char text[200];
    std::snprintf(text, sizeof text, "height %g m (sample %g) at %s is outside the accepted -%g..%g m, %zu such sample(s)%s",
                  offset_m + double(samples[at]) * scale_m, double(samples[at]), texelName(first + at, width).c_str(),
                  kHeightLimitM, kHeightLimitM, bad, scope);
    return std::string(text) + "; [terrain] height_scale_m and height_offset_m map samples to metres";
}

}  // namespace

bool checkHeightRange(const Heightmap& map, double scale_m, double offset_m, const std::string& file, InputErrors& errors) {
    std::string problem = heightRangeProblem(map.samples, 0, map.width, scale_m, offset_m, "");
    if (problem.empty()) return true;
    errors.push_back({file, 0, std::move(problem)});
    return false;
}

std::string heightRowProblem(const float* row, int width, int z, double scale_m, double offset_m) {
    return heightRangeProblem({row, std::size_t(width)}, std::size_t(z) * std::size_t(width), width, scale_m, offset_m,
                              " in that row");
}

std::int64_t wholeHeightmapLoads() { return whole_loads.load(); }

float Heightmap::sample(double x, double z) const {
    if (width <= 0 || height <= 0) return 0.0f;
    // NaN coordinates clamp to 0 rather than reaching an int conversion.
    x = std::isnan(x) ? 0.0 : std::clamp(x, 0.0, double(width - 1));
    z = std::isnan(z) ? 0.0 : std::clamp(z, 0.0, double(height - 1));
    int x0 = int(x), z0 = int(z);
    int x1 = std::min(x0 + 1, width - 1), z1 = std::min(z0 + 1, height - 1);
    double fx = x - x0, fz = z - z0;
    double top = at(x0, z0) + (at(x1, z0) - at(x0, z0)) * fx;
    double bottom = at(x0, z1) + (at(x1, z1) - at(x0, z1)) * fx;
    return float(top + (bottom - top) * fz);
}

namespace {

// Encodes in memory, then writes atomically: every write and the close are checked (a full
// disk is an error, never a truncated map) and a crash never leaves a partial file.
std::string encodeAndWrite(const std::filesystem::path& file, const char* format, const OIIO::ImageSpec& spec,
                           const void* pixels, bool force) {
    auto out = OIIO::ImageOutput::create(format);
    if (!out) return file.string() + ": OpenImageIO has no " + format + " writer (" + OIIO::geterror() + ")";
    std::vector<unsigned char> bytes;
    OIIO::Filesystem::IOVecOutput memory(bytes);
    out->set_ioproxy(&memory);
    if (!out->open(file.string(), spec)) return file.string() + ": " + out->geterror();
    bool ok = out->write_image(spec.format, pixels);
    ok = out->close() && ok;
    if (!ok) return file.string() + ": " + out->geterror();
    return writeFileAtomic(file, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()), force);
}

}  // namespace

std::string saveHeightmapPng16(const std::filesystem::path& file, const Heightmap& map, bool force) {
    if (map.width < 1 || map.height < 1 || map.samples.size() != std::size_t(map.width) * std::size_t(map.height))
        return file.string() + ": heightmap is empty or its size does not match its samples";
    std::vector<std::uint16_t> pixels(map.samples.size());
    for (std::size_t i = 0; i < pixels.size(); ++i) {
        float v = map.samples[i];
        pixels[i] = std::uint16_t(std::lround(double(std::isnan(v) ? 0.0f : std::clamp(v, 0.0f, 1.0f)) * 65535.0));
    }
    OIIO::ImageSpec spec(map.width, map.height, 1, OIIO::TypeDesc::UINT16);
    return encodeAndWrite(file, "png", spec, pixels.data(), force);
}

std::string saveHeightmapExr(const std::filesystem::path& file, const Heightmap& map, bool force) {
    if (map.width < 1 || map.height < 1 || map.samples.size() != std::size_t(map.width) * std::size_t(map.height))
        return file.string() + ": heightmap is empty or its size does not match its samples";
    OIIO::ImageSpec spec(map.width, map.height, 1, OIIO::TypeDesc::FLOAT);
    spec.channelnames = {"Y"};
    spec.attribute("compression", "zip");
    return encodeAndWrite(file, "openexr", spec, map.samples.data(), force);
}

// ---------------------------------------------------------------------------------------
// Island generator. Only integer hashing, + - * /, sqrt and floor are used (all exactly
// rounded in IEEE 754), so the same params give the same bits everywhere; rows are
// independent, so the thread count does not matter either.
namespace {

std::uint32_t mix32(std::uint32_t x) {  // "lowbias32" integer hash (C. Wellons)
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return x;
}

float smoothstep(float e0, float e1, float x) {
    float t = std::clamp((x - e0) / (e1 - e0), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

// 2D gradient (Perlin) noise in about [-1, 1] with a quintic fade.
float gradientNoise(float x, float y, std::uint32_t seed) {
    static constexpr float s = 0.70710678f;
    static constexpr float grad[8][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}, {s, s}, {-s, s}, {s, -s}, {-s, -s}};
    float fx = std::floor(x), fy = std::floor(y);
    std::int32_t ix = std::int32_t(fx), iy = std::int32_t(fy);
    float dx = x - fx, dy = y - fy;
    auto corner = [&](std::int32_t cx, std::int32_t cy, float px, float py) {
        const float* g = grad[mix32(std::uint32_t(ix + cx) + mix32(std::uint32_t(iy + cy) ^ seed)) & 7];
        return g[0] * px + g[1] * py;
    };
    float n00 = corner(0, 0, dx, dy), n10 = corner(1, 0, dx - 1, dy);
    float n01 = corner(0, 1, dx, dy - 1), n11 = corner(1, 1, dx - 1, dy - 1);
    float u = dx * dx * dx * (dx * (dx * 6 - 15) + 10), v = dy * dy * dy * (dy * (dy * 6 - 15) + 10);
    float a = n00 + (n10 - n00) * u, b = n01 + (n11 - n01) * u;
    return 1.4142f * (a + (b - a) * v);
}

// Each octave doubles the frequency and rotates (a 2x scaled rotation by ~37 deg, exact in
// float) so the lattices of successive octaves do not line up into grid artefacts.
void nextOctave(float& x, float& y) {
    float nx = 1.6f * x - 1.2f * y + 19.1f;
    y = 1.2f * x + 1.6f * y - 7.3f;
    x = nx;
}

// fBm, gain 0.5, normalised to about [-1, 1].
float fbm(float x, float y, int octaves, std::uint32_t seed) {
    float sum = 0, amp = 1, norm = 0;
    for (int i = 0; i < octaves; ++i) {
        sum += amp * gradientNoise(x, y, seed + std::uint32_t(i) * 0x9e3779b9U);
        norm += amp;
        amp *= 0.5f;
        nextOctave(x, y);
    }
    return sum / norm;
}

// Ridged multifractal (Musgrave) in [0, 1]: sharp crests where the noise crosses zero, and
// each octave weighted by the one before, so detail gathers on the ridges, not the valleys.
float ridged(float x, float y, int octaves, std::uint32_t seed) {
    float sum = 0, amp = 1, norm = 0, weight = 1;
    for (int i = 0; i < octaves; ++i) {
        float s = 1.0f - std::abs(gradientNoise(x, y, seed + std::uint32_t(i) * 0x9e3779b9U));
        s = s * s * weight;
        weight = std::clamp(s * 2.0f, 0.0f, 1.0f);
        sum += amp * s;
        norm += amp;
        amp *= 0.5f;
        nextOctave(x, y);
    }
    return sum / norm;
}

// Raw height before remapping: 0 is the shoreline, negative is sea. p in [-1, 1]^2.
float islandHeight(float px, float py, const IslandParams& prm, std::uint32_t seed) {
    auto sub = [&](std::uint32_t k) { return mix32(seed ^ (k * 0x85ebca6bU)); };  // independent noise fields
    // Domain warp: bends the coast and the ridges so nothing looks radial or gridded.
    float wx = fbm(1.3f * px + 3.1f, 1.3f * py - 1.7f, 4, sub(1)), wy = fbm(1.3f * px - 4.3f, 1.3f * py + 2.9f, 4, sub(2));
    float qx = px + 0.22f * wx, qy = py + 0.22f * wy;
    // Distance to the coast in units of the falloff radius (1 = shoreline), made ragged with
    // noise (large bays and headlands, then smaller coves) so the island is not a circle.
    float coast = fbm(1.6f * qx, 1.6f * qy, 7, sub(3));
    // The island is stretched along an axis picked by the seed (a unit vector made from two
    // hashed numbers, not sin/cos, whose last bits differ between C libraries).
    float ax = float(mix32(seed) >> 8) / 8388608.0f - 1.0f, ay = float(mix32(seed + 1) >> 8) / 8388608.0f - 1.0f;
    float alen = std::sqrt(ax * ax + ay * ay) + 1e-6f;
    ax /= alen;
    ay /= alen;
    float along = (qx * ax + qy * ay) / 1.2f, across = (qy * ax - qx * ay) / 0.85f;
    float d = std::sqrt(along * along + across * across) / prm.falloff + 0.45f * coast;
    // Gentle coastal plain and shelf: rises slowly inland, sinks slowly out to sea.
    float h = 0.20f * (1.0f - d);
    // Rolling hills everywhere on land, fading near the shore so beaches stay wide.
    float hills = fbm(4.0f * qx, 4.0f * qy, prm.octaves, sub(4));
    float inland = smoothstep(1.0f, 0.2f, d);
    h += (0.015f + 0.05f * inland) * hills;
    // Mountains: the interior, more in some parts than others, a mix of fBm and ridges.
    float ranges = smoothstep(-0.3f, 0.3f, fbm(1.5f * qx + 7.7f, 1.5f * qy, 3, sub(5)) + 0.1f);
    // Ridges see less of the warp: strongly warped crests swirl instead of forming ranges.
    float crest = ridged(2.2f * (px + 0.06f * wx), 2.2f * (py + 0.06f * wy), prm.octaves, sub(6));
    float mountain = prm.ridge * 2.0f * crest * crest * crest + (1.0f - prm.ridge) * (0.5f + 0.5f * hills);
    float interior = smoothstep(0.95f, 0.3f, d);
    h += interior * (0.25f + 0.75f * ranges) * mountain;
    // Sea cliffs along parts of the coast: the land just above the shoreline steps up.
    float cliffs = smoothstep(0.2f, 0.45f, fbm(2.5f * qx - 11.0f, 2.5f * qy + 5.0f, 3, sub(7)));
    h += cliffs * 0.08f * smoothstep(0.0f, 0.006f, h);
    // The map border is always open sea.
    float border = smoothstep(0.88f, 0.98f, std::max(std::abs(px), std::abs(py)));
    return h + border * (std::min(h, -0.06f) - h);
}

// Spreads rows over the cores; each row is written by one thread only.
template <class F>
void parallelRows(int rows, F&& rowFn) {
    int threads = int(std::clamp(std::thread::hardware_concurrency(), 1u, 16u));
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t)
        pool.emplace_back([&, t] {
            for (int z = t; z < rows; z += threads) rowFn(z);
        });
    for (auto& th : pool) th.join();
}

// Piecewise-linear remap: [min, sea] -> [0, 0.12], [sea, max] -> [0.12, 1], from the map's
// smallest and largest value (one pass finds them, the next applies the remap).
struct Remap {
    float mn, mx, sea;
    Remap(float lo, float hi, float sea_level)
        : mn(std::min(lo, sea_level - 1e-6f)), mx(std::max(hi, sea_level + 1e-6f)), sea(sea_level) {}
    float operator()(float v) const { return v < sea ? 0.12f * (v - mn) / (sea - mn) : 0.12f + 0.88f * (v - sea) / (mx - sea); }
};

void remap(std::vector<float>& h, float sea) {
    auto [lo, hi] = std::minmax_element(h.begin(), h.end());
    const Remap r(*lo, *hi, sea);
    for (float& v : h) v = r(v);
}

// Thermal erosion: wherever the drop to a neighbour exceeds the talus threshold, half of the
// largest excess slides down, shared among the lower neighbours by how far they are over it.
// Sequential in place, so the order (and the result) is fixed.
struct Talus {
    float limit[8];
    explicit Talus(float talus) {
        for (int k = 0; k < 8; ++k) limit[k] = (kDx[k] != 0 && kDz[k] != 0) ? talus * 1.41421356f : talus;
    }
    static constexpr int kDx[8] = {-1, 0, 1, -1, 1, -1, 0, 1}, kDz[8] = {-1, -1, -1, 0, 0, 1, 1, 1};
};

// One row z (1 .. n - 2) of one pass; rows z - 1 .. z + 1 lie at c - n, c, c + n (stride n).
void erodeRow(float* row, int n, const Talus& t) {
    for (int x = 1; x < n - 1; ++x) {
        float* c = row + x;
        float excess[8], total = 0, largest = 0;
        for (int k = 0; k < 8; ++k) {
            float e = *c - c[Talus::kDz[k] * n + Talus::kDx[k]] - t.limit[k];
            excess[k] = e > 0 ? e : 0;
            total += excess[k];
            largest = std::max(largest, excess[k]);
        }
        if (total <= 0) continue;
        float moved = 0.5f * largest;
        for (int k = 0; k < 8; ++k) c[Talus::kDz[k] * n + Talus::kDx[k]] += moved * excess[k] / total;
        *c -= moved;
    }
}

void thermalErosion(std::vector<float>& h, int n, float talus, int passes) {
    const Talus t(talus);
    for (int pass = 0; pass < passes; ++pass)
        for (int z = 1; z < n - 1; ++z) erodeRow(&h[std::size_t(z) * std::size_t(n)], n, t);
}

// Talus of ~40 degrees (tan = 0.84) under the intended mapping (8192 m across, value 1 =
// 600 m), per texel, so the look does not depend on the resolution.
float islandTalus(int n) { return 0.84f * (8192.0f / float(n - 1)) / 600.0f; }

// Row z of the raw island (before the remaps and erosion).
void islandRow(const IslandParams& params, std::uint32_t seed, int n, int z, float* out) {
    for (int x = 0; x < n; ++x) {
        float px = 2.0f * float(x) / float(n - 1) - 1.0f, py = 2.0f * float(z) / float(n - 1) - 1.0f;
        out[x] = islandHeight(px, py, params, seed);
    }
}

std::uint32_t islandSeed(const IslandParams& params) { return mix32(params.seed + 0x6a09e667U); }

}  // namespace

Heightmap generateIsland(const IslandParams& params) {
    Heightmap map;
    int n = std::max(params.size, 2);
    map.width = map.height = n;
    map.samples.resize(std::size_t(n) * std::size_t(n));
    const std::uint32_t seed = islandSeed(params);
    parallelRows(n, [&](int z) { islandRow(params, seed, n, z, &map.samples[std::size_t(z) * std::size_t(n)]); });
    remap(map.samples, 0.0f);
    thermalErosion(map.samples, n, islandTalus(n), params.erosion_passes);
    // Erosion lowers the peaks and fills the sea floor a little: restore 0 .. 0.12 .. 1.
    remap(map.samples, 0.12f);
    return map;
}

namespace {

// The scratch file of generateIslandRows: size² floats, row by row, removed when closed.
class ScratchRows {
public:
    ScratchRows(const std::filesystem::path& file, int n) : n_(n) {
        fd_ = ::open(file.c_str(), O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
        if (fd_ < 0) {
            why_ = file.string() + ": cannot create the scratch file (" + std::strerror(errno) + ")";
            return;
        }
        ::unlink(file.c_str());  // gone with the process, whatever happens
    }
    ~ScratchRows() {
        if (fd_ >= 0) ::close(fd_);
    }
    const std::string& why() const { return why_; }
    bool write(int z, int rows, const float* data) { return io(z, rows, const_cast<float*>(data), true); }
    bool read(int z, int rows, float* data) { return io(z, rows, data, false); }

private:
    bool io(int z, int rows, float* data, bool writing) {
        std::size_t bytes = std::size_t(rows) * std::size_t(n_) * sizeof(float);
        off_t at = off_t(z) * off_t(n_) * off_t(sizeof(float));
        auto* p = reinterpret_cast<char*>(data);
        while (bytes > 0 && why_.empty()) {
            const ssize_t done = writing ? ::pwrite(fd_, p, bytes, at) : ::pread(fd_, p, bytes, at);
            if (done <= 0) why_ = std::string("the scratch file failed (") + (done < 0 ? std::strerror(errno) : "short") + ")";
            else {
                p += done;
                at += done;
                bytes -= std::size_t(done);
            }
        }
        return why_.empty();
    }
    int n_, fd_ = -1;
    std::string why_;
};

}  // namespace

std::string generateIslandRows(const IslandParams& params, const std::filesystem::path& scratch_file,
                               const std::function<std::string(int, const float*)>& row,
                               const std::function<void(double)>& progress) {
    const int n = std::max(params.size, 2);
    const std::uint32_t seed = islandSeed(params);
    ScratchRows scratch(scratch_file, n);
    if (!scratch.why().empty()) return scratch.why();
    const std::size_t stride = std::size_t(n);
    auto report = [&](double done) {
        if (progress) progress(done);
    };

    // 1. The raw heights, a band of rows at a time (rows on the cores), and their range.
    constexpr int kBand = 64;
    std::vector<float> band(std::size_t(kBand) * stride);
    float lo = std::numeric_limits<float>::infinity(), hi = -lo;
    for (int z0 = 0; z0 < n; z0 += kBand) {
        const int rows = std::min(kBand, n - z0);
        parallelRows(rows, [&](int z) { islandRow(params, seed, n, z0 + z, &band[std::size_t(z) * stride]); });
        for (std::size_t i = 0; i < std::size_t(rows) * stride; ++i) {
            lo = std::min(lo, band[i]);
            hi = std::max(hi, band[i]);
        }
        if (!scratch.write(z0, rows, band.data())) return scratch.why();
        report(0.8 * double(z0 + rows) / double(n));
    }

    // 2. The first remap and the erosion passes, pipelined in a window of rows: pass p works on
    // row s - 3p at step s. Pass p + 1's row z touches rows z - 1 .. z + 1 only, pass p's later
    // rows (>= z + 3) rows from z + 2 on: the same operations on the same values as pass after
    // pass over the whole map. A row is final once the last pass has worked on the row below it.
    const Remap first(lo, hi, 0.0f);
    const Talus talus(islandTalus(n));
    const int passes = n >= 3 ? std::max(params.erosion_passes, 0) : 0, lag = 3;
    const int capacity = lag * passes + kBand;
    std::vector<float> window(std::size_t(capacity) * stride);
    int base = 0, loaded = 0, flushed = 0;  // window holds rows [base, loaded); rows < flushed are written back
    lo = std::numeric_limits<float>::infinity();
    hi = -lo;
    auto at = [&](int z) { return &window[std::size_t(z - base) * stride]; };
    auto load = [&](int upto) {
        for (; loaded < std::min(upto, n); ++loaded) {
            if (loaded - base == capacity) {  // drop the rows already written back
                std::memmove(window.data(), at(flushed), std::size_t(loaded - flushed) * stride * sizeof(float));
                base = flushed;
            }
            float* r = at(loaded);
            if (!scratch.read(loaded, 1, r)) return false;
            for (int x = 0; x < n; ++x) r[x] = first(r[x]);
        }
        return true;
    };
    auto flush = [&](int upto) {
        for (; flushed < upto; ++flushed) {
            const float* r = at(flushed);
            for (int x = 0; x < n; ++x) {
                lo = std::min(lo, r[x]);
                hi = std::max(hi, r[x]);
            }
            if (!scratch.write(flushed, 1, r)) return false;
        }
        return true;
    };
    const int steps = passes > 0 ? n - 2 + lag * (passes - 1) : 0;
    for (int s = 1; s <= steps; ++s) {
        if (!load(s + 2)) return scratch.why();
        for (int p = 0; p < passes; ++p)
            if (const int z = s - lag * p; z >= 1 && z <= n - 2) erodeRow(at(z), n, talus);
        if (!flush(std::max(0, s - lag * (passes - 1)))) return scratch.why();
        if (s % kBand == 0) report(0.8 + 0.1 * double(s) / double(steps));
    }
    // The rest is final (all of it without erosion): a row at a time through the window.
    for (int z = flushed; z < n; ++z)
        if (!load(z + 1) || !flush(z + 1)) return scratch.why();

    // 3. The second remap, row by row to the caller.
    const Remap second(lo, hi, 0.12f);
    std::vector<float>& out = band;
    for (int z0 = 0; z0 < n; z0 += kBand) {
        const int rows = std::min(kBand, n - z0);
        if (!scratch.read(z0, rows, out.data())) return scratch.why();
        for (int z = 0; z < rows; ++z) {
            float* r = &out[std::size_t(z) * stride];
            for (int x = 0; x < n; ++x) r[x] = second(r[x]);
            if (std::string why = row(z0 + z, r); !why.empty()) return why;
        }
        report(0.9 + 0.1 * double(z0 + rows) / double(n));
    }
    return {};
}

}  // namespace vista
