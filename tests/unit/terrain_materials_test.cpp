// [terrain.material.NAME] sections and splat maps without GL: the sections load, save and reload,
// --set makes and refuses them; loadMaterialSet (what Terrain::create and `vista check` run) puts
// user layers in their places, enlarges small images, and refuses bad files and keys naming the
// file or key and what is accepted.
#include "../temp_dir.h"
#include "config/ini.h"
#include "terrain/user_materials.h"

#include <OpenImageIO/imageio.h>
#include <doctest/doctest.h>

#include <fstream>

using namespace vista;

namespace {

void writeMaterialImage(const std::filesystem::path& file, int width, int height, int channels, std::uint8_t value) {
    auto out = OIIO::ImageOutput::create(file.string());
    REQUIRE(out);
    REQUIRE(out->open(file.string(), OIIO::ImageSpec(width, height, channels, OIIO::TypeDesc::UINT8)));
    std::vector<std::uint8_t> pixels(std::size_t(width) * std::size_t(height) * std::size_t(channels), value);
    REQUIRE(out->write_image(OIIO::TypeDesc::UINT8, pixels.data()));
    out->close();
}

std::string allMessages(const InputErrors& errors) {
    std::string out;
    for (const InputError& e : errors) out += e.str() + "\n";
    return out;
}

}  // namespace

TEST_CASE("config: [terrain.material.NAME] sections load, save and reload, and --set makes and refuses them") {
    Settings s;
    const InputErrors errors = loadIniString("[terrain.material.pebbles]\nalbedo = a.png\ntiling_m = 2\n"
                                             "[terrain.material.rock]\nheight = h.png\n[terrain]\nsplat_map = s.png\n",
                                             "scene.ini", s);
    CHECK(allMessages(errors) == "");
    REQUIRE(s.terrain.materials.size() == 2);
    CHECK(s.terrain.materials[0].name == "pebbles");
    CHECK(s.terrain.materials[0].albedo == "a.png");
    CHECK(s.terrain.materials[0].tiling_m == 2.0f);
    CHECK(s.terrain.materials[1].section == "terrain.material.rock");
    CHECK(s.terrain.materials[1].height == "h.png");
    Settings reloaded;
    CHECK(allMessages(loadIniString(saveIniString(s), "saved.ini", reloaded)) == "");
    CHECK(reloaded.terrain.materials == s.terrain.materials);
    CHECK(reloaded.terrain.splat_map == "s.png");

    CHECK(applyOverride("terrain.material.moss.albedo=m.png", s).empty());
    REQUIRE(s.terrain.materials.size() == 3);
    CHECK(s.terrain.materials[2].albedo == "m.png");
    CHECK(!applyOverride("terrain.material.fern.albedoo=m.png", s).empty());
    CHECK(s.terrain.materials.size() == 3);  // the refused key leaves no entry behind
    CHECK(!applyOverride("terrain.material.fern.tiling_m=0", s).empty());
    CHECK(s.terrain.materials.size() == 3);

    Settings bad;
    const std::string key = allMessages(loadIniString("[terrain.material.x]\ntiling = 2\n", "bad.ini", bad));
    CHECK(key.find("bad.ini:2") != std::string::npos);
    CHECK(key.find("tiling_m") != std::string::npos);
    const std::string name = allMessages(loadIniString("[terrain.material.a-b]\nalbedo = a.png\n", "bad.ini", bad));
    CHECK(name.find("unknown section [terrain.material.a-b]") != std::string::npos);
}

TEST_CASE("terrain materials: user layers replace and extend the generated ones, small images are enlarged") {
    test::TempDir dir("user-materials");
    writeMaterialImage(dir / "red.png", 16, 16, 3, 200);
    writeMaterialImage(dir / "h.png", 16, 16, 1, 64);
    writeMaterialImage(dir / "splat.png", 9, 9, 4, 255);
    TerrainSettings s;
    TerrainMaterialSettings rock{"rock", "terrain.material.rock", (dir / "red.png").string(), "", (dir / "h.png").string(), "", 0.5f, 3.0f};
    TerrainMaterialSettings moss{"moss", "terrain.material.moss", (dir / "red.png").string(), "", "", "", 0.25f, 1.0f};
    s.materials = {rock, moss};
    s.splat_map = (dir / "splat.png").string();
    s.splat_layers = "grass moss";
    InputErrors errors;
    MaterialSet set = loadMaterialSet(s, 9, 9, errors);
    REQUIRE(allMessages(errors) == "");
    CHECK(set.images.layers == 6);
    CHECK(set.images.size == kGeneratedMaterialSize);
    CHECK(set.names[2] == "rock");
    CHECK(set.names[5] == "moss");
    CHECK(set.repeat_m[2] == 3.0f);
    CHECK(set.repeat_m[0] == 0.0f);
    CHECK(set.repeat_m[5] == 1.0f);
    CHECK(set.splat_layers == std::vector<int>{1, 5, -1, -1});
    const std::size_t texels = std::size_t(set.images.size) * std::size_t(set.images.size);
    // rock: the user's albedo, roughness_value in alpha, its height in the detail alpha, flat normal
    CHECK(set.images.albedo[(2 * texels + 1234) * 4 + 0] == 200);
    CHECK(set.images.albedo[(2 * texels + 1234) * 4 + 3] == 128);
    CHECK(set.images.normal[(2 * texels + 1234) * 4 + 3] == 64);
    CHECK(set.images.normal[(2 * texels + 1234) * 4 + 2] == 255);
    // the generated layers are untouched
    MaterialImages generated = generateMaterialImages(kGeneratedMaterialSize);
    CHECK(std::equal(generated.albedo.begin(), generated.albedo.begin() + std::ptrdiff_t(2 * texels * 4), set.images.albedo.begin()));
    CHECK(set.images.albedo[(5 * texels + 77) * 4 + 3] == 64);  // moss: roughness 0.25
}

TEST_CASE("terrain materials: bad files and keys are refused naming the file or key and what is accepted") {
    test::TempDir dir("user-materials-bad");
    writeMaterialImage(dir / "a16.png", 16, 16, 3, 100);
    writeMaterialImage(dir / "a32.png", 32, 32, 3, 100);
    writeMaterialImage(dir / "a12.png", 12, 12, 3, 100);
    writeMaterialImage(dir / "rgb.png", 16, 16, 3, 100);
    writeMaterialImage(dir / "two.png", 16, 16, 2, 100);
    writeMaterialImage(dir / "splat8.png", 8, 8, 4, 255);
    std::ofstream(dir / "text.png") << "not an image";
    std::ofstream(dir / "notes.txt") << "not an image";
    std::filesystem::create_directories(dir / "folder.png");
    struct Case {
        std::string albedo, height, splat, layers, file, says;
    } cases[] = {
        {(dir / "missing.png").string(), "", "", "", "missing.png", "albedo"},
        {(dir / "text.png").string(), "", "", "", "text.png", "cannot be read as png"},
        {(dir / "notes.txt").string(), "", "", "", "notes.txt", "accepted: .png .jpg"},
        {(dir / "folder.png").string(), "", "", "", "folder.png", "regular file"},
        {(dir / "two.png").string(), "", "", "", "two.png", "has 2 channels; accepted: 3 (RGB) or 4 (RGBA)"},
        {(dir / "a12.png").string(), "", "", "", "a12.png", "is 12x12; accepted: square, a power of two"},
        {(dir / "a16.png").string(), (dir / "rgb.png").string(), "", "", "rgb.png", "has 3 channels; accepted: 1 (grey)"},
        {(dir / "a16.png").string(), "", (dir / "a32.png").string(), "", "a32.png", "accepted: one texel per heightmap sample, 8x8"},
        {(dir / "a16.png").string(), "", (dir / "splat8.png").string(), "grass gravel", "splat_layers", "'gravel' is no layer"},
        {"", "", "", "", "[terrain.material.rock] albedo", "no albedo image"},
    };
    for (const Case& c : cases) {
        TerrainSettings s;
        TerrainMaterialSettings m;
        m.name = "rock", m.section = "terrain.material.rock", m.albedo = c.albedo, m.height = c.height;
        s.materials = {m};
        s.splat_map = c.splat;
        s.splat_layers = c.layers;
        InputErrors errors;
        MaterialSet set = loadMaterialSet(s, 8, 8, errors);
        const std::string text = allMessages(errors);
        CAPTURE(text);
        CHECK(set.images.layers == 0);
        CHECK(text.find(c.file) != std::string::npos);
        CHECK(text.find(c.says) != std::string::npos);
    }
    // Sizes must agree between materials; an added material must be placed by a splat map.
    TerrainSettings s;
    s.materials = {{"rock", "terrain.material.rock", (dir / "a16.png").string(), "", "", "", 0.8f, 4.0f},
                   {"moss", "terrain.material.moss", (dir / "a32.png").string(), "", "", "", 0.8f, 4.0f}};
    InputErrors errors;
    CHECK(loadMaterialSet(s, 8, 8, errors).images.layers == 0);
    const std::string text = allMessages(errors);
    CHECK(text.find("a32.png: [terrain.material.moss] albedo: is 32x32; accepted: the size of every other material image, 16x16") != std::string::npos);
    CHECK(text.find("[terrain.material.moss]: is placed by nothing") != std::string::npos);
}
