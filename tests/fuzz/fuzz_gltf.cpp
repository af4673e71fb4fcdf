// libFuzzer target: glTF and GLB files. Any bytes must load or be refused with a message naming
// the file, never crash or read out of bounds; a model that loads has every index inside its
// vertex array, every primitive's material and texture inside their arrays, finite positions,
// and survives the LOD builder.
#include "renderer/meshes/gltf_loader.h"
#include "renderer/meshes/mesh_lod.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
    vista::Model m;
    const std::string why = vista::loadGltfFromMemory(bytes, "", "fuzz.gltf", m);  // external files refused
    if (!why.empty()) {
        if (why.rfind("fuzz.gltf: ", 0) != 0) std::abort();
        return 0;
    }
    auto checkTexture = [&](int t) {
        if (t >= int(m.images.size())) std::abort();
    };
    for (const vista::ModelMaterial& mat : m.materials) {
        checkTexture(mat.base_color_texture);
        checkTexture(mat.metallic_roughness_texture);
        checkTexture(mat.normal_texture);
        checkTexture(mat.occlusion_texture);
        checkTexture(mat.emissive_texture);
    }
    for (const vista::MeshVertex& v : m.vertices)
        if (!std::isfinite(v.position.x) || !std::isfinite(v.position.y) || !std::isfinite(v.position.z)) std::abort();
    vista::buildLods(m, {8});
    for (const vista::ModelLod& lod : m.lods)
        for (const vista::ModelPrimitive& p : lod.primitives) {
            if (p.material < 0 || std::size_t(p.material) >= m.materials.size()) std::abort();
            if (std::size_t(p.first_index) + p.index_count > m.indices.size()) std::abort();
            for (std::uint32_t i = 0; i < p.index_count; ++i)
                if (m.indices[p.first_index + i] >= m.vertices.size()) std::abort();
        }
    return 0;
}
