// The OpenEXR header check: real files written by OpenImageIO pass; each corruption that
// would make OpenEXR allocate more than the file holds (a huge data window, an attribute
// larger than the file, tiny tiles, a cut-off file) is refused with what is wrong, both by
// checkExrHeaders and through the heightmap loader.
#include "terrain/exr_header.h"
#include "terrain/heightmap.h"

#include <doctest/doctest.h>
#include <OpenImageIO/imageio.h>
#include <unistd.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <utility>
#include <string_view>
#include <vector>

using namespace vista;
namespace fs = std::filesystem;

namespace {

using Bytes = std::vector<unsigned char>;

// An EXR of width x height float samples as OpenImageIO writes it (tiled when tile > 0).
Bytes writeExr(int width, int height, const std::string& compression, int tile = 0, int parts = 1) {
    const fs::path file = fs::temp_directory_path() / ("vista-exr-header-" + std::to_string(::getpid()) + ".exr");
    auto out = OIIO::ImageOutput::create(file.string());
    REQUIRE(out);
    OIIO::ImageSpec spec(width, height, 1, OIIO::TypeDesc::FLOAT);
    spec.attribute("compression", compression);
    if (tile > 0) {
        spec.tile_width = tile;
        spec.tile_height = tile;
    }
    std::vector<OIIO::ImageSpec> specs(std::size_t(parts), spec);
    REQUIRE(out->open(file.string(), parts, specs.data()));
    std::vector<float> samples(std::size_t(width) * std::size_t(height));
    for (std::size_t i = 0; i < samples.size(); ++i) samples[i] = float(i) * 0.25f;
    for (int p = 0; p < parts; ++p) {
        if (p > 0) REQUIRE(out->open(file.string(), specs[std::size_t(p)], OIIO::ImageOutput::AppendSubimage));
        REQUIRE(out->write_image(OIIO::TypeDesc::FLOAT, samples.data()));
    }
    REQUIRE(out->close());
    std::ifstream in(file, std::ios::binary);
    Bytes bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    fs::remove(file);
    return bytes;
}

// Offset of the value of the first attribute called name (of type type).
std::size_t valueOffset(const Bytes& bytes, const std::string& name, const std::string& type) {
    std::string key = name;
    key.push_back('\0');
    key += type;
    key.push_back('\0');
    const std::string_view all(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    const std::size_t at = all.find(key);
    REQUIRE(at != std::string_view::npos);
    return at + key.size() + 4;
}

void putInt32(Bytes& bytes, std::size_t at, std::int32_t value) {
    std::uint32_t v;
    std::memcpy(&v, &value, sizeof v);
    for (int i = 0; i < 4; ++i) bytes[at + std::size_t(i)] = std::uint8_t(v >> (8 * i));
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// Decodes bytes as an EXR heightmap that must fail, and returns the message.
std::string decodeError(const Bytes& bytes, std::uint64_t max_bytes = 1u << 30) {
    InputErrors errors;
    const Heightmap map = decodeHeightmap(bytes, "corrupt.exr", 0, 0, errors, max_bytes);
    CHECK(map.samples.empty());
    REQUIRE(errors.size() == 1);
    return errors[0].message;
}

constexpr std::uint64_t kLimit = 1u << 20;

}  // namespace

TEST_CASE("exr header: files OpenImageIO writes pass, scan lines and tiles, one part and several") {
    for (const std::string compression : {"none", "zip", "piz", "rle"}) {
        CAPTURE(compression);
        const Bytes scanlines = writeExr(37, 19, compression);
        CHECK(isExr(scanlines));
        CHECK(checkExrHeaders(scanlines, kLimit) == "");
        const Bytes tiles = writeExr(37, 19, compression, 8);
        CHECK(checkExrHeaders(tiles, kLimit) == "");
    }
    const Bytes two_parts = writeExr(16, 16, "zip", 0, 2);
    CHECK(checkExrHeaders(two_parts, kLimit) == "");
    // And they still load as heightmaps through the check.
    InputErrors errors;
    const Heightmap map = decodeHeightmap(writeExr(37, 19, "zip", 8), "tiled.exr", 0, 0, errors);
    CHECK(errors.empty());
    CHECK(map.width == 37);
    CHECK(map.height == 19);
    CHECK(map.at(36, 18) == doctest::Approx((37 * 19 - 1) * 0.25));
}

TEST_CASE("exr header: a data window larger than the limit is refused before OpenEXR allocates it") {
    Bytes bytes = writeExr(8, 8, "zip");
    const std::size_t window = valueOffset(bytes, "dataWindow", "box2i");
    putInt32(bytes, window + 8, 0x7ffffff0);  // x_max
    putInt32(bytes, window + 12, 0x7ffffff0);  // y_max
    const std::string why = checkExrHeaders(bytes, kLimit);
    CHECK(contains(why, "data window of 2147483633x2147483633 samples, over the limit of 1048576 bytes"));
    // The regression the fuzzer found: this reached OpenEXR, which allocated gigabytes.
    CHECK(contains(decodeError(bytes), "data window of 2147483633x2147483633"));
    // Inverted and extreme windows are refused too, without overflow.
    putInt32(bytes, window, 5);
    putInt32(bytes, window + 8, 4);
    CHECK(contains(checkExrHeaders(bytes, kLimit), "empty data window (5, 0) - (4, 2147483632)"));
    putInt32(bytes, window, std::numeric_limits<std::int32_t>::min());
    putInt32(bytes, window + 8, std::numeric_limits<std::int32_t>::max());
    CHECK(contains(checkExrHeaders(bytes, std::uint64_t(-1)), "data window of 4294967296x2147483633 samples"));
}

TEST_CASE("exr header: an attribute larger than what is left of the file is refused") {
    Bytes bytes = writeExr(8, 8, "zip");
    const std::size_t window = valueOffset(bytes, "dataWindow", "box2i");
    putInt32(bytes, window - 4, 0x7fffffff);
    CHECK(contains(checkExrHeaders(bytes, kLimit), "has attribute 'dataWindow' of 2147483647 bytes but"));
    putInt32(bytes, window - 4, -1);
    CHECK(contains(checkExrHeaders(bytes, kLimit), "has attribute 'dataWindow' of -1 bytes"));
    CHECK(contains(decodeError(bytes), "dataWindow"));
}

TEST_CASE("exr header: every cut-off prefix of a file is refused up to the end of its offset table") {
    // 8 scan lines uncompressed: 8 chunks; 4x4 tiles over 8x8: 4 chunks.
    for (auto [tile, chunks] : {std::pair{0, 8}, std::pair{4, 4}}) {
        CAPTURE(tile);
        const Bytes bytes = writeExr(8, 8, "none", tile);
        CHECK(checkExrHeaders(bytes, kLimit) == "");
        std::size_t shortest = bytes.size();
        for (std::size_t size = 0; size < bytes.size(); ++size) {
            const Bytes prefix(bytes.begin(), bytes.begin() + std::ptrdiff_t(size));
            if (checkExrHeaders(prefix, kLimit).empty()) {
                shortest = std::min(shortest, size);
            } else {
                CHECK_MESSAGE(size < shortest, "a prefix of " << size << " bytes is refused after a shorter one passed");
            }
        }
        // The shortest accepted prefix ends where the first chunk starts: just after the table,
        // whose first entry holds that offset.
        REQUIRE(shortest >= std::size_t(8 * chunks));
        std::uint64_t first_chunk = 0;
        for (int i = 0; i < 8; ++i) first_chunk |= std::uint64_t(bytes[shortest - std::size_t(8 * chunks) + std::size_t(i)]) << (8 * i);
        CHECK(first_chunk == shortest);
    }
}

TEST_CASE("exr header: tiles of zero size, tiny tiles over a large window, unknown modes and deep data are refused") {
    Bytes bytes = writeExr(8, 8, "none", 4);
    const std::size_t tiles = valueOffset(bytes, "tiles", "tiledesc");
    Bytes zero = bytes;
    putInt32(zero, tiles, 0);
    CHECK(contains(checkExrHeaders(zero, kLimit), "tiles of 0x4"));
    Bytes mode = bytes;
    mode[tiles + 8] = 3;
    CHECK(contains(checkExrHeaders(mode, kLimit), "tile level mode 3"));
    // 1x1 tiles over 512x512 samples: 262,144 offsets (2 MiB), more than the file holds.
    Bytes tiny = bytes;
    putInt32(tiny, tiles, 1);
    putInt32(tiny, tiles + 4, 1);
    const std::size_t window = valueOffset(tiny, "dataWindow", "box2i");
    putInt32(tiny, window + 8, 511);
    putInt32(tiny, window + 12, 511);
    CHECK(contains(checkExrHeaders(tiny, std::uint64_t(1) << 30), "offset table of 262144 chunks"));
    // A rip-mapped 512x512 in 1x1 tiles: (1023 across) x (1023 down) levels' tiles.
    tiny[tiles + 8] = 2;
    CHECK(contains(checkExrHeaders(tiny, std::uint64_t(1) << 30), "offset table of 1046529 chunks"));
    Bytes deep = writeExr(8, 8, "none");
    deep[5] |= 0x08;  // version flag 0x800
    CHECK(contains(checkExrHeaders(deep, kLimit), "deep data"));
    Bytes version = writeExr(8, 8, "none");
    version[4] = 3;
    CHECK(contains(checkExrHeaders(version, kLimit), "version 3"));
    CHECK(contains(checkExrHeaders(Bytes{1, 2, 3, 4, 5}, kLimit), "not an OpenEXR file"));
}

TEST_CASE("exr header: a multi-part file declaring more chunks than its window needs is refused") {
    Bytes bytes = writeExr(16, 16, "zip", 0, 2);
    const std::size_t count = valueOffset(bytes, "chunkCount", "int");
    putInt32(bytes, count, 0x10000000);
    CHECK(contains(checkExrHeaders(bytes, kLimit), "part 0 declares 268435456 chunks"));
}

TEST_CASE("exr header: loading a corrupt EXR file names the file and the data window") {
    Bytes bytes = writeExr(8, 8, "zip");
    const std::size_t window = valueOffset(bytes, "dataWindow", "box2i");
    putInt32(bytes, window + 12, 1 << 30);
    const fs::path file = fs::temp_directory_path() / ("vista-exr-corrupt-" + std::to_string(::getpid()) + ".exr");
    {
        std::ofstream out(file, std::ios::binary);
        out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    }
    InputErrors errors;
    const Heightmap map = loadHeightmap(file, 0, 0, errors, kLimit);
    fs::remove(file);
    CHECK(map.samples.empty());
    REQUIRE(errors.size() == 1);
    CHECK(errors[0].file == file.string());
    CHECK(contains(errors[0].message, "data window of 8x1073741825 samples"));
}
