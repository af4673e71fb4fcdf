// Heightmap loading (formats, validation errors), bilinear sampling, the island generator
// and gen-heightmap. Test images are written with OpenImageIO into a per-test temp folder.
#include "../temp_dir.h"
#include "terrain/gen_heightmap.h"
#include "terrain/heightmap.h"

#include <doctest/doctest.h>
#include <OpenImageIO/imageio.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>

using namespace vista;
namespace fs = std::filesystem;

namespace {

// ctest runs test cases as parallel processes: the folder name includes the pid.
using test::TempDir;

// Alpha, if any, is written as stored (PNG keeps unassociated alpha; OIIO would otherwise
// divide RGB by it).
template <class T>
void writeImage(const fs::path& file, int width, int height, int channels, OIIO::TypeDesc type, const std::vector<T>& pixels) {
    auto out = OIIO::ImageOutput::create(file.string());
    REQUIRE(out);
    OIIO::ImageSpec spec(width, height, channels, type);
    spec.attribute("oiio:UnassociatedAlpha", 1);
    REQUIRE(out->open(file.string(), spec));
    REQUIRE(out->write_image(type, pixels.data()));
    REQUIRE(out->close());
}

// Loads a file that must fail, and returns its one error's message.
std::string loadError(const fs::path& file, int raw_width = 0, int raw_height = 0, std::uint64_t max_bytes = 1u << 30) {
    InputErrors errors;
    Heightmap map = loadHeightmap(file, raw_width, raw_height, errors, max_bytes);
    CHECK(map.samples.empty());
    CHECK(map.width == 0);
    REQUIRE(errors.size() == 1);
    CHECK(errors[0].file == file.string());
    CHECK(errors[0].line == 0);
    return errors[0].message;
}

Heightmap loadOk(const fs::path& file, int raw_width = 0, int raw_height = 0) {
    InputErrors errors;
    Heightmap map = loadHeightmap(file, raw_width, raw_height, errors);
    for (const auto& e : errors) FAIL_CHECK(e.str());
    return map;
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST_CASE("heightmap: 16-bit PNG save/load round trip is exact to 1/65535, at a non-power-of-two size") {
    TempDir dir("png16");
    Heightmap map;
    map.width = 37;
    map.height = 23;
    for (int i = 0; i < 37 * 23; ++i) map.samples.push_back(float(i % 101) / 100.0f);
    CHECK(saveHeightmapPng16(dir / "map.png", map) == "");
    CHECK_FALSE(fs::exists(dir / "map.png.part"));
    Heightmap back = loadOk(dir / "map.png");
    REQUIRE(back.width == 37);
    REQUIRE(back.height == 23);
    REQUIRE(back.samples.size() == map.samples.size());
    float worst = 0;
    for (std::size_t i = 0; i < map.samples.size(); ++i) worst = std::max(worst, std::abs(back.samples[i] - map.samples[i]));
    CHECK(worst <= 1.0f / 65535.0f);
    CHECK(back.at(0, 0) == 0.0f);
    CHECK(back.at(100 % 37, 100 / 37) == 1.0f);
}

TEST_CASE("heightmap: 8-bit PNG loads normalised to [0, 1]") {
    TempDir dir("png8");
    writeImage(dir / "map.png", 3, 2, 1, OIIO::TypeDesc::UINT8, std::vector<std::uint8_t>{0, 51, 255, 255, 51, 0});
    Heightmap map = loadOk(dir / "map.png");
    REQUIRE(map.width == 3);
    REQUIRE(map.height == 2);
    CHECK(map.at(0, 0) == 0.0f);
    CHECK(map.at(1, 0) == doctest::Approx(0.2f));
    CHECK(map.at(2, 0) == 1.0f);
    CHECK(map.at(0, 1) == 1.0f);
}

TEST_CASE("heightmap: 16-bit TIFF and half-float EXR load") {
    TempDir dir("tiff");
    writeImage(dir / "map.tif", 2, 2, 1, OIIO::TypeDesc::UINT16, std::vector<std::uint16_t>{0, 65535, 13107, 4660});
    Heightmap map = loadOk(dir / "map.tif");
    REQUIRE(map.width == 2);
    CHECK(map.at(1, 0) == 1.0f);
    CHECK(map.at(0, 1) == doctest::Approx(0.2f));
    // Half 0x3c00 = 1.0, 0xc000 = -2.0, 0x3800 = 0.5, 0x5640 = 100.0.
    writeImage(dir / "half.exr", 2, 2, 1, OIIO::TypeDesc::HALF, std::vector<std::uint16_t>{0x3c00, 0xc000, 0x3800, 0x5640});
    map = loadOk(dir / "half.exr");
    CHECK(map.samples == std::vector<float>{1.0f, -2.0f, 0.5f, 100.0f});
}

TEST_CASE("heightmap: float EXR keeps its values exactly") {
    TempDir dir("exr");
    std::vector<float> values{-3.5f, 0.25f, 1234.5678f, 1e-7f, 0.1f, 7.0f};
    writeImage(dir / "map.exr", 2, 3, 1, OIIO::TypeDesc::FLOAT, values);
    Heightmap map = loadOk(dir / "map.exr");
    REQUIRE(map.width == 2);
    REQUIRE(map.height == 3);
    CHECK(map.samples == values);
}

TEST_CASE("heightmap: a grey image saved as RGB loads, RGB with differing channels names the texel") {
    TempDir dir("rgb");
    std::vector<std::uint8_t> grey{10, 10, 10, 20, 20, 20, 30, 30, 30, 40, 40, 40};
    writeImage(dir / "grey.png", 2, 2, 3, OIIO::TypeDesc::UINT8, grey);
    Heightmap map = loadOk(dir / "grey.png");
    REQUIRE(map.width == 2);
    CHECK(map.at(1, 1) == doctest::Approx(40.0f / 255.0f));

    // RGBA: alpha is ignored, even where it is not opaque.
    std::vector<std::uint8_t> rgba(3 * 2 * 4, 100);
    rgba[3] = 0;
    writeImage(dir / "rgba.png", 3, 2, 4, OIIO::TypeDesc::UINT8, rgba);
    map = loadOk(dir / "rgba.png");
    REQUIRE(map.width == 3);
    CHECK(map.at(0, 0) == doctest::Approx(100.0f / 255.0f));
    CHECK(map.at(2, 1) == doctest::Approx(100.0f / 255.0f));

    std::vector<std::uint8_t> colour = rgba;
    colour[(1 * 3 + 2) * 4 + 1] = 101;  // G at texel (2, 1)
    writeImage(dir / "colour.png", 3, 2, 4, OIIO::TypeDesc::UINT8, colour);
    std::string why = loadError(dir / "colour.png");
    CHECK(contains(why, "texel (2, 1)"));
    CHECK(contains(why, "1 (grey)"));
}

TEST_CASE("heightmap: raw .r16 with the right size loads little-endian samples") {
    TempDir dir("r16");
    std::vector<unsigned char> bytes{0x00, 0x00, 0xff, 0xff, 0x34, 0x12, 0x01, 0x00, 0x00, 0x80, 0xfe, 0xff};
    std::ofstream(dir / "map.R16", std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    Heightmap map = loadOk(dir / "map.R16", 3, 2);  // extension is case-insensitive
    REQUIRE(map.width == 3);
    REQUIRE(map.height == 2);
    CHECK(map.at(0, 0) == 0.0f);
    CHECK(map.at(1, 0) == 1.0f);
    CHECK(map.at(2, 0) == doctest::Approx(0x1234 / 65535.0));
    CHECK(map.at(1, 1) == doctest::Approx(0x8000 / 65535.0));
}

TEST_CASE("heightmap: raw .r16 with a wrong or missing size is an error") {
    TempDir dir("r16bad");
    std::ofstream(dir / "map.r16", std::ios::binary).write("0123456789", 10);
    std::string why = loadError(dir / "map.r16", 3, 2);
    CHECK(contains(why, "is 10 bytes"));
    CHECK(contains(why, "need 12 bytes"));
    CHECK(contains(loadError(dir / "map.r16", 0, 0), "raw_width and raw_height"));
    CHECK(contains(loadError(dir / "map.r16", 5, 1), "raw_width and raw_height"));
}

TEST_CASE("heightmap: a missing file is an error naming it") {
    TempDir dir("missing");
    // Every input is checked the same way first (config/file_io.h): regular file, size limit.
    CHECK(contains(loadError(dir / "nope.png"), "cannot be opened: No such file or directory"));
    CHECK(contains(loadError(dir / "nope.r16", 4, 4), "cannot be opened: No such file or directory"));
}

TEST_CASE("heightmap: a 2-channel image is an error") {
    TempDir dir("twochannel");
    writeImage(dir / "map.png", 2, 2, 2, OIIO::TypeDesc::UINT8, std::vector<std::uint8_t>(8, 7));
    CHECK(contains(loadError(dir / "map.png"), "has 2 channels; a heightmap needs 1 (grey)"));
}

TEST_CASE("heightmap: a NaN sample is an error naming the first bad texel and the count") {
    TempDir dir("nan");
    std::vector<float> values(5 * 4, 0.5f);
    values[1 * 5 + 3] = std::numeric_limits<float>::quiet_NaN();  // texel (3, 1)
    values[3 * 5 + 0] = std::numeric_limits<float>::infinity();
    writeImage(dir / "map.exr", 5, 4, 1, OIIO::TypeDesc::FLOAT, values);
    std::string why = loadError(dir / "map.exr");
    CHECK(contains(why, "texel (3, 1)"));
    CHECK(contains(why, "2 non-finite"));
}

TEST_CASE("heightmap: a 1x1 image is too small") {
    TempDir dir("tiny");
    writeImage(dir / "map.png", 1, 1, 1, OIIO::TypeDesc::UINT8, std::vector<std::uint8_t>{9});
    std::string why = loadError(dir / "map.png");
    CHECK(contains(why, "1x1"));
    CHECK(contains(why, "at least 2x2"));
}

TEST_CASE("heightmap: an image over max_bytes is an error saying the size and the limit") {
    TempDir dir("big");
    writeImage(dir / "map.png", 8, 8, 1, OIIO::TypeDesc::UINT8, std::vector<std::uint8_t>(64, 1));
    std::string why = loadError(dir / "map.png", 0, 0, 100);
    CHECK(contains(why, "256 bytes"));
    CHECK(contains(why, "limit of 100 bytes"));
    std::ofstream(dir / "map.r16", std::ios::binary).write(std::string(128, '\0').data(), 128);
    CHECK(contains(loadError(dir / "map.r16", 8, 8, 100), "limit of 100 bytes"));
}

TEST_CASE("heightmap: bilinear sample at texel centres, midpoints and clamped outside") {
    Heightmap map;
    map.width = 3;
    map.height = 2;
    map.samples = {0, 1, 2, 10, 11, 12};
    CHECK(map.sample(0, 0) == 0.0f);
    CHECK(map.sample(2, 1) == 12.0f);
    CHECK(map.sample(1, 1) == 11.0f);
    CHECK(map.sample(0.5, 0) == doctest::Approx(0.5));
    CHECK(map.sample(1, 0.5) == doctest::Approx(6.0));
    CHECK(map.sample(1.5, 0.5) == doctest::Approx(6.5));
    CHECK(map.sample(1.25, 0.25) == doctest::Approx(3.75));
    CHECK(map.sample(-4, -1) == 0.0f);
    CHECK(map.sample(9, 0.5) == doctest::Approx(7.0));
    CHECK(map.sample(2, 7) == 12.0f);
}

TEST_CASE("heightmap: generateIsland is deterministic, in [0, 1], with sea at the edges and land in the middle") {
    IslandParams params{257, 7};
    Heightmap a = generateIsland(params), b = generateIsland(params);
    REQUIRE(a.width == 257);
    REQUIRE(a.height == 257);
    REQUIRE(a.samples.size() == 257u * 257u);
    CHECK(a.samples == b.samples);
    params.seed = 8;
    CHECK(generateIsland(params).samples != a.samples);

    auto [lo, hi] = std::minmax_element(a.samples.begin(), a.samples.end());
    CHECK(*lo >= 0.0f);
    CHECK(*hi == 1.0f);
    float edge = 0;
    for (int i = 0; i < 257; ++i) edge = std::max({edge, a.at(i, 0), a.at(i, 256), a.at(0, i), a.at(256, i)});
    CHECK(edge < 0.12f);
    double land = double(std::count_if(a.samples.begin(), a.samples.end(), [](float v) { return v >= 0.12f; })) / double(a.samples.size());
    CHECK(land > 0.2);
    CHECK(land < 0.6);
}

// The promise is the same bits on every machine (compiler, flags, CPU, thread count): a
// fingerprint of a small island catches FMA contraction, libm calls or unordered reductions
// creeping into the generator. Changing the generator on purpose changes this number (and
// data/heightmaps/island.png should then be regenerated).
TEST_CASE("heightmap: generateIsland bits match the reference fingerprint") {
    Heightmap map = generateIsland(IslandParams{65, 3});
    std::uint64_t fnv = 1469598103934665603ull;  // FNV-1a over the float bits, little-endian
    for (float v : map.samples) {
        std::uint32_t bits;
        std::memcpy(&bits, &v, sizeof bits);
        for (int i = 0; i < 4; ++i) fnv = (fnv ^ ((bits >> (8 * i)) & 0xffu)) * 1099511628211ull;
    }
    CHECK(fnv == 0x6e9e7f6b5b572c53ull);
}

TEST_CASE("heightmap: gen-heightmap writes PNG and EXR that load back, and rejects bad input") {
    TempDir dir("gen");
    CHECK(runGenHeightmap(65, 3, dir / "island.png") == 0);
    CHECK(runGenHeightmap(65, 3, dir / "island.exr") == 0);
    Heightmap png = loadOk(dir / "island.png"), exr = loadOk(dir / "island.exr");
    Heightmap expected = generateIsland(IslandParams{65, 3});
    CHECK(exr.samples == expected.samples);
    REQUIRE(png.samples.size() == expected.samples.size());
    for (std::size_t i = 0; i < png.samples.size(); ++i) CHECK(std::abs(png.samples[i] - expected.samples[i]) <= 1.0f / 65535.0f);

    CHECK(runGenHeightmap(1, 3, dir / "a.png") == 2);
    CHECK(runGenHeightmap(16386, 3, dir / "a.png") == 2);  // .png/.exr are encoded in memory
    CHECK(runGenHeightmap(65538, 3, dir / "a.tif") == 2);
    CHECK_FALSE(fs::exists(dir / "a.tif"));
    CHECK(runGenHeightmap(65, 3, dir / "a.jpg") == 2);
    CHECK(runGenHeightmap(65, 3, dir / "no-such-dir" / "a.png") == 2);
}

// Maps larger than memory: the island row by row through a scratch file, the same bits as in
// memory (erosion pipelined over a window of rows, both remaps from streamed ranges).
TEST_CASE("heightmap: generateIslandRows gives generateIsland's bits, row by row in order") {
    TempDir dir("rows");
    for (int size : {2, 3, 4, 17, 66, 129})
        for (int passes : {0, 1, 4}) {
            CAPTURE(size);
            CAPTURE(passes);
            IslandParams p{size, 5};
            p.erosion_passes = passes;
            const Heightmap expected = generateIsland(p);
            std::vector<float> got;
            int next = 0;
            double last_progress = 0.0;
            const std::string why = generateIslandRows(
                p, dir / "scratch",
                [&](int z, const float* row) {
                    REQUIRE(z == next++);
                    got.insert(got.end(), row, row + size);
                    return std::string();
                },
                [&](double done) { last_progress = done; });
            REQUIRE(why == "");
            CHECK(last_progress == 1.0);
            CHECK_FALSE(fs::exists(dir / "scratch"));  // unlinked as soon as it was made
            CHECK(got == expected.samples);  // bit for bit
        }
    // The row callback's error stops the run and comes back.
    CHECK(generateIslandRows(IslandParams{33, 1}, dir / "scratch", [](int z, const float*) {
              return z == 5 ? std::string("full disk") : std::string();
          }) == "full disk");
    CHECK(generateIslandRows(IslandParams{33, 1}, dir / "no-such-dir" / "scratch", [](int, const float*) {
              return std::string();
          }).find("scratch") != std::string::npos);
}

TEST_CASE("heightmap: gen-heightmap writes a float TIFF row by row with the in-memory generator's bits") {
    TempDir dir("gentif");
    REQUIRE(runGenHeightmap(129, 3, dir / "island.tif") == 0);
    CHECK(loadOk(dir / "island.tif").samples == generateIsland(IslandParams{129, 3}).samples);
    CHECK_FALSE(fs::exists(dir / ".island.tif.partial"));
    CHECK(runGenHeightmap(129, 3, dir / "island.tif") == 2);  // exists: needs --force
    CHECK(runGenHeightmap(65, 3, dir / "island.tif", true) == 0);
    CHECK(loadOk(dir / "island.tif").width == 65);
}

namespace {

std::vector<unsigned char> fileBytes(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

TEST_CASE("heightmap: decoding from memory gives what loading the file gives, and the same errors") {
    TempDir dir("memory");
    writeImage(dir / "map.png", 3, 2, 1, OIIO::TypeDesc::UINT16, std::vector<std::uint16_t>{0, 65535, 13107, 4660, 1, 2});
    writeImage(dir / "map.exr", 2, 2, 1, OIIO::TypeDesc::HALF, std::vector<std::uint16_t>{0x3c00, 0xc000, 0x3800, 0x5640});
    for (const std::string name : {"map.png", "map.exr"}) {
        CAPTURE(name);
        InputErrors errors;
        const Heightmap from_memory = decodeHeightmap(fileBytes(dir / name), name, 0, 0, errors);
        for (const auto& e : errors) FAIL_CHECK(e.str());
        REQUIRE(errors.empty());
        const Heightmap from_file = loadOk(dir / name);
        CHECK(from_memory.width == from_file.width);
        CHECK(from_memory.height == from_file.height);
        CHECK(from_memory.samples == from_file.samples);
    }
    const std::vector<unsigned char> raw = {0x00, 0x00, 0xff, 0xff, 0x00, 0x80, 0x01, 0x00};
    InputErrors errors;
    Heightmap map = decodeHeightmap(raw, "tiny.r16", 2, 2, errors);
    REQUIRE(errors.empty());
    CHECK(map.samples == std::vector<float>{0.0f, 1.0f, 32768.0f / 65535.0f, 1.0f / 65535.0f});
    // Wrong size, garbage, an empty buffer and a header claiming more than the limit.
    map = decodeHeightmap(raw, "tiny.r16", 3, 2, errors);
    CHECK(map.samples.empty());
    REQUIRE(errors.size() == 1);
    CHECK(contains(errors[0].message, "is 8 bytes but raw_width x raw_height = 3x2"));
    errors.clear();
    const std::vector<unsigned char> garbage(64, 0x5a);
    map = decodeHeightmap(garbage, "garbage.png", 0, 0, errors);
    CHECK(map.samples.empty());
    REQUIRE(errors.size() == 1);
    CHECK(errors[0].file == "garbage.png");
    errors.clear();
    map = decodeHeightmap({}, "empty.exr", 0, 0, errors);
    CHECK(errors.size() == 1);
    errors.clear();
    writeImage(dir / "big.png", 64, 64, 1, OIIO::TypeDesc::UINT8, std::vector<std::uint8_t>(64 * 64, 7));
    map = decodeHeightmap(fileBytes(dir / "big.png"), "big.png", 0, 0, errors, 1024);
    REQUIRE(errors.size() == 1);
    CHECK(contains(errors[0].message, "over the limit of 1024 bytes"));
}

TEST_CASE("heightmap: from memory, only the reader the extension names sees the bytes") {
    // OpenImageIO's ImageInput::open tries every format it has when the named one fails; the
    // fuzzer found inputs on which one of those (through DICOM, FITS, camera raw readers) grew
    // the memory past 2 GB. A PNG named .tif is refused by the TIFF reader, not read as PNG.
    TempDir dir("extension");
    writeImage(dir / "map.png", 3, 2, 1, OIIO::TypeDesc::UINT16, std::vector<std::uint16_t>{0, 65535, 13107, 4660, 1, 2});
    const std::vector<unsigned char> png = fileBytes(dir / "map.png");
    InputErrors errors;
    Heightmap map = decodeHeightmap(png, "map.tif", 0, 0, errors);
    CHECK(map.samples.empty());
    REQUIRE(errors.size() == 1);
    CHECK(contains(errors[0].message, "cannot read as tiff"));
    errors.clear();
    // The fuzzer's input (after its 5 bytes of format and raw size): not a PGM.
    const std::vector<unsigned char> fuzzed = {0x2f, 0x3f, 0x31, 0x01, 0x02, 0x00, 0x00, 0x13, 0x73, 0x69, 0x6e, 0x67, 0x00, 0x00,
                                               0x00, 0x13, 0xff, 0xd3, 0xff, 0xff, 0xff, 0x13, 0x00, 0xb1, 0xb8, 0x43, 0x60, 0x82};
    map = decodeHeightmap(fuzzed, "fuzz.pgm", 0, 0, errors);
    CHECK(map.samples.empty());
    REQUIRE(errors.size() == 1);
    CHECK(contains(errors[0].message, "cannot read as pnm"));
    errors.clear();
    map = decodeHeightmap(png, "map.png", 0, 0, errors);
    CHECK(errors.empty());
    CHECK(map.width == 3);
}
