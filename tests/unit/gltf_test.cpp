// glTF loading (renderer/meshes/gltf_loader.h) on small files written here: node transforms,
// materials with every texture slot, alpha modes and double-sided, the procedural props
// round-tripping through .glb, their LODs, and malformed files refused with the file named.
#include "renderer/meshes/gen_props.h"
#include "renderer/meshes/gltf_loader.h"
#include "renderer/meshes/mesh_lod.h"

#include <doctest/doctest.h>
#include <glm/geometric.hpp>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using namespace vista;

namespace {

std::string base64(const std::string& in) {
    static const char* t = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    std::size_t i = 0;
    for (; i + 2 < in.size(); i += 3) {
        const unsigned v = unsigned((unsigned char)in[i]) << 16 | unsigned((unsigned char)in[i + 1]) << 8 | (unsigned char)in[i + 2];
        out += {t[v >> 18], t[(v >> 12) & 63], t[(v >> 6) & 63], t[v & 63]};
    }
    if (i + 1 == in.size()) {
        const unsigned v = unsigned((unsigned char)in[i]) << 16;
        out += {t[v >> 18], t[(v >> 12) & 63], '=', '='};
    } else if (i + 2 == in.size()) {
        const unsigned v = unsigned((unsigned char)in[i]) << 16 | unsigned((unsigned char)in[i + 1]) << 8;
        out += {t[v >> 18], t[(v >> 12) & 63], t[(v >> 6) & 63], '='};
    }
    return out;
}

// One triangle (0,0,0) (1,0,0) (0,0,-1) with normals and UVs, uint16 indices, as a data: buffer.
std::string triangleBuffer() {
    const float pos[9] = {0, 0, 0, 1, 0, 0, 0, 0, -1};
    const float nrm[9] = {0, 1, 0, 0, 1, 0, 0, 1, 0};
    const float uv[6] = {0, 0, 1, 0, 0, 1};
    const std::uint16_t idx[4] = {0, 1, 2, 0};  // padded to 8 bytes
    std::string b(reinterpret_cast<const char*>(pos), sizeof pos);
    b.append(reinterpret_cast<const char*>(nrm), sizeof nrm);
    b.append(reinterpret_cast<const char*>(uv), sizeof uv);
    b.append(reinterpret_cast<const char*>(idx), sizeof idx);
    return b;  // 36 + 36 + 24 + 8 = 104 bytes
}

// A 1 x 1 RGBA PNG (opaque red).
const char* kPixelPng =
    "iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAYAAAAfFcSJAAAADUlEQVR42mP8z8DwHwAFBQIAX8jx0gAAAABJRU5ErkJggg==";

// A complete file with one material using every texture slot, nodes: parent (translate 10 0 0,
// scale 2) -> child (rotated 90 deg about y) holding the mesh. patch() edits the text.
std::string gltf(const std::string& extra_root = "", const std::string& buffer_uri = "") {
    const std::string uri = buffer_uri.empty() ? "data:application/octet-stream;base64," + base64(triangleBuffer()) : buffer_uri;
    return R"({
  "asset": {"version": "2.0"}, )" + extra_root + R"(
  "scene": 0, "scenes": [{"nodes": [0]}],
  "nodes": [{"translation": [10, 0, 0], "scale": [2, 2, 2], "children": [1]},
            {"rotation": [0, 0.70710678, 0, 0.70710678], "mesh": 0}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2}, "indices": 3, "material": 0}]}],
  "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.25, 1, 0.75], "metallicFactor": 0.2,
                   "roughnessFactor": 0.7, "baseColorTexture": {"index": 0}, "metallicRoughnessTexture": {"index": 0}},
                 "normalTexture": {"index": 0, "scale": 0.5}, "occlusionTexture": {"index": 0, "strength": 0.8},
                 "emissiveTexture": {"index": 0}, "emissiveFactor": [1, 0.5, 0.25],
                 "alphaMode": "MASK", "alphaCutoff": 0.3, "doubleSided": true}],
  "textures": [{"source": 0}],
  "images": [{"uri": "data:image/png;base64,)" + std::string(kPixelPng) + R"("}],
  "buffers": [{"byteLength": 104, "uri": ")" + uri + R"("}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 96}, {"buffer": 0, "byteOffset": 96, "byteLength": 6}],
  "accessors": [{"bufferView": 0, "byteOffset": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0,0,-1], "max": [1,0,0]},
                {"bufferView": 0, "byteOffset": 36, "componentType": 5126, "count": 3, "type": "VEC3"},
                {"bufferView": 0, "byteOffset": 72, "componentType": 5126, "count": 3, "type": "VEC2"},
                {"bufferView": 1, "byteOffset": 0, "componentType": 5123, "count": 3, "type": "SCALAR"}]
})";
}

std::string replaceOnce(std::string s, const std::string& from, const std::string& to) {
    const std::size_t at = s.find(from);
    REQUIRE(at != std::string::npos);
    return s.replace(at, from.size(), to);
}

}  // namespace

TEST_CASE("gltf: node transforms are baked into the vertices, normals follow") {
    Model m;
    REQUIRE(loadGltfFromMemory(gltf(), "", "tri.gltf", m) == "");
    REQUIRE(m.vertices.size() == 3);
    REQUIRE(m.lods.size() == 1);
    REQUIRE(m.lods[0].primitives.size() == 1);
    CHECK(m.lods[0].triangles() == 1);
    // Child: 90 deg about +y takes (1,0,0) to (0,0,-1) and (0,0,-1) to (-1,0,0); parent: x2, +10 x.
    auto near = [](glm::vec3 a, glm::vec3 b) { return glm::length(a - b) < 1e-5f; };
    CHECK(near(m.vertices[0].position, {10, 0, 0}));
    CHECK(near(m.vertices[1].position, {10, 0, -2}));
    CHECK(near(m.vertices[2].position, {8, 0, 0}));
    CHECK(near(m.vertices[1].normal, {0, 1, 0}));
    CHECK(near(m.bounds_min, {8, 0, -2}));
    CHECK(near(m.bounds_max, {10, 0, 0}));
    CHECK(m.vertices[2].uv == glm::vec2(0, 1));
}

TEST_CASE("gltf: metallic-roughness material with every texture slot, mask and double-sided") {
    Model m;
    REQUIRE(loadGltfFromMemory(gltf(), "", "tri.gltf", m) == "");
    REQUIRE(m.materials.size() == 1);
    const ModelMaterial& mat = m.materials[0];
    CHECK(mat.base_color == glm::vec4(0.5f, 0.25f, 1.0f, 0.75f));
    CHECK(mat.metallic == doctest::Approx(0.2));
    CHECK(mat.roughness == doctest::Approx(0.7));
    CHECK(mat.emissive == glm::vec3(1.0f, 0.5f, 0.25f));
    CHECK(mat.normal_scale == doctest::Approx(0.5));
    CHECK(mat.occlusion_strength == doctest::Approx(0.8));
    CHECK(mat.alpha_mode == AlphaMode::Mask);
    CHECK(mat.alpha_cutoff == doctest::Approx(0.3));
    CHECK(mat.double_sided);
    CHECK(mat.base_color_texture == 0);
    CHECK(mat.metallic_roughness_texture == 0);
    CHECK(mat.normal_texture == 0);
    CHECK(mat.occlusion_texture == 0);
    CHECK(mat.emissive_texture == 0);
    REQUIRE(m.images.size() == 1);
    CHECK(m.images[0].width == 1);
    CHECK(m.images[0].rgba.size() == 4);
    CHECK(m.images[0].rgba[3] == 255);
    // A normal map without TANGENT: tangents derived from the UVs (unit, in the surface plane).
    CHECK(m.vertices[0].tangent.w != 0.0f);
    CHECK(std::abs(glm::dot(glm::vec3(m.vertices[0].tangent), m.vertices[0].normal)) < 1e-5f);

    Model blend;
    REQUIRE(loadGltfFromMemory(replaceOnce(replaceOnce(gltf(), "\"MASK\"", "\"BLEND\""), "\"doubleSided\": true", "\"doubleSided\": false"),
                               "", "blend.gltf", blend) == "");
    CHECK(blend.materials[0].alpha_mode == AlphaMode::Blend);
    CHECK(!blend.materials[0].double_sided);
    CHECK(blend.hasBlend());
    Model opaque;
    REQUIRE(loadGltfFromMemory(replaceOnce(gltf(), "\"MASK\"", "\"OPAQUE\""), "", "opaque.gltf", opaque) == "");
    CHECK(opaque.materials[0].alpha_mode == AlphaMode::Opaque);
}

TEST_CASE("gltf: malformed files are refused with the file and the element named") {
    Model m;
    struct Case {
        std::string text, expect;
    };
    const Case cases[] = {
        {gltf("", "missing.bin"), "missing.bin"},
        {replaceOnce(gltf(), "\"count\": 3, \"type\": \"VEC2\"", "\"count\": 30, \"type\": \"VEC2\""), "TEXCOORD_0"},
        {replaceOnce(gltf(), "\"count\": 3, \"type\": \"SCALAR\"", "\"count\": 30, \"type\": \"SCALAR\""), "reach past"},
        {gltf("\"extensionsUsed\": [\"KHR_draco_mesh_compression\"], \"extensionsRequired\": [\"KHR_draco_mesh_compression\"],"),
         "requires extension KHR_draco_mesh_compression"},
        {replaceOnce(gltf(), "\"material\": 0}", "\"material\": 0, \"mode\": 1}"), "mode 1 is not supported"},
        {replaceOnce(gltf(), "\"material\": 0}", "\"material\": 5}"), "material 5 does not exist"},
        {replaceOnce(gltf(), "\"mesh\": 0}", "\"mesh\": 0, \"children\": [0]}"), "cycle"},
        {replaceOnce(gltf(), "\"alphaMode\": \"MASK\"", "\"alphaMode\": \"GLASS\""), "alphaMode 'GLASS'"},
        {"{\"asset\": {\"version\": \"2.0\"}, ", "not a valid glTF"},
        {"glTF\x02\0\0\0", "not a valid glTF"},
    };
    for (const Case& c : cases) {
        CAPTURE(c.expect);
        const std::string why = loadGltfFromMemory(c.text, "", "bad.gltf", m);
        CHECK(why.rfind("bad.gltf: ", 0) == 0);
        CHECK(why.find(c.expect) != std::string::npos);
    }
    // Out-of-range indices: the triangle's third index points past its 3 vertices.
    std::string buffer = triangleBuffer();
    const std::uint16_t bad = 7;
    std::memcpy(&buffer[96 + 4], &bad, 2);
    const std::string why = loadGltfFromMemory(gltf("", "data:application/octet-stream;base64," + base64(buffer)), "", "bad.gltf", m);
    CHECK(why.find("index 7") != std::string::npos);
    // A missing file on disk.
    CHECK(loadGltf("/nonexistent/model.glb", m).find("/nonexistent/model.glb") != std::string::npos);
}

TEST_CASE("gltf: external buffers load from the model's folder, .glb round trip of the props") {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "vista_gltf_test";
    std::filesystem::create_directories(dir);
    {
        std::ofstream(dir / "tri.bin", std::ios::binary) << triangleBuffer();
        std::ofstream(dir / "tri.gltf") << gltf("", "tri.bin");
    }
    Model m;
    CHECK(loadGltf(dir / "tri.gltf", m) == "");
    CHECK(m.vertices.size() == 3);

    for (const Model& prop : {generateTree(1), generateRock(1), generateHouse(), generateLantern()}) {
        CAPTURE(prop.name);
        Model back;
        REQUIRE(loadGltfFromMemory(modelToGlb(prop), "", prop.name, back) == "");
        // Primitives sharing one vertex accessor get their own copies (one vertex run per primitive).
        CHECK(back.vertices.size() >= prop.vertices.size());
        CHECK(back.lods[0].triangles() == prop.lods[0].triangles());
        CHECK(back.materials.size() == prop.materials.size());
        for (std::size_t k = 0; k < prop.materials.size(); ++k) {
            CHECK(back.materials[k].alpha_mode == prop.materials[k].alpha_mode);
            CHECK(back.materials[k].double_sided == prop.materials[k].double_sided);
            CHECK(glm::length(back.materials[k].emissive - prop.materials[k].emissive) < 1e-6f);
        }
        CHECK(back.images.size() == prop.images.size());
        CHECK(glm::length(back.bounds_max - prop.bounds_max) < 1e-5f);
    }
    // The same seed writes the same bytes; another seed another tree.
    CHECK(modelToGlb(generateTree(1)) == modelToGlb(generateTree(1)));
    CHECK(modelToGlb(generateTree(1)) != modelToGlb(generateTree(2)));
    std::filesystem::remove_all(dir);
}

TEST_CASE("gltf: props have what the scene needs: leaf cards masked, windows emissive, lantern glass blended, sizes") {
    const Model tree = generateTree(1), house = generateHouse(), rock = generateRock(1), lantern = generateLantern();
    bool mask = false, emissive = false;
    for (const ModelMaterial& mat : tree.materials) mask |= mat.alpha_mode == AlphaMode::Mask && mat.double_sided && mat.base_color_texture == 0;
    for (const ModelMaterial& mat : house.materials) emissive |= mat.emissive.r > 0.5f;
    CHECK(mask);
    CHECK(emissive);
    CHECK(tree.bounds_max.y > 6.0f);
    CHECK(tree.bounds_max.y < 20.0f);
    CHECK(house.bounds_max.y == doctest::Approx(5.6f));
    CHECK(rock.bounds_max.y < 1.0f);
    // The lantern's glass is blended, double-sided and see-through around the lamp's 2.5 m; the
    // rest is opaque.
    int blended = 0;
    for (const ModelMaterial& mat : lantern.materials)
        if (mat.alpha_mode == AlphaMode::Blend) {
            ++blended;
            CHECK(mat.double_sided);
            CHECK(mat.base_color.a < 0.5f);
        }
    CHECK(blended == 1);
    CHECK(lantern.materials.size() == 2);
    CHECK(lantern.bounds_max.y > 2.5f);
    CHECK(lantern.bounds_max.y < 3.5f);
    // The leaf texture has both holes and leaves (what the alpha test cuts).
    int holes = 0, leaves = 0;
    for (std::size_t p = 3; p < tree.images[0].rgba.size(); p += 4) (tree.images[0].rgba[p] ? leaves : holes)++;
    CHECK(holes > 200);
    CHECK(leaves > 200);
}

TEST_CASE("gltf: vertex clustering LODs keep fewer triangles, the bounds and every material") {
    Model tree = generateTree(1);
    const std::uint64_t full = tree.lods[0].triangles();
    buildLods(tree, {12, 4});
    REQUIRE(tree.lods.size() == 3);
    CHECK(tree.lods[1].triangles() < full);
    CHECK(tree.lods[2].triangles() < tree.lods[1].triangles());
    CHECK(tree.lods[2].triangles() > 0);
    for (const ModelLod& lod : tree.lods)
        for (const ModelPrimitive& p : lod.primitives) {
            CHECK(p.first_index + p.index_count <= tree.indices.size());
            for (std::uint32_t i = 0; i < p.index_count; ++i) CHECK(tree.indices[p.first_index + i] < tree.vertices.size());
        }
    for (const MeshVertex& v : tree.vertices) {
        CHECK(glm::all(glm::greaterThanEqual(v.position, tree.bounds_min - 1e-4f)));
        CHECK(glm::all(glm::lessThanEqual(v.position, tree.bounds_max + 1e-4f)));
    }
}
