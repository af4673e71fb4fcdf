// The FrameRenderer a GL test file renders with, on the shared OSMesa context (gl_fixture.h),
// and the frame helpers the feature tests share: render one frame and read back its image and
// GPU counters; give the renderer a terrain made from a height function.
// Internal linkage: every test file that includes this has its own renderer, made on first use.
#pragma once

#include "app/frame.h"
#include "app/scene.h"
#include "gl_fixture.h"
#include "renderer/half.h"
#include "terrain/heightmap.h"
#include "terrain/terrain.h"

#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace vista::test {
namespace {

[[maybe_unused]] FrameRenderer& fileRenderer() {
    glContext();
    static FrameRenderer r(vistaRoot());
    return r;
}

// The terrain (and sky and sun shadows, as the caller leaves them) alone: no grass, sea, clouds,
// local lights, objects, SSAO, TAA or debug grid, for tests that measure the terrain's own image.
[[maybe_unused]] void terrainOnly(Settings& s) {
    s.grass.enabled = false;
    s.water.enabled = false;
    s.clouds.enabled = false;
    s.lights.enabled = false;
    s.objects.enabled = false;
    s.ssao.enabled = false;
    s.taa.enabled = false;
    s.debug.grid = false;
}

// 129x129 texels over 256 m (2 m texels): flat at 0 with a 40 m pillar of 5x5 texels (x, z in
// [-4, 4] m; its walls slope to the ground from |x| = 4 to 6 m), written once per test file into
// a temporary folder named dir_name. The sun and the lamp shadow tests cast it.
[[maybe_unused]] const std::filesystem::path& pillarHeightmap(const char* dir_name) {
    static TempDir dir(dir_name);
    static std::filesystem::path file = [] {
        const int n = 129;
        Heightmap map{n, n, std::vector<float>(std::size_t(n) * n, 0.0f)};
        for (int z = 62; z <= 66; ++z)
            for (int x = 62; x <= 66; ++x) map.samples[std::size_t(z * n + x)] = 1.0f;
        std::filesystem::path f = dir.path / "pillar.png";
        REQUIRE(saveHeightmapPng16(f, map).empty());
        return f;
    }();
    return file;
}

// The same renderer. Programs compile on first use, each test compiling only what its scenes
// use; a compile error or an unlisted variant throws (gl_fixture.h), failing the test.
[[maybe_unused]] FrameRenderer& compiledFileRenderer() { return fileRenderer(); }

// One rendered frame: its report, the image as RGBA floats (top row first: the linear HDR target,
// or with ldr the displayed sRGB image in [0, 1]) and the GPU counters it wrote, summed by name.
struct RenderedFrame {
    FrameReport report;
    std::vector<float> rgba;
    std::map<std::string, std::uint64_t> counters;

    std::uint64_t counter(const std::string& name) const {
        auto it = counters.find(name);
        return it == counters.end() ? 0 : it->second;
    }
};

// Renders s from view at time t. request says which GPU counters to count; its capture fields
// are set here.
[[maybe_unused]] RenderedFrame renderFrame(FrameRenderer& r, const Settings& s, const ViewParams& view, double t = 0.0,
                                           FrameRequest request = {}, bool ldr = false) {
    r.counters().collect(true);  // drop what earlier frames left
    std::vector<std::uint16_t> half;
    std::vector<unsigned char> bytes;
    if (ldr)
        request.capture_ldr = &bytes;
    else
        request.capture_hdr = &half;
    RenderedFrame out;
    out.report = r.render(s, view, t, request);
    for (const auto& c : r.counters().collect(true)) out.counters[c.name] += c.value;
    out.rgba.resize(ldr ? bytes.size() : half.size());
    for (std::size_t i = 0; i < out.rgba.size(); ++i) out.rgba[i] = ldr ? float(bytes[i]) / 255.0f : halfToFloat(half[i]);
    return out;
}

// Gives r a terrain of n x n samples, height(x, z) in [0, 1], laid out by terrain's settings.
template <class Height>
void adoptTerrain(FrameRenderer& r, const TerrainSettings& terrain, int n, Height&& height) {
    Heightmap map{n, n, std::vector<float>(std::size_t(n) * std::size_t(n))};
    for (int z = 0; z < n; ++z)
        for (int x = 0; x < n; ++x) map.samples[std::size_t(z) * std::size_t(n) + std::size_t(x)] = height(x, z);
    InputErrors errors;
    auto made = Terrain::create(std::move(map), terrain, r.shaders(), errors);
    REQUIRE(made);
    r.adoptTerrain(std::move(made));
}

// A width x height m double-sided pane in the model's x-y plane facing +z (x centred, y from 0),
// one non-metallic material: base (colour and alpha), roughness and alpha mode.
[[maybe_unused]] Model paneModel(const char* name, float width, float height, glm::vec4 base, float roughness,
                                 AlphaMode mode) {
    Model m;
    m.name = name;
    for (int c = 0; c < 4; ++c) {
        MeshVertex v;
        v.uv = glm::vec2(float(c == 1 || c == 2), float(c >= 2));
        v.position = glm::vec3((v.uv.x - 0.5f) * width, v.uv.y * height, 0.0f);
        v.normal = glm::vec3(0.0f, 0.0f, 1.0f);
        m.vertices.push_back(v);
    }
    m.indices = {0, 1, 2, 0, 2, 3};
    ModelMaterial mat;
    mat.base_color = base;
    mat.metallic = 0.0f;
    mat.roughness = roughness;
    mat.alpha_mode = mode;
    mat.double_sided = true;
    m.materials = {mat};
    m.lods = {ModelLod{{ModelPrimitive{0, 6, 0}}}};
    m.bounds_min = glm::vec3(-0.5f * width, 0.0f, 0.0f);
    m.bounds_max = glm::vec3(0.5f * width, height, 0.0f);
    return m;
}

}  // namespace
}  // namespace vista::test
