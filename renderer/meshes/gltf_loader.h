// glTF 2.0 (.gltf with external or data: buffers and images, and .glb) into a Model, through
// tinygltf (Debian libtinygltf-dev). What is read: every node of the default scene (or of
// scene 0) with its transform (matrix or TRS) baked into the vertices, triangle primitives
// (POSITION; NORMAL, TANGENT, TEXCOORD_0 where given, else derived), uint8/16/32 or no indices,
// metallic-roughness materials with base colour, metallic-roughness, normal, occlusion and
// emissive textures, alpha modes opaque/mask/blend, double-sided. Everything else that the file
// requires (extensionsRequired, sparse accessors, non-triangle modes, morph targets used
// as required) is refused with a message naming the file and the element. Limits keep a
// hostile file from taking all memory (kMaxModelVertices, kMaxModelImagePixels).
#pragma once

#include "renderer/meshes/model.h"

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace vista {

constexpr std::size_t kMaxModelVertices = std::size_t(1) << 24;      // per model, all primitives
constexpr std::size_t kMaxModelImagePixels = std::size_t(1) << 26;  // per model, all images

// Loads path (.gltf or .glb by content). "" on success, else "FILE: what is wrong".
std::string loadGltf(const std::filesystem::path& path, Model& out);
// The same from bytes in memory (the fuzz target and tests); external files are looked up in
// base_dir ("" refuses them). name is used in messages.
std::string loadGltfFromMemory(std::string_view bytes, const std::filesystem::path& base_dir, const std::string& name,
                               Model& out);

}  // namespace vista
