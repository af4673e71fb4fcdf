// Objects: glTF models ([objects] object.NAME) and scattered ones (scatter.NAME) drawn instanced
// into the G-buffer. place() loads the models (renderer/meshes/gltf_loader.h), builds two
// simplified LODs (mesh_lod.h) and uploads the instances it is given (placed_objects.h: the app
// places [objects]' lists over the terrain with terrain/scatter/scatter.h, once per change of the
// lists). Each frame:
//   "objects.cull"    (compute) frustum + distance culling of every instance on the GPU into
//                     per-(model, LOD) lists and a shadow-caster list, then the indirect
//                     commands' instance counts: the CPU's work does not grow with the instances;
//   "objects.gbuffer" one indirect draw per (model, LOD, material) into the G-buffer, emissive
//                     into the HDR target, and one per model of its octahedral impostors
//                     (renderer/meshes/impostor.h: baked at the first frame that draws them)
//                     beyond impostor_distance_m, dithered into the mesh over impostor_fade_m;
// and drawShadow() draws the caster lists into the sun cascades and the spot atlas. Without
// entries (or with [objects] off) the frame makes no Objects: no pass, no memory.
#pragma once

#include "config/input_error.h"
#include "renderer/aerial_volume.h"
#include "renderer/frame_graph.h"
#include "renderer/gl/objects.h"
#include "renderer/meshes/model.h"
#include "renderer/meshes/object_draw_settings.h"
#include "renderer/meshes/placed_objects.h"
#include "renderer/pass_timers.h"
#include "renderer/render_context.h"
#include "renderer/scene_targets.h"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace vista {

struct ObjectBlock;  // object.glsl's uniforms (shaders/object_block.glsl)

// A shadow map a forward pass samples: the pass reads `map`, bind(map texture) binds it with its
// samplers and uniforms, unbind() puts the samplers back (invalid map: unshadowed).
struct ForwardShadow {
    TextureHandle map;
    std::function<void(GLuint)> bind;
    std::function<void()> unbind;
    bool valid() const { return map.valid(); }
};
// The light a forward pass needs besides FrameUniforms (renderer/meshes cannot include the
// lighting: the frame passes what its sun, sky and local lights give).
struct ForwardLight {
    glm::vec3 sun_irradiance{0.0f}, sky_up{0.0f}, ground_up{0.0f};  // as renderer/lighting/deferred.h SunAndSky
    std::string lights_define;          // LocalLights::define() ("" without local lights)
    std::function<void()> bind_lights;  // LocalLights::bindForForward()
    // Each surface is shaded in light_chunks draws of light_chunk lights (LocalLights::chunks(),
    // kLightChunk): the blended one, then the rest added where its depth is equal.
    std::uint32_t light_chunk = 0, light_chunks = 1;
    ForwardShadow sun_shadow;     // the sun's cascades (renderer/shadows/sun_shadows.h SunShadowInput)
    ForwardShadow spot_shadows;   // the local lights' spot atlas (spot_shadows.h SpotShadowInput), with lights only
    ForwardShadow point_shadows;  // their point cubes (point_shadows.h PointShadowInput), with lights only
};
// Which BLEND surfaces a transparent pass draws when the sea is on. The sea refracts and absorbs
// the scene it copies, so glass beyond the water plane (seen through the surface from the eye's
// side) is drawn before "water.surface" into that scene, as an opaque object there is; glass on
// the eye's side is drawn after it, over the sea. Each is clipped at the still surface level.
enum class TransparentSide { BeyondWater, EyeSide };
// Transparent (instance, primitive) pairs sorted and drawn per frame at most (the nearest).
constexpr std::size_t kMaxTransparentItems = 4096;

// Lists per model (object_common.glsl OBJECT_GROUPS): LOD 0..2, shadow casters, impostors.
constexpr int kObjectGroups = 5;
// Bytes of one instance on the GPU (ObjectInstance in object_common.glsl) and of its list slots
// (one per group it could join).
constexpr std::size_t kObjectInstanceBytes = 32;
constexpr std::size_t kObjectSlotBytes = 4 * kObjectGroups;

struct ObjectStats {
    std::size_t models = 0;
    std::size_t instances = 0;      // placed
    std::uint64_t triangles = 0;    // of every model's full LOD
    std::size_t memory_bytes = 0;
    double place_ms = 0.0;          // CPU time of the last place() (loading, LODs, upload)
    std::size_t impostor_bytes = 0; // of the baked atlases (0 until baked)
};

class Objects {
public:
    // Loads the models placements name (resolve turns a scene path into a file; problems name the
    // entry and the file, a model that fails leaves its instances out) and uploads the instances,
    // model by model in the order given. Returns false when nothing is to be drawn.
    bool place(const std::vector<ObjectPlacement>& placements,
               const std::function<std::filesystem::path(const std::string&)>& resolve, InputErrors& errors);
    // Replaces the instances with placements' when they list the entries and files place() was
    // given (a camera-local scatter moving with the view): the models, their LODs, textures and
    // impostors stay. False (nothing changed) when the lists differ: place() them instead.
    bool replaceInstances(const std::vector<ObjectPlacement>& placements);
    // The luminance of emissive factor 1 (ObjectDrawSettings::emissive_nits) the draws use.
    void setEmissive(float nits) { emissive_nits_ = nits; }

    // "objects.cull"; `after`: a buffer the pass must follow (the frame's other shadow casters,
    // so one caster handle orders the shadow passes after both). Returns the culled lists.
    BufferHandle addCullPass(FrameGraph& graph, const RenderContext& rc, const ObjectDrawSettings& s, CounterReadback& counters,
                             bool count, BufferHandle after = {});
    void addGbufferPass(FrameGraph& graph, const RenderContext& rc, const ObjectDrawSettings& s, BufferHandle lists,
                        SceneTargets& targets);
    // The shadow-caster list depth-only through matrix (camera-relative world -> clip); adds its
    // triangles to objects.shadow_triangles when the cull pass counted.
    void drawShadow(const RenderContext& rc, const glm::mat4& matrix) const;
    // The casters within radius_m of a point light at centre (world; picked on the CPU from the
    // placed instances, not the cull pass's lists; their full LOD 0 meshes) into its views:
    // before(i) binds view i's target, then they are drawn with matrices[i]. For the point-light
    // cubes (renderer/shadows/point_shadows.h), which would otherwise draw every caster of the
    // shadow distance six times a light.
    void drawShadowNear(const RenderContext& rc, const glm::dvec3& centre, double radius_m,
                        std::span<const glm::mat4> matrices, const std::function<void(std::size_t)>& before);
    // Renders every model's impostor atlas (once; the cull pass's gbuffer pass calls it when
    // impostors can be drawn). Public for the tests.
    void bakeImpostors(const RenderContext& rc);
    bool impostorsBaked() const { return baked_; }
    // Sorts this frame's BLEND items (renderer/meshes/objects_forward.cpp) back to front per
    // (instance, primitive) and uploads the lists; water_level_m: the sea's still surface (NaN:
    // no sea, one list), wave_height_m: how far its waves reach above and below it (the split
    // between the sides is the wave band's edge beyond the eye: objects_forward.cpp). Call once a
    // frame before the passes.
    void sortTransparent(const RenderContext& rc, const ObjectDrawSettings& s, double water_level_m, double wave_height_m = 0.0);
    // "objects.transparent" (EyeSide) and "objects.transparent_beyond_water": the sorted items of
    // that side, forward lit and blended into targets.hdr. Adds nothing when the side has none.
    // fog (valid): the pass comes after "sky.aerial" and each surface fogs itself with the volume
    // at its own distance (variant AERIAL_FOG); otherwise the aerial pass, if any, is still to come.
    void addTransparentPass(FrameGraph& graph, const RenderContext& rc, const ForwardLight& light, SceneTargets& targets,
                            TransparentSide side, const AerialVolume& fog = {});
    bool hasTransparent() const { return !blend_.empty(); }
    std::size_t transparentDrawn() const { return transparent_drawn_; }      // this frame's sorted items
    std::size_t transparentBeyondWater() const { return sides_[0].items.size(); }  // of them drawn before the sea
    // The highest world height this frame's eye-side items reach (-infinity: none).
    double transparentTop() const { return transparent_top_; }
    std::size_t transparentDropped() const { return transparent_dropped_; }  // beyond kMaxTransparentItems
    void setSortTransparent(bool on) { sort_transparent_ = on; }  // tests: off draws in placement order

    const ObjectStats& stats() const { return stats_; }
    // The lowest world height a placed instance's bounding sphere reaches (+infinity: none placed).
    double lowestPoint() const;
    std::size_t memoryBytes() const { return stats_.memory_bytes; }
    const std::vector<Model>& models() const { return models_; }
    // Placed instances per model, in upload order (tests).
    const std::vector<std::vector<PlacedObject>>& placed() const { return placed_; }
    GLuint countsBuffer() const { return counts_.id(); }  // uint per group (model * kObjectGroups + k), tests

private:
    struct Draw {
        int model = 0, group = 0, material = 0;
        std::uint32_t region = 0;
        std::size_t offset = 0;  // bytes into draws_
        bool shadow = false, impostor = false;
    };
    struct Blend {
        int model = 0;
        ModelPrimitive primitive;
        glm::vec3 centre{0.0f};  // model space, of the primitive's bounds
        float low_y = 0.0f, high_y = 0.0f;  // model space, the bounds' lowest and highest y
        std::uint32_t first_instance = 0;  // the model's first instance in the upload order
    };
    void collectBlend();
    struct Impostor {
        gl::Texture emissive, albedo, normal;  // the G-buffer's encodings, kImpostorFrames^2 frames
    };
    struct Texture {
        gl::Texture texture;
    };
    void upload();           // uploadModels(), then uploadInstances()
    void uploadModels();     // vertices, indices, textures; drops the impostors
    void uploadInstances();  // placed_: instances, per-model regions, indirect commands
    void drawList(const RenderContext& rc, const glm::mat4& matrix, bool shadow, const ObjectDrawSettings* fade) const;
    void drawImpostors(const RenderContext& rc, const ObjectDrawSettings& s) const;
    // Sets a material's factors in block, binds its textures and sets its face culling.
    void setMaterial(ObjectBlock& block, int model, int material, float emissive_nits, bool shadow) const;

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
    std::vector<Impostor> impostors_;  // per model, once baked
    std::vector<glm::vec4> spheres_;   // per model: bounding sphere (centre, radius), model space
    std::vector<std::uint32_t> vertex_base_, index_base_;
    std::uint32_t quad_vertex_ = 0, quad_index_ = 0;  // the impostor card's first vertex and index
    std::size_t model_bytes_ = 0;                      // uploadModels()'s buffers and textures
    std::uint64_t model_triangles_ = 0;                // every model's full LOD
    // What place() was given: per placement its entry, its files and their models (-1: failed).
    std::vector<std::pair<std::string, std::vector<std::string>>> entries_;
    std::vector<std::vector<int>> entry_models_;
    bool baked_ = false;
    std::vector<Blend> blend_;
    struct SortedItem {
        std::uint32_t slot;  // in forward_list_ (the instance index is there)
        int blend;
    };
    struct Side {
        std::vector<SortedItem> items;  // back to front
        glm::vec4 clip{0.0f};           // camera-relative plane: kept where dot(clip, (p, 1)) >= 0
        bool clipped = false;
    };
    Side sides_[2];            // TransparentSide::BeyondWater, EyeSide
    gl::Buffer forward_list_;  // this frame's sorted instance indices, both sides
    gl::Buffer near_list_;     // drawShadowNear's instance indices, per model
    std::vector<std::uint32_t> near_scratch_;
    bool sort_transparent_ = true;
    std::size_t transparent_drawn_ = 0, transparent_dropped_ = 0;
    double transparent_top_ = 0.0;
    GLuint shadow_counter_ = 0;        // this frame's objects.shadow_triangles buffer, 0: not counting
    std::size_t instance_count_ = 0, group_count_ = 0;
    float emissive_nits_ = 0.0f;
    ObjectStats stats_;
};

ProgramList objectPrograms();
// The defines of "objects.transparent"'s program (object.glsl FORWARD): the local lights' method
// ("" without), their spot and point shadows (with a method only), the aerial fog; the pass adds
// HAS_SUN_SHADOW or LIGHT_CHUNK. objectPrograms() lists every combination from it.
std::vector<std::string> forwardDefines(const std::string& lights_define, bool spot_shadows, bool point_shadows, bool fog);

}  // namespace vista
