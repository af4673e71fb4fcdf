// A mesh model as the renderer uses it, without GL: one vertex and index array per model with
// the glTF node transforms baked in, its materials (metallic-roughness PBR) and decoded RGBA8
// images. Loaded from glTF 2.0 (renderer/meshes/gltf_loader.h), simplified into LODs
// (renderer/meshes/mesh_lod.h), uploaded and instanced by renderer/meshes/objects.h.
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace vista {

// 48 bytes, the vertex layout of renderer/meshes/shaders/object.glsl (locations 0..3).
struct MeshVertex {
    glm::vec3 position{0.0f};  // model space, m
    glm::vec3 normal{0.0f, 1.0f, 0.0f};
    glm::vec4 tangent{0.0f};   // xyz tangent, w handedness; w = 0: none (the shader derives one)
    glm::vec2 uv{0.0f};
};
static_assert(sizeof(MeshVertex) == 48);

enum class AlphaMode : int { Opaque, Mask, Blend };

struct ModelImage {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgba;  // width * height * 4, top row first, sRGB or linear by use
};

// glTF 2.0 metallic-roughness material; texture fields index Model::images (-1: none).
struct ModelMaterial {
    glm::vec4 base_color{1.0f};       // linear RGBA factor
    float metallic = 1.0f;            // glTF defaults
    float roughness = 1.0f;
    glm::vec3 emissive{0.0f};         // linear factor (x emissive texture)
    float normal_scale = 1.0f;
    float occlusion_strength = 1.0f;
    AlphaMode alpha_mode = AlphaMode::Opaque;
    float alpha_cutoff = 0.5f;
    bool double_sided = false;
    int base_color_texture = -1;          // sRGB
    int metallic_roughness_texture = -1;  // linear: g roughness, b metallic
    int normal_texture = -1;              // linear tangent-space
    int occlusion_texture = -1;           // linear: r
    int emissive_texture = -1;            // sRGB
};

// A run of triangles with one material: indices [first_index, first_index + index_count).
struct ModelPrimitive {
    std::uint32_t first_index = 0, index_count = 0;
    int material = 0;
};

// One level of detail: primitives over the model's vertex and index arrays.
struct ModelLod {
    std::vector<ModelPrimitive> primitives;
    std::uint64_t triangles() const {
        std::uint64_t n = 0;
        for (const ModelPrimitive& p : primitives) n += p.index_count / 3;
        return n;
    }
};

struct Model {
    std::string name;                  // the file, for messages
    std::vector<MeshVertex> vertices;  // every LOD's vertices
    std::vector<std::uint32_t> indices;
    std::vector<ModelLod> lods;        // lods[0]: as loaded; coarser ones appended by buildLods()
    std::vector<ModelMaterial> materials;  // at least one (glTF's default material when none given)
    std::vector<ModelImage> images;
    glm::vec3 bounds_min{0.0f}, bounds_max{0.0f};  // model space, of lods[0]
    float radius() const;              // bounding sphere radius about the model origin, m
    bool hasBlend() const;
};

}  // namespace vista
