// User materials and splat maps (docs/terrain-materials.md): a known splat pattern comes back in
// the material view's layer IDs pixel for pixel, a user material's albedo shows in the G-buffer
// where the splat map puts it, and `vista check` refuses a bad material file with exit 2 naming
// it; grass blades grow only where the splat map's grass channel is. The test writes its own images.
#include "../temp_dir.h"
#include "cli_runner.h"
#include "renderer_fixture.h"
#include "renderer/camera.h"
#include "terrain/grass/grass.h"
#include "terrain/user_materials.h"

#include <OpenImageIO/imageio.h>
#include <glm/glm.hpp>

#include <fstream>

using namespace vista;

namespace {

void writeImage(const std::filesystem::path& file, int width, int height, int channels, const std::vector<std::uint8_t>& pixels) {
    auto out = OIIO::ImageOutput::create(file.string());
    REQUIRE(out);
    REQUIRE(out->open(file.string(), OIIO::ImageSpec(width, height, channels, OIIO::TypeDesc::UINT8)));
    REQUIRE(out->write_image(OIIO::TypeDesc::UINT8, pixels.data()));
    out->close();
}

constexpr int kMap = 65;          // heightmap samples per side
constexpr float kSize = 256.0f;   // m: 4 m per texel
constexpr int kCell = 16;         // texels per splat checker cell

// The splat pattern: checker cells of kCell texels, channel (cell x parity) + 2 (cell z parity).
int splatChannel(int x, int z) { return (x / kCell) % 2 + 2 * ((z / kCell) % 2); }

struct Assets {
    test::TempDir dir{"materials"};
    Assets() {
        // A pure red user material ("pebbles"), 8x8, and the splat map over the 65x65 heightmap.
        std::vector<std::uint8_t> red(8 * 8 * 3, 0);
        for (std::size_t i = 0; i < red.size(); i += 3) red[i] = 255;
        writeImage(dir / "pebbles.png", 8, 8, 3, red);
        std::vector<std::uint8_t> splat(std::size_t(kMap) * kMap * 4, 0);
        for (int z = 0; z < kMap; ++z)
            for (int x = 0; x < kMap; ++x) splat[(std::size_t(z) * kMap + std::size_t(x)) * 4 + std::size_t(splatChannel(x, z))] = 255;
        writeImage(dir / "splat.png", kMap, kMap, 4, splat);
        // Halves: channel 0 (grass) where x >= kMap / 2, channel 1 (sand) elsewhere.
        std::vector<std::uint8_t> halves(std::size_t(kMap) * kMap * 4, 0);
        for (int z = 0; z < kMap; ++z)
            for (int x = 0; x < kMap; ++x) halves[(std::size_t(z) * kMap + std::size_t(x)) * 4 + (x >= kMap / 2 ? 0 : 1)] = 255;
        writeImage(dir / "halves.png", kMap, kMap, 4, halves);
    }
};

Assets& assets() {
    static Assets a;
    return a;
}

// Flat ground in the grass band, splat channels sand, pebbles, rock, snow; the terrain alone, unlit.
Settings splatScene() {
    Settings s;
    s.terrain.size_m = kSize;
    s.terrain.height_scale_m = 100.0f;
    s.terrain.splat_map = (assets().dir / "splat.png").string();
    s.terrain.splat_layers = "sand pebbles rock snow";
    addNamedSection(s, "terrain.material.pebbles");
    s.terrain.materials[0].albedo = (assets().dir / "pebbles.png").string();
    s.terrain.materials[0].tiling_m = 2.0f;
    s.terrain.view = TerrainView::Material;
    test::terrainOnly(s);
    s.sky.enabled = false;
    s.shadows.enabled = false;
    return s;
}

FrameRenderer& renderer() { return test::fileRenderer(); }

void adoptSplatTerrain(const Settings& s) {
    test::adoptTerrain(renderer(), s.terrain, kMap, [](int, int) { return 0.3f; });
}

// Heightmap texel coordinates (x, z) seen at pixel (px, py) of a view looking at the flat ground.
glm::dvec2 texelAt(const ViewParams& view, double ground, int px, int py) {
    const glm::mat4 inv = viewMatrices(view).inv_view_proj;  // camera-relative
    const glm::vec2 ndc{(float(px) + 0.5f) / float(view.width) * 2.0f - 1.0f, 1.0f - (float(py) + 0.5f) / float(view.height) * 2.0f};
    glm::vec4 a = inv * glm::vec4(ndc, 1.0f, 1.0f), b = inv * glm::vec4(ndc, 0.5f, 1.0f);
    glm::dvec3 p0 = glm::dvec3(a) / double(a.w), p1 = glm::dvec3(b) / double(b.w);
    glm::dvec3 d = p1 - p0;
    double t = (ground - view.position.y - p0.y) / d.y;
    glm::dvec3 world = view.position + p0 + d * t;
    const double texel_m = kSize / double(kMap - 1);
    return {(world.x + kSize * 0.5) / texel_m, (world.z + kSize * 0.5) / texel_m};
}

}  // namespace

TEST_CASE("gl: a splat map's pattern comes back as the material view's layer IDs") {
    Settings s = splatScene();
    adoptSplatTerrain(s);
    const double ground = renderer().terrain()->heightAt(0.0, 0.0);
    const ViewParams view{{3.0, ground + 150.0, -5.0}, 20.0, -89.0, 90.0, 0.5, 96, 96};
    renderer().resetHistory();
    test::RenderedFrame f = test::renderFrame(renderer(), s, view);
    // Layers: sand 0, grass 1, rock 2, snow 3, dirt 4, then pebbles 5.
    const int layer_of_channel[4] = {0, 5, 2, 3};
    int checked = 0, wrong = 0, seen[8] = {};
    for (int py = 0; py < view.height; ++py)
        for (int px = 0; px < view.width; ++px) {
            glm::dvec2 t = texelAt(view, ground, px, py);
            if (t.x < 1.0 || t.y < 1.0 || t.x > kMap - 2.0 || t.y > kMap - 2.0) continue;
            // Away from the cells' edges, where the bilinear weights blend two channels.
            auto inner = [](double v) { double f = std::fmod(v, double(kCell)); return f > 1.5 && f < kCell - 1.5; };
            if (!inner(t.x) || !inner(t.y)) continue;
            const int expected = layer_of_channel[splatChannel(int(t.x), int(t.y))];
            const float id = f.rgba[(std::size_t(py) * std::size_t(view.width) + std::size_t(px)) * 4 + 3];
            ++checked;
            seen[expected]++;
            if (int(std::lround(id)) != expected) {
                if (wrong++ < 5) MESSAGE("pixel " << px << "," << py << " texel " << t.x << "," << t.y << ": id " << id << ", expected " << expected);
            }
        }
    CHECK(checked > 2000);
    CHECK(wrong == 0);
    for (int layer : layer_of_channel) CHECK(seen[layer] > 100);
}

TEST_CASE("gl: a user material's albedo shows where the splat map puts it") {
    Settings s = splatScene();
    s.terrain.view = TerrainView::Shaded;
    s.debug.view = DebugView::Albedo;
    adoptSplatTerrain(s);
    const double ground = renderer().terrain()->heightAt(0.0, 0.0);
    const ViewParams view{{3.0, ground + 150.0, -5.0}, 20.0, -89.0, 90.0, 0.5, 64, 64};
    renderer().resetHistory();
    test::RenderedFrame f = test::renderFrame(renderer(), s, view, 0.0, {}, /*ldr=*/true);
    int red = 0, red_expected = 0, other = 0, other_red = 0;
    for (int py = 0; py < view.height; ++py)
        for (int px = 0; px < view.width; ++px) {
            glm::dvec2 t = texelAt(view, ground, px, py);
            if (t.x < 1.0 || t.y < 1.0 || t.x > kMap - 2.0 || t.y > kMap - 2.0) continue;
            auto inner = [](double v) { double f = std::fmod(v, double(kCell)); return f > 1.5 && f < kCell - 1.5; };
            if (!inner(t.x) || !inner(t.y)) continue;
            const float* c = &f.rgba[(std::size_t(py) * std::size_t(view.width) + std::size_t(px)) * 4];
            const bool is_red = c[0] > 0.8f && c[1] < 0.1f && c[2] < 0.1f;
            if (splatChannel(int(t.x), int(t.y)) == 1) {
                ++red_expected;
                red += is_red;
            } else {
                ++other;
                other_red += is_red;
            }
        }
    CHECK(red_expected > 100);
    CHECK(red == red_expected);
    CHECK(other > 300);
    CHECK(other_red == 0);
}

TEST_CASE("gl: vista check refuses a bad material file with exit 2, naming it") {
    test::TempDir dir("materials-cli");
    std::ofstream(dir / "not_an_image.png") << "hello";
    std::filesystem::create_directories(dir / "folder.png");
    std::vector<std::uint8_t> grey(16 * 16, 128);
    writeImage(dir / "grey.png", 16, 16, 1, grey);
    struct Case {
        std::string key, file, says;
    } cases[] = {
        {"albedo", (dir / "missing.png").string(), "missing.png"},
        {"albedo", (dir / "not_an_image.png").string(), "cannot be read as png"},
        {"albedo", (dir / "folder.png").string(), "folder.png"},
        {"albedo", (dir / "grey.png").string(), "has 1 channels; accepted: 3 (RGB) or 4 (RGBA)"},
    };
    for (const Case& c : cases) {
        std::ofstream(dir / "scene.ini") << "[terrain.material.rock]\n" << c.key << " = " << c.file << "\n";
        test::Run r = test::runVista("check -c " + (dir / "scene.ini").string());
        CAPTURE(c.file);
        CAPTURE(r.output);
        CHECK(r.code == 2);
        CHECK(test::has(r, c.file));
        CHECK(test::has(r, c.says));
    }
}

TEST_CASE("gl: grass grows only where the splat map's grass channel is") {
    // Flat ground in the grass band (the height/slope rules put grass everywhere), seen from above
    // the line x = 0 where the splat map's grass half (x >= 0: texel kMap / 2 on) meets its sand half.
    Settings s = splatScene();
    s.terrain.splat_map = (assets().dir / "halves.png").string();
    s.terrain.splat_layers = "grass sand";
    s.terrain.materials.clear();  // no added layer: one that no channel places is refused
    s.terrain.view = TerrainView::Shaded;
    s.grass.enabled = true;
    const double texel_m = kSize / double(kMap - 1);
    // World x of each drawn blade's root (the blade buffer's first vec4: camera-relative root, width).
    auto bladesX = [&](const Settings& scene) {
        test::adoptTerrain(renderer(), scene.terrain, kMap, [](int, int) { return 0.3f; });
        const double ground = renderer().terrain()->heightAt(0.0, 0.0);
        const ViewParams view{{0.0, ground + 20.0, 0.0}, 0.0, -89.0, 70.0, 0.1, 64, 64};
        FrameRequest request;
        request.count_grass = true;
        renderer().resetHistory();
        test::RenderedFrame f = test::renderFrame(renderer(), scene, view, 0.0, request);
        Grass* grass = renderer().grass();
        REQUIRE(grass);
        std::uint32_t draws[8] = {};
        glGetNamedBufferSubData(grass->drawBuffer(), 0, sizeof draws, draws);
        std::vector<double> xs;
        for (const auto& [first, count] : {std::pair<std::size_t, std::size_t>{0, draws[1]}, {grass->farStart(), draws[5]}}) {
            std::vector<float> blades(count * kGrassBladeBytes / sizeof(float));
            if (count > 0)
                glGetNamedBufferSubData(grass->bladeBuffer(), GLintptr(first * kGrassBladeBytes), GLsizeiptr(count * kGrassBladeBytes),
                                        blades.data());
            for (std::size_t b = 0; b < count; ++b) xs.push_back(view.position.x + double(blades[b * kGrassBladeBytes / sizeof(float)]));
        }
        CHECK(f.counter("grass.blades") == xs.size());
        return xs;
    };
    auto count = [](const std::vector<double>& xs, double lo, double hi) {
        return std::count_if(xs.begin(), xs.end(), [&](double x) { return x >= lo && x < hi; });
    };
    const std::vector<double> splat = bladesX(s);
    Settings rules = s;
    rules.terrain.splat_map.clear();
    rules.terrain.splat_layers.clear();
    const std::vector<double> by_rules = bladesX(rules);
    // Between the last sand texel (x = -texel_m) and the first grass one (x = 0) the weights blend.
    const auto splat_sand = count(splat, -1e9, -texel_m), splat_grass = count(splat, 0.0, 1e9);
    const auto rules_sand = count(by_rules, -1e9, -texel_m), rules_grass = count(by_rules, 0.0, 1e9);
    std::printf("grass on a splat map's halves: %td blades on the sand half, %td on the grass half (height/slope rules: %td, %td)\n",
                splat_sand, splat_grass, rules_sand, rules_grass);
    CHECK(rules_sand > 200);  // the rules alone grow grass on both halves
    CHECK(rules_grass > 200);
    CHECK(splat_sand == 0);
    CHECK(splat_grass > rules_grass / 2);
}
