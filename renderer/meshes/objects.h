// Objects: glTF models ([objects] object.NAME) and scattered ones (scatter.NAME) drawn instanced
// into the G-buffer. prepare() loads the models (renderer/meshes/gltf_loader.h), builds two
// simplified LODs (mesh_lod.h), places the instances (terrain/scatter/scatter.h, over the whole
// terrain, once per change of the settings) and uploads them. Each frame:
//   "objects.cull"    (compute) frustum + distance culling of every instance on the GPU into
//                     per-(model, LOD) lists and a shadow-caster list, then the indirect
//                     commands' instance counts: the CPU's work does not grow with the instances;
//   "objects.gbuffer" one indirect draw per (model, LOD, material) into the G-buffer, emissive
//                     into the HDR target;
// and drawShadow() draws the caster lists into the sun cascades and the spot atlas. Without
// entries (or with [objects] off) the frame makes no Objects: no pass, no memory.
#pragma once

#include "config/input_error.h"
#include "renderer/frame_graph.h"
#include "renderer/gl/objects.h"
#include "renderer/meshes/model.h"
#include "renderer/pass_timers.h"
#include "renderer/render_context.h"
#include "renderer/scene_targets.h"
#include "terrain/scatter/object_settings.h"
#include "terrain/scatter/scatter.h"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace vista {

// Bytes of one instance on the GPU (ObjectInstance in object_common.glsl) and of its list slots
// (one per view LOD group it could join and one shadow slot).
constexpr std::size_t kObjectInstanceBytes = 32;
constexpr std::size_t kObjectSlotBytes = 4 * 4;

struct ObjectStats {
    std::size_t models = 0;
    std::size_t instances = 0;      // placed
    std::uint64_t triangles = 0;    // of every model's full LOD
    std::size_t memory_bytes = 0;
    double place_ms = 0.0;          // CPU time of the last placement
};

// The world area scatter rules cover: [min, max] in x and z (the terrain's extent).
struct ScatterArea {
    glm::dvec2 min{0.0}, max{0.0};
};

class Objects {
public:
    // Loads and places what s lists (resolve turns a scene path into a file); problems name the
    // entry and the file. Cheap when nothing changed. Returns false when nothing is to be drawn.
    bool prepare(const ObjectsSettings& s, const GroundFunction& ground, const ScatterArea& area,
                 const std::function<std::filesystem::path(const std::string&)>& resolve, InputErrors& errors);

    // "objects.cull"; `after`: a buffer the pass must follow (the frame's other shadow casters,
    // so one caster handle orders the shadow passes after both). Returns the culled lists.
    BufferHandle addCullPass(FrameGraph& graph, const RenderContext& rc, const ObjectsSettings& s, CounterReadback& counters,
                             bool count, BufferHandle after = {});
    void addGbufferPass(FrameGraph& graph, const RenderContext& rc, BufferHandle lists, SceneTargets& targets);
    // The shadow-caster list depth-only through matrix (camera-relative world -> clip).
    void drawShadow(const RenderContext& rc, const glm::mat4& matrix) const;

    const ObjectStats& stats() const { return stats_; }
    std::size_t memoryBytes() const { return stats_.memory_bytes; }
    const std::vector<Model>& models() const { return models_; }
    // Placed instances per model, in upload order (tests).
    const std::vector<std::vector<PlacedObject>>& placed() const { return placed_; }
    GLuint countsBuffer() const { return counts_.id(); }  // uint per group (model * 4 + k), tests

private:
    struct Draw {
        int model = 0, group = 0, material = 0;
        std::uint32_t region = 0;
        std::size_t offset = 0;  // bytes into draws_
        bool shadow = false;
    };
    struct Texture {
        gl::Texture texture;
    };
    void upload(float emissive_nits);
    void drawList(const RenderContext& rc, const glm::mat4& matrix, bool shadow) const;

    ObjectsSettings placed_for_;
    bool has_placement_ = false;
    std::vector<std::string> files_;           // resolved model files, one per model
    std::vector<Model> models_;
    std::vector<std::vector<PlacedObject>> placed_;  // per model
    glm::dvec3 anchor_{0.0};
    std::vector<Draw> draws_list_;
    std::vector<std::vector<int>> image_textures_;  // per model, per image: texture index (sRGB) ...
    std::vector<std::vector<int>> image_linear_;    // ... and linear
    std::vector<gl::Texture> textures_;
    gl::Texture white_, flat_normal_;
    gl::Sampler sampler_;
    gl::Buffer vertices_, indices_, instances_, models_buffer_, visible_, counts_, draws_;
    gl::VertexArray vao_;
    std::size_t instance_count_ = 0, group_count_ = 0;
    float emissive_nits_ = 0.0f;
    ObjectStats stats_;
};

std::vector<std::pair<std::string, std::vector<std::string>>> objectPrograms();

}  // namespace vista
