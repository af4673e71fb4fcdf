// Vertex clustering LODs (see mesh_lod.h).
#include "renderer/meshes/mesh_lod.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <tuple>

namespace vista {

void buildLods(Model& model, const std::vector<int>& cells_list) {
    if (model.lods.empty()) return;
    const ModelLod source = model.lods.front();
    const glm::vec3 lo = model.bounds_min, extent = glm::max(model.bounds_max - model.bounds_min, glm::vec3(1e-6f));
    const float longest = std::max({extent.x, extent.y, extent.z});
    for (int cells : cells_list) {
        const float cell = longest / float(std::max(1, cells));
        ModelLod lod;
        for (const ModelPrimitive& p : source.primitives) {
            // Cluster key: integer cell coordinates; one output vertex per (cell) within this material.
            std::map<std::tuple<int, int, int>, std::uint32_t> slot;
            std::vector<MeshVertex> sums;
            std::vector<int> counts;
            std::vector<std::uint32_t> remap;  // source index -> cluster
            auto cluster = [&](std::uint32_t vi) {
                const MeshVertex& v = model.vertices[vi];
                const glm::ivec3 c = glm::ivec3(glm::floor((v.position - lo) / cell));
                auto [it, added] = slot.try_emplace({c.x, c.y, c.z}, std::uint32_t(sums.size()));
                if (added) {
                    sums.push_back(MeshVertex{glm::vec3(0.0f), glm::vec3(0.0f), glm::vec4(0.0f), glm::vec2(0.0f)});
                    counts.push_back(0);
                }
                MeshVertex& s = sums[it->second];
                s.position += v.position;
                s.normal += v.normal;
                s.tangent += glm::vec4(glm::vec3(v.tangent), 0.0f);
                s.tangent.w = v.tangent.w;
                s.uv += v.uv;
                ++counts[it->second];
                return it->second;
            };
            for (std::uint32_t i = 0; i < p.index_count; ++i) remap.push_back(cluster(model.indices[p.first_index + i]));
            const std::uint32_t base = std::uint32_t(model.vertices.size());
            for (std::size_t k = 0; k < sums.size(); ++k) {
                MeshVertex v = sums[k];
                const float n = float(counts[k]);
                v.position /= n;
                v.uv /= n;
                const float nl = glm::length(v.normal);
                v.normal = nl > 1e-12f ? v.normal / nl : glm::vec3(0.0f, 1.0f, 0.0f);
                const glm::vec3 t = glm::vec3(v.tangent);
                const float tl = glm::length(t);
                v.tangent = tl > 1e-12f && v.tangent.w != 0.0f ? glm::vec4(t / tl, v.tangent.w) : glm::vec4(0.0f);
                model.vertices.push_back(v);
            }
            ModelPrimitive out{std::uint32_t(model.indices.size()), 0, p.material};
            std::map<std::tuple<std::uint32_t, std::uint32_t, std::uint32_t>, bool> seen;  // drop duplicate triangles
            for (std::size_t i = 0; i + 2 < remap.size(); i += 3) {
                const std::uint32_t a = remap[i], b = remap[i + 1], c = remap[i + 2];
                if (a == b || b == c || a == c) continue;
                // Same triangle in the same winding, whichever corner comes first.
                const std::uint32_t m = std::min({a, b, c});
                const auto key = m == a ? std::make_tuple(a, b, c) : m == b ? std::make_tuple(b, c, a) : std::make_tuple(c, a, b);
                if (!seen.emplace(key, true).second) continue;
                model.indices.insert(model.indices.end(), {base + a, base + b, base + c});
                out.index_count += 3;
            }
            if (out.index_count > 0) lod.primitives.push_back(out);
        }
        if (lod.primitives.empty()) lod = model.lods.back();
        model.lods.push_back(std::move(lod));
    }
}

}  // namespace vista
