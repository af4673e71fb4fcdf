// Objects: loading, upload and the cull, G-buffer and shadow draws (see objects.h).
#include "renderer/meshes/objects.h"

#include "renderer/bindings.h"
#include "renderer/frustum.h"
#include "renderer/gl_device.h"
#include "renderer/pass_kit.h"
#include "renderer/meshes/gltf_loader.h"
#include "renderer/meshes/impostor.h"
#include "renderer/meshes/mesh_lod.h"

#include <glm/trigonometric.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>

namespace vista {

#include "renderer/meshes/shaders/object_block.glsl"

namespace {

#include "renderer/meshes/shaders/impostor_block.glsl"
#include "renderer/meshes/shaders/object_cull_block.glsl"

struct GpuInstance {
    glm::vec4 position_yaw;
    glm::vec4 params;
};
static_assert(sizeof(GpuInstance) == kObjectInstanceBytes);
struct GpuModel {
    glm::vec4 sphere;
    glm::uvec4 region;
    glm::uvec4 triangles;
    glm::uvec4 impostor;  // x: region, y: triangles
};
struct DrawCommand {
    std::uint32_t count, instance_count, first_index;
    std::int32_t base_vertex;
    std::uint32_t base_instance;  // the group (object_cull.glsl FIXUP_DRAWS reads it)
};

// Grid cells of the two simplified LODs along the model's longest side.
const std::vector<int> kLodCells = {10, 4};
constexpr int kShadowLod = 1;
constexpr int kShadowGroup = 3, kImpostorGroup = 4;

gl::Texture solidTexture(std::uint8_t r, std::uint8_t g, std::uint8_t b, GLenum format, const char* name) {
    gl::Texture t = gl::Texture::create2D(1, 1, format, 1, name);
    const std::uint8_t px[4] = {r, g, b, 255};
    glTextureSubImage2D(t.id(), 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    return t;
}

}  // namespace

ProgramList objectPrograms() {
    ProgramList programs = {
            {"renderer/meshes/shaders/object_cull.glsl", {}},
            {"renderer/meshes/shaders/object_cull.glsl", {"FIXUP_DRAWS"}},
            {"renderer/meshes/shaders/object_cull.glsl", {"COUNT_SHADOW"}},
            {"renderer/meshes/shaders/object.glsl", {}},
            {"renderer/meshes/shaders/object.glsl", {"ALPHA_MASK"}},
            {"renderer/meshes/shaders/object.glsl", {"IMPOSTOR_FADE"}},
            {"renderer/meshes/shaders/object.glsl", {"IMPOSTOR_FADE", "ALPHA_MASK"}},
            {"renderer/meshes/shaders/impostor.glsl", {}},
            {"renderer/meshes/shaders/object.glsl", {"SHADOW_PASS"}},
            {"renderer/meshes/shaders/object.glsl", {"SHADOW_PASS", "ALPHA_MASK"}}};
    // objects.transparent: every combination forwardDefines() can give, each with the sun's
    // shadows or not and, with local lights, the further light chunks (objects_forward.cpp).
    const char* forward = "renderer/meshes/shaders/object.glsl";
    for (const char* method : {"", "LIGHTS_NAIVE", "LIGHTS_TILED", "LIGHTS_CLUSTERED", "LIGHTS_HASHED"}) {
        const bool lit = method[0] != '\0';
        for (int shadows = 0; shadows < (lit ? 4 : 1); ++shadows)
            for (bool fog : {false, true}) {
                std::vector<std::string> defines = forwardDefines(method, (shadows & 1) != 0, (shadows & 2) != 0, fog);
                programs.push_back({forward, defines});
                for (const char* extra : {"HAS_SUN_SHADOW", "LIGHT_CHUNK"}) {
                    if (!lit && std::string(extra) == "LIGHT_CHUNK") continue;
                    std::vector<std::string> with = defines;
                    with.push_back(extra);
                    programs.push_back({forward, with});
                }
            }
    }
    return programs;
}

bool Objects::place(const std::vector<ObjectPlacement>& placements,
                    const std::function<std::filesystem::path(const std::string&)>& resolve, InputErrors& errors) {
    const auto start = std::chrono::steady_clock::now();
    files_.clear();
    models_.clear();
    placed_.clear();
    std::map<std::string, int> index;  // resolved file -> model
    auto model = [&](const std::string& file, const std::string& entry) -> int {
        const std::string path = resolve(file).string();
        auto it = index.find(path);
        if (it != index.end()) return it->second;
        Model m;
        if (std::string why = loadGltf(path, m); !why.empty()) {
            errors.push_back({"[objects] " + entry, 0, why});
            index[path] = -1;
            return -1;
        }
        buildLods(m, kLodCells);
        models_.push_back(std::move(m));
        placed_.emplace_back();
        files_.push_back(path);
        return index[path] = int(models_.size()) - 1;
    };
    entries_.clear();
    entry_models_.clear();
    for (const ObjectPlacement& placement : placements) {
        std::vector<int> ms;
        for (const std::string& f : placement.files) ms.push_back(model(f, placement.entry));
        for (const PlacedObject& p : placement.instances) {
            const int m = ms[std::size_t(p.file)];
            if (m >= 0) placed_[std::size_t(m)].push_back(p);
        }
        entries_.emplace_back(placement.entry, placement.files);
        entry_models_.push_back(std::move(ms));
    }
    upload();
    stats_.place_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return stats_.instances > 0;
}

bool Objects::replaceInstances(const std::vector<ObjectPlacement>& placements) {
    if (placements.size() != entries_.size()) return false;
    for (std::size_t i = 0; i < placements.size(); ++i)
        if (placements[i].entry != entries_[i].first || placements[i].files != entries_[i].second) return false;
    const auto start = std::chrono::steady_clock::now();
    for (auto& list : placed_) list.clear();
    for (std::size_t i = 0; i < placements.size(); ++i)
        for (const PlacedObject& p : placements[i].instances) {
            const int m = entry_models_[i][std::size_t(p.file)];
            if (m >= 0) placed_[std::size_t(m)].push_back(p);
        }
    uploadInstances();
    stats_.place_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return true;
}

void Objects::upload() {
    uploadModels();
    uploadInstances();
}

void Objects::uploadModels() {
    textures_.clear();
    image_textures_.clear();
    image_linear_.clear();
    vertices_ = {};
    indices_ = {};
    vao_ = {};
    impostors_.clear();
    spheres_.clear();
    baked_ = false;
    model_bytes_ = 0;
    model_triangles_ = 0;
    if (models_.empty()) return;

    // One vertex and index array for every model (offsets applied per draw).
    std::vector<MeshVertex> vertices;
    std::vector<std::uint32_t> indices;
    vertex_base_.clear();
    index_base_.clear();
    for (const Model& m : models_) {
        vertex_base_.push_back(std::uint32_t(vertices.size()));
        index_base_.push_back(std::uint32_t(indices.size()));
        vertices.insert(vertices.end(), m.vertices.begin(), m.vertices.end());
        indices.insert(indices.end(), m.indices.begin(), m.indices.end());
        model_triangles_ += m.lods[0].triangles();
        const glm::vec3 centre = 0.5f * (m.bounds_min + m.bounds_max);
        float radius = 0.0f;
        for (const MeshVertex& v : m.vertices) radius = std::max(radius, glm::length(v.position - centre));
        spheres_.push_back(glm::vec4(centre, radius));
    }
    // The impostor card: a unit quad in (right, up), uv from its lower left corner.
    quad_vertex_ = std::uint32_t(vertices.size());
    quad_index_ = std::uint32_t(indices.size());
    for (int c = 0; c < 4; ++c) {
        MeshVertex v;
        v.uv = glm::vec2(float(c == 1 || c == 2), float(c >= 2));
        v.position = glm::vec3(v.uv * 2.0f - 1.0f, 0.0f);
        vertices.push_back(v);
    }
    for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) indices.push_back(i);
    vertices_ = gl::Buffer::create(GLsizeiptr(vertices.size() * sizeof(MeshVertex)), vertices.data(), 0, "objects vertices");
    indices_ = gl::Buffer::create(GLsizeiptr(indices.size() * 4), indices.data(), 0, "objects indices");
    vao_ = gl::createVertexArray("objects");
    glVertexArrayVertexBuffer(vao_.id(), 0, vertices_.id(), 0, sizeof(MeshVertex));
    glVertexArrayElementBuffer(vao_.id(), indices_.id());
    const GLuint offsets[4] = {offsetof(MeshVertex, position), offsetof(MeshVertex, normal), offsetof(MeshVertex, tangent),
                               offsetof(MeshVertex, uv)};
    const GLint sizes[4] = {3, 3, 4, 2};
    for (GLuint a = 0; a < 4; ++a) {
        glEnableVertexArrayAttrib(vao_.id(), a);
        glVertexArrayAttribFormat(vao_.id(), a, sizes[a], GL_FLOAT, GL_FALSE, offsets[a]);
        glVertexArrayAttribBinding(vao_.id(), a, 0);
    }

    // Textures: colour slots (base colour, emissive) in sRGB, data slots linear; made on first use.
    white_ = solidTexture(255, 255, 255, GL_SRGB8_ALPHA8, "objects white");
    flat_normal_ = solidTexture(128, 128, 255, GL_RGBA8, "objects flat normal");
    sampler_ = gl::createSampler(GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, GL_REPEAT, "objects sampler");
    std::size_t texture_bytes = 0;
    for (const Model& model : models_) {
        image_textures_.emplace_back(model.images.size(), -1);
        image_linear_.emplace_back(model.images.size(), -1);
        auto make = [&](int image, bool srgb) {
            if (image < 0) return;
            int& slot_ref = (srgb ? image_textures_.back() : image_linear_.back())[std::size_t(image)];
            if (slot_ref >= 0) return;
            const ModelImage& im = model.images[std::size_t(image)];
            const int levels = 1 + int(std::floor(std::log2(double(std::max(im.width, im.height)))));
            gl::Texture t = gl::Texture::create2D(im.width, im.height, srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8, levels, "objects texture");
            glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
            glTextureSubImage2D(t.id(), 0, 0, 0, im.width, im.height, GL_RGBA, GL_UNSIGNED_BYTE, im.rgba.data());
            glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
            glGenerateTextureMipmap(t.id());
            texture_bytes += t.bytes();
            textures_.push_back(std::move(t));
            slot_ref = int(textures_.size()) - 1;
        };
        for (const ModelMaterial& mat : model.materials) {
            make(mat.base_color_texture, true);
            make(mat.emissive_texture, true);
            make(mat.metallic_roughness_texture, false);
            make(mat.normal_texture, false);
            make(mat.occlusion_texture, false);
        }
    }
    model_bytes_ = std::size_t(vertices_.size() + indices_.size()) + texture_bytes + white_.bytes() + flat_normal_.bytes();
}

void Objects::uploadInstances() {
    const std::size_t impostor_bytes = stats_.impostor_bytes;
    stats_ = ObjectStats{};
    stats_.impostor_bytes = baked_ ? impostor_bytes : 0;
    draws_list_.clear();
    instances_ = {};
    models_buffer_ = {};
    visible_ = {};
    counts_ = {};
    draws_ = {};
    instance_count_ = 0;
    for (const auto& p : placed_) instance_count_ += p.size();
    stats_.models = models_.size();
    stats_.instances = instance_count_;
    stats_.triangles = model_triangles_;
    if (models_.empty()) return;

    // The anchor: instances are stored relative to it in floats (camera-relative in the shaders).
    glm::dvec3 sum(0.0);
    for (const auto& list : placed_)
        for (const PlacedObject& p : list) sum += p.position;
    anchor_ = instance_count_ > 0 ? glm::floor(sum / double(instance_count_)) : glm::dvec3(0.0);

    std::vector<GpuInstance> instances;
    std::vector<GpuModel> gpu_models;
    instances.reserve(instance_count_);
    std::uint32_t slot = 0;
    for (std::size_t m = 0; m < models_.size(); ++m) {
        const Model& model = models_[m];
        const float radius = spheres_[m].w;
        GpuModel g{spheres_[m], glm::uvec4(0), glm::uvec4(0), glm::uvec4(0)};
        const std::uint32_t n = std::uint32_t(placed_[m].size());
        for (int k = 0; k < 4; ++k) {
            g.region[k] = slot;
            slot += n;
            const int lod = k < 3 ? std::min(k, int(model.lods.size()) - 1) : std::min(kShadowLod, int(model.lods.size()) - 1);
            g.triangles[k] = std::uint32_t(model.lods[std::size_t(lod)].triangles());
        }
        g.impostor = glm::uvec4(slot, 2u, 0u, 0u);
        slot += n;
        gpu_models.push_back(g);
        for (const PlacedObject& p : placed_[m])
            instances.push_back({glm::vec4(glm::vec3(p.position - anchor_), p.yaw_rad),
                                 glm::vec4(p.scale, float(m), radius * p.scale, 0.0f)});
    }
    group_count_ = models_.size() * kObjectGroups;

    // Indirect commands: per model, per group k (LOD 0..2, shadow), per primitive; then its impostors.
    std::vector<DrawCommand> commands;
    for (std::size_t m = 0; m < models_.size(); ++m) {
        const Model& model = models_[m];
        for (int k = 0; k < 4; ++k) {
            const int lod = k < 3 ? std::min(k, int(model.lods.size()) - 1) : std::min(kShadowLod, int(model.lods.size()) - 1);
            for (const ModelPrimitive& p : model.lods[std::size_t(lod)].primitives) {
                Draw d;
                d.model = int(m);
                d.group = int(m) * kObjectGroups + k;
                d.material = p.material;
                d.region = gpu_models[m].region[k];
                d.offset = commands.size() * sizeof(DrawCommand);
                d.shadow = k == kShadowGroup;
                draws_list_.push_back(d);
                commands.push_back({p.index_count, 0, index_base_[m] + p.first_index, std::int32_t(vertex_base_[m]),
                                    std::uint32_t(d.group)});
            }
        }
        Draw d;
        d.model = int(m);
        d.group = int(m) * kObjectGroups + kImpostorGroup;
        d.region = gpu_models[m].impostor.x;
        d.offset = commands.size() * sizeof(DrawCommand);
        d.impostor = true;
        draws_list_.push_back(d);
        commands.push_back({6, 0, quad_index_, std::int32_t(quad_vertex_), std::uint32_t(d.group)});
    }
    // At least one instance's room: a camera-local placement may hold none for a while.
    instances.resize(std::max<std::size_t>(instances.size(), 1));
    instances_ = gl::Buffer::create(GLsizeiptr(instances.size() * sizeof(GpuInstance)), instances.data(), 0, "objects instances");
    models_buffer_ = gl::Buffer::create(GLsizeiptr(gpu_models.size() * sizeof(GpuModel)), gpu_models.data(), 0, "objects models");
    visible_ = gl::Buffer::create(GLsizeiptr(std::max<std::uint32_t>(slot, 1) * 4), nullptr, 0, "objects visible lists");
    counts_ = gl::Buffer::create(GLsizeiptr(group_count_ * 4), nullptr, GL_DYNAMIC_STORAGE_BIT, "objects group counts");
    draws_ = gl::Buffer::create(GLsizeiptr(commands.size() * sizeof(DrawCommand)), commands.data(), 0, "objects draws");
    collectBlend();
    stats_.memory_bytes = model_bytes_ + std::size_t(instances_.size() + models_buffer_.size() + visible_.size() +
                                                     counts_.size() + draws_.size()) + stats_.impostor_bytes;
}

BufferHandle Objects::addCullPass(FrameGraph& graph, const RenderContext& rc, const ObjectDrawSettings& s,
                                  CounterReadback& counters, bool count, BufferHandle after) {
    const BufferHandle imported = graph.importBuffer("objects.lists", BufferDesc{std::size_t(visible_.size())}, visible_.id());
    struct Data {
        BufferHandle lists;
    };
    const Data& d = graph.addPass<Data>("objects.cull",
        [&](PassBuilder& b, Data& data) {
            if (after.valid()) b.read(after);
            data.lists = b.write(imported);
        },
        [this, &rc, &s, &counters, count](const Data&, PassContext&) {
            const glm::vec3 camera = glm::vec3(rc.view.position - anchor_);
            const Frustum planes = frustumFromViewProj(glm::dmat4(rc.matrices.view_proj));
            glClearNamedBufferData(counts_.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, nullptr);
            glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
            GLuint program = rc.shaders.id("renderer/meshes/shaders/object_cull.glsl");
            glUseProgram(program);
            ObjectCullBlock block{};
            block.u_count = GLuint(instance_count_);
            block.u_camera = camera;
            block.u_distances = {s.lod1_distance_m, s.lod2_distance_m, s.max_distance_m,
                                 s.cast_shadows ? s.shadow_distance_m : -1.0f};
            block.u_count_enabled = count ? 1u : 0u;
            // Impostors only nearer than max_distance_m (else none: the fade band is empty too).
            const float impostor = s.impostor_distance_m < s.max_distance_m ? s.impostor_distance_m : 2.0f * s.max_distance_m + 1.0f;
            block.u_impostor = {impostor, s.impostor_fade_m};
            for (std::size_t p = 0; p < 5; ++p) block.u_planes[p] = glm::vec4(planes[p]);
            bindPassBlock(rc, program, block);
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kObjectInstances, instances_.id());
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kObjectModels, models_buffer_.id());
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kObjectVisible, visible_.id());
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kObjectCounts, counts_.id());
            if (count) {
                glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kCounters, counters.request(rc.frame, "objects.instances"));
                glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kAux, counters.request(rc.frame, "objects.triangles"));
                glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kAux2, counters.request(rc.frame, "objects.impostors"));
            }
            // The shadow views drawn after this pass add their triangles to this frame's counter.
            shadow_counter_ = count && s.cast_shadows ? counters.request(rc.frame, "objects.shadow_triangles") : 0;
            const std::uint64_t groups = (instance_count_ + 63) / 64;
            const std::uint64_t gx = std::min<std::uint64_t>(groups, 65535), gy = (groups + gx - 1) / gx;
            glDispatchCompute(GLuint(gx), GLuint(gy), 1);
            glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
            GLuint fixup = rc.shaders.id("renderer/meshes/shaders/object_cull.glsl", {"FIXUP_DRAWS"});
            glUseProgram(fixup);
            ObjectCullBlock fixup_block{};
            fixup_block.u_draw_count = GLuint(draws_list_.size());
            bindPassBlock(rc, fixup, fixup_block);
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kObjectDraws, draws_.id());
            glDispatchCompute(GLuint((draws_list_.size() + 63) / 64), 1, 1);
            glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
        });
    return d.lists;
}

void Objects::setMaterial(ObjectBlock& block, int model_index, int material, float emissive_nits, bool shadow) const {
    const ModelMaterial& mat = models_[std::size_t(model_index)].materials[std::size_t(material)];
    block.u_base_color = mat.base_color;
    block.u_material = {mat.metallic, mat.roughness, mat.normal_scale, mat.occlusion_strength};
    block.u_emissive = {mat.emissive * emissive_nits, mat.alpha_mode == AlphaMode::Blend ? 0.5f : mat.alpha_cutoff};
    auto tex = [&](int image, bool srgb, GLuint fallback) {
        if (image < 0) return fallback;
        const int t = (srgb ? image_textures_ : image_linear_)[std::size_t(model_index)][std::size_t(image)];
        return t >= 0 ? textures_[std::size_t(t)].id() : fallback;
    };
    glBindTextureUnit(binding::kTex0, tex(mat.base_color_texture, true, white_.id()));
    if (!shadow) {
        glBindTextureUnit(binding::kTex1, tex(mat.metallic_roughness_texture, false, white_.id()));
        glBindTextureUnit(binding::kTex2, tex(mat.normal_texture, false, flat_normal_.id()));
        glBindTextureUnit(binding::kTex3, tex(mat.occlusion_texture, false, white_.id()));
        glBindTextureUnit(binding::kTex4, tex(mat.emissive_texture, true, white_.id()));
    }
    if (mat.double_sided) glDisable(GL_CULL_FACE);
    else {
        glEnable(GL_CULL_FACE);
        glCullFace(GL_BACK);
    }
}

void Objects::drawList(const RenderContext& rc, const glm::mat4& matrix, bool shadow, const ObjectDrawSettings* fade) const {
    const glm::vec3 camera = glm::vec3(rc.view.position - anchor_);
    glBindVertexArray(vao_.id());
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, draws_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kObjectInstances, instances_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kObjectVisible, visible_.id());
    for (int u = 0; u < 5; ++u) glBindSampler(GLuint(binding::kTex0 + u), sampler_.id());
    // The fade band before the impostors: the LODs whose distance range reaches into it dither.
    float band_start = 0.0f, band_end = 0.0f;
    if (fade && fade->impostor_fade_m > 0.0f && fade->impostor_distance_m < fade->max_distance_m) {
        band_end = fade->impostor_distance_m;
        band_start = std::max(0.0f, band_end - fade->impostor_fade_m);
    }
    for (const Draw& d : draws_list_) {
        if (d.shadow != shadow || d.impostor) continue;
        const Model& model = models_[std::size_t(d.model)];
        const ModelMaterial& mat = model.materials[std::size_t(d.material)];
        if (mat.alpha_mode == AlphaMode::Blend) continue;  // objects.transparent draws it (no shadow: glass)
        const bool mask = mat.alpha_mode == AlphaMode::Mask;
        const int k = d.group % kObjectGroups;
        float lod_near = 0.0f, lod_far = 1.0e30f;  // the distances the cull pass gives LOD k
        if (fade) {
            if (k == 0) lod_far = fade->lod1_distance_m;
            if (k == 1) lod_near = fade->lod1_distance_m, lod_far = fade->lod2_distance_m;
            if (k == 2) lod_near = fade->lod2_distance_m;
        }
        const bool fading = !shadow && band_end > band_start && lod_near < band_end && lod_far > band_start;
        std::vector<std::string> defines;
        if (shadow) defines.push_back("SHADOW_PASS");
        if (fading) defines.push_back("IMPOSTOR_FADE");
        if (mask) defines.push_back("ALPHA_MASK");
        const GLuint program = rc.shaders.id("renderer/meshes/shaders/object.glsl", defines);
        glUseProgram(program);
        ObjectBlock block{};
        block.u_matrix = matrix;
        block.u_camera = camera;
        block.u_region = d.region;
        if (fading) {
            const glm::vec4& sphere = spheres_[std::size_t(d.model)];
            block.u_fade = {band_start, 1.0f / (band_end - band_start), sphere.x, sphere.y};
            block.u_fade_centre_z = sphere.z;
        }
        setMaterial(block, d.model, d.material, emissive_nits_, shadow);
        bindPassBlock(rc, program, block);
        glDrawElementsIndirect(GL_TRIANGLES, GL_UNSIGNED_INT, reinterpret_cast<const void*>(d.offset));
    }
    glDisable(GL_CULL_FACE);
    for (int u = 0; u < 5; ++u) glBindSampler(GLuint(binding::kTex0 + u), 0);
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
    glBindVertexArray(rc.empty_vao);
}

void Objects::drawImpostors(const RenderContext& rc, const ObjectDrawSettings& s) const {
    const glm::vec3 camera = glm::vec3(rc.view.position - anchor_);
    const GLuint program = rc.shaders.id("renderer/meshes/shaders/impostor.glsl");
    glUseProgram(program);
    glBindVertexArray(vao_.id());
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, draws_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kObjectInstances, instances_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kObjectVisible, visible_.id());
    for (int u = 0; u < 3; ++u) glBindSampler(GLuint(binding::kTex0 + u), sampler_.id());
    const float band_start = std::max(0.0f, s.impostor_distance_m - s.impostor_fade_m);
    ImpostorBlock block{};
    block.u_matrix = rc.matrices.view_proj;
    block.u_camera = camera;
    block.u_params = {band_start, 1.0f / std::max(s.impostor_distance_m - band_start, 1e-3f), float(kImpostorFrames),
                      emissive_nits_};
    glDisable(GL_CULL_FACE);
    for (const Draw& d : draws_list_) {
        if (!d.impostor) continue;
        const Impostor& atlas = impostors_[std::size_t(d.model)];
        const glm::vec4& sphere = spheres_[std::size_t(d.model)];
        block.u_region = d.region;
        block.u_sphere = sphere;
        bindPassBlock(rc, program, block);
        glBindTextureUnit(binding::kTex0, atlas.emissive.id());
        glBindTextureUnit(binding::kTex1, atlas.albedo.id());
        glBindTextureUnit(binding::kTex2, atlas.normal.id());
        glDrawElementsIndirect(GL_TRIANGLES, GL_UNSIGNED_INT, reinterpret_cast<const void*>(d.offset));
    }
    for (int u = 0; u < 3; ++u) glBindSampler(GLuint(binding::kTex0 + u), 0);
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
    glBindVertexArray(rc.empty_vao);
}

void Objects::bakeImpostors(const RenderContext& rc) {
    if (baked_ || instance_count_ == 0) return;
    baked_ = true;
    const int side = kImpostorFrames * kImpostorFramePx;
    // One instance at the origin, unturned and unscaled, so world space is model space.
    struct Unit {
        GpuInstance instance;
        std::uint32_t visible[4];
    };
    gl::Texture depth = gl::Texture::create2D(side, side, GL_DEPTH_COMPONENT32F, 1, "impostor bake depth");
    gl::Framebuffer fb = gl::createFramebuffer("impostor bake");
    GLint old_viewport[4];
    glGetIntegerv(GL_VIEWPORT, old_viewport);
    glBindVertexArray(vao_.id());
    glDisable(GL_BLEND);
    glDisable(GL_SCISSOR_TEST);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_GREATER);
    glDepthMask(GL_TRUE);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    for (int u = 0; u < 5; ++u) glBindSampler(GLuint(binding::kTex0 + u), sampler_.id());
    for (std::size_t m = 0; m < models_.size(); ++m) {
        const Model& model = models_[m];
        const glm::vec4 sphere = spheres_[m];
        Impostor atlas;
        atlas.emissive = gl::Texture::create2D(side, side, GL_RGBA8, kImpostorMipLevels, "impostor emissive");
        atlas.albedo = gl::Texture::create2D(side, side, GL_RGBA8, kImpostorMipLevels, "impostor albedo");
        atlas.normal = gl::Texture::create2D(side, side, GL_RGBA8, kImpostorMipLevels, "impostor normal");
        glNamedFramebufferTexture(fb.id(), GL_COLOR_ATTACHMENT0, atlas.emissive.id(), 0);
        glNamedFramebufferTexture(fb.id(), GL_COLOR_ATTACHMENT1, atlas.albedo.id(), 0);
        glNamedFramebufferTexture(fb.id(), GL_COLOR_ATTACHMENT2, atlas.normal.id(), 0);
        glNamedFramebufferTexture(fb.id(), GL_DEPTH_ATTACHMENT, depth.id(), 0);
        const GLenum buffers[3] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2};
        glNamedFramebufferDrawBuffers(fb.id(), 3, buffers);
        glBindFramebuffer(GL_FRAMEBUFFER, fb.id());
        glViewport(0, 0, side, side);
        const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
        for (int b = 0; b < 3; ++b) glClearNamedFramebufferfv(fb.id(), GL_COLOR, b, zero);
        const float far_depth = 0.0f;
        glClearNamedFramebufferfv(fb.id(), GL_DEPTH, 0, &far_depth);
        const Unit unit{{glm::vec4(0.0f), glm::vec4(1.0f, float(m), sphere.w, 0.0f)}, {0, 0, 0, 0}};
        gl::Buffer instance = gl::Buffer::create(sizeof(GpuInstance), &unit.instance, 0, "impostor bake instance");
        gl::Buffer visible = gl::Buffer::create(sizeof unit.visible, unit.visible, 0, "impostor bake list");
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kObjectInstances, instance.id());
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kObjectVisible, visible.id());
        for (int j = 0; j < kImpostorFrames; ++j)
            for (int i = 0; i < kImpostorFrames; ++i) {
                glViewport(i * kImpostorFramePx, j * kImpostorFramePx, kImpostorFramePx, kImpostorFramePx);
                const glm::mat4 matrix = impostorBakeMatrix(impostorFrameDirection(i, j), glm::vec3(sphere), sphere.w);
                for (const ModelPrimitive& p : model.lods[0].primitives) {
                    const ModelMaterial& mat = model.materials[std::size_t(p.material)];
                    if (mat.alpha_mode == AlphaMode::Blend) continue;  // impostors show the opaque parts
                    std::vector<std::string> defines;
                    if (mat.alpha_mode != AlphaMode::Opaque) defines.push_back("ALPHA_MASK");
                    const GLuint program = rc.shaders.id("renderer/meshes/shaders/object.glsl", defines);
                    glUseProgram(program);
                    ObjectBlock block{};  // region 0, camera at the origin
                    block.u_matrix = matrix;
                    setMaterial(block, int(m), p.material, 1.0f, false);  // emissive factor; x nits when drawn
                    bindPassBlock(rc, program, block);
                    glDrawElementsInstancedBaseVertex(
                        GL_TRIANGLES, GLsizei(p.index_count), GL_UNSIGNED_INT,
                        reinterpret_cast<const void*>(std::size_t(index_base_[m] + p.first_index) * 4), 1, GLint(vertex_base_[m]));
                }
            }
        glGenerateTextureMipmap(atlas.emissive.id());
        glGenerateTextureMipmap(atlas.albedo.id());
        glGenerateTextureMipmap(atlas.normal.id());
        stats_.impostor_bytes += atlas.emissive.bytes() + atlas.albedo.bytes() + atlas.normal.bytes();
        impostors_.push_back(std::move(atlas));
    }
    stats_.memory_bytes += stats_.impostor_bytes;
    glDisable(GL_CULL_FACE);
    glDisable(GL_DEPTH_TEST);
    for (int u = 0; u < 5; ++u) glBindSampler(GLuint(binding::kTex0 + u), 0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(old_viewport[0], old_viewport[1], old_viewport[2], old_viewport[3]);
    glBindVertexArray(rc.empty_vao);
}

void Objects::drawShadow(const RenderContext& rc, const glm::mat4& matrix) const {
    drawList(rc, matrix, true, nullptr);
    if (shadow_counter_ == 0) return;
    const GLuint program = rc.shaders.id("renderer/meshes/shaders/object_cull.glsl", {"COUNT_SHADOW"});
    glUseProgram(program);
    ObjectCullBlock block{};
    block.u_model_count = GLuint(models_.size());
    bindPassBlock(rc, program, block);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kObjectModels, models_buffer_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kObjectCounts, counts_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kCounters, shadow_counter_);
    glDispatchCompute(GLuint((models_.size() + 63) / 64), 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

double Objects::lowestPoint() const {
    double lowest = std::numeric_limits<double>::infinity();
    for (std::size_t m = 0; m < models_.size() && m < spheres_.size() && m < placed_.size(); ++m) {
        const glm::vec4& sphere = spheres_[m];
        const double reach = glm::length(glm::dvec3(sphere)) + double(sphere.w);
        for (const PlacedObject& p : placed_[m]) lowest = std::min(lowest, p.position.y - reach * double(p.scale));
    }
    return lowest;
}

void Objects::drawShadowNear(const RenderContext& rc, const glm::dvec3& centre, double radius_m,
                             std::span<const glm::mat4> matrices, const std::function<void(std::size_t)>& before) {
    // Per model, the instances whose bounding sphere meets the light's (upload order: model by model).
    std::vector<std::uint32_t>& list = near_scratch_;
    list.clear();
    std::vector<std::pair<std::uint32_t, std::uint32_t>> ranges(models_.size());  // first, count in list
    std::uint32_t first = 0;
    for (std::size_t m = 0; m < models_.size(); ++m) {
        const glm::vec4& sphere = spheres_[m];
        ranges[m].first = std::uint32_t(list.size());
        for (std::size_t j = 0; j < placed_[m].size(); ++j) {
            const PlacedObject& p = placed_[m][j];
            const double reach = radius_m + double(sphere.w) * double(p.scale) + glm::length(glm::dvec3(sphere)) * double(p.scale);
            const glm::dvec3 d = p.position - centre;
            if (glm::dot(d, d) < reach * reach) list.push_back(first + std::uint32_t(j));
        }
        ranges[m].second = std::uint32_t(list.size()) - ranges[m].first;
        first += std::uint32_t(placed_[m].size());
    }
    if (list.empty()) return;
    if (near_list_.size() < GLsizeiptr(list.size() * 4))
        near_list_ = gl::Buffer::create(GLsizeiptr(list.size() * 4 * 2), nullptr, GL_DYNAMIC_STORAGE_BIT, "objects near-light casters");
    glNamedBufferSubData(near_list_.id(), 0, GLsizeiptr(list.size() * 4), list.data());
    const glm::vec3 camera = glm::vec3(rc.view.position - anchor_);
    for (std::size_t i = 0; i < matrices.size(); ++i) {
        before(i);
        glBindVertexArray(vao_.id());
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kObjectInstances, instances_.id());
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kObjectVisible, near_list_.id());
        for (int u = 0; u < 5; ++u) glBindSampler(GLuint(binding::kTex0 + u), sampler_.id());
        // The full mesh (LOD 0), not the shadow LOD: a lamp a few metres from a wall sees the
        // simplified mesh's bulges as a caster in front of the wall it lights.
        for (std::size_t m = 0; m < models_.size(); ++m) {
            const auto [start, count] = ranges[m];
            if (count == 0) continue;
            for (const ModelPrimitive& p : models_[m].lods[0].primitives) {
                const ModelMaterial& mat = models_[m].materials[std::size_t(p.material)];
                if (mat.alpha_mode == AlphaMode::Blend || p.index_count == 0) continue;  // glass casts no shadow (as drawList)
                std::vector<std::string> defines{"SHADOW_PASS"};
                if (mat.alpha_mode == AlphaMode::Mask) defines.push_back("ALPHA_MASK");
                const GLuint program = rc.shaders.id("renderer/meshes/shaders/object.glsl", defines);
                glUseProgram(program);
                ObjectBlock block{};
                block.u_matrix = matrices[i];
                block.u_camera = camera;
                block.u_region = start;
                setMaterial(block, int(m), p.material, emissive_nits_, true);
                bindPassBlock(rc, program, block);
                glDrawElementsInstancedBaseVertex(
                    GL_TRIANGLES, GLsizei(p.index_count), GL_UNSIGNED_INT,
                    reinterpret_cast<const void*>(std::size_t(index_base_[m] + p.first_index) * 4), GLsizei(count),
                    GLint(vertex_base_[m]));
            }
        }
        glDisable(GL_CULL_FACE);
        for (int u = 0; u < 5; ++u) glBindSampler(GLuint(binding::kTex0 + u), 0);
        glBindVertexArray(rc.empty_vao);
    }
}

void Objects::addGbufferPass(FrameGraph& graph, const RenderContext& rc, const ObjectDrawSettings& s, BufferHandle lists,
                             SceneTargets& targets) {
    const bool impostors = s.impostor_distance_m < s.max_distance_m;
    addGbufferDrawPass(graph, rc, "objects.gbuffer", lists, targets,
        [this, &rc, &s, impostors] {
            drawList(rc, rc.matrices.view_proj, false, &s);
            if (impostors) drawImpostors(rc, s);
        },
        [this, &rc, impostors] {
            // Baked the first time impostors can be drawn (the atlas render binds its own target).
            if (impostors) bakeImpostors(rc);
        });
}

}  // namespace vista
