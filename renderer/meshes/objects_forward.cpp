// "objects.transparent": the BLEND materials of the objects, forward shaded and sorted back to
// front (see objects.h). The G-buffer holds one surface per pixel, so glass cannot go there: it
// is drawn after the sea, lit by the sun, the ambient and the same forward light lists the sea
// reads, and blended premultiplied over what is behind. Sorting is per (instance, primitive) by
// the distance of the primitive's centre, on the CPU: transparent parts are few (windows), and
// the nearest kMaxTransparentItems are drawn, one draw each.
// Local lights past the first chunk (ForwardLight::light_chunks > 1: more lights than one shader
// invocation may loop over on llvmpipe) are added to each item right after its blended draw, one
// draw per chunk with depth test EQUAL (variant LIGHT_CHUNK: the light only, alpha 0). The blend
// adds them unattenuated, as the item's own light, before anything nearer is blended over it, so
// back-to-front order stays exact. Where an item's own faces overlap on screen, only the layer
// left in the depth buffer (its nearest drawn) gets the further chunks.
#include "renderer/meshes/objects.h"

#include "renderer/bindings.h"
#include "renderer/gl_device.h"

#include <algorithm>
#include <cmath>

namespace vista {

void Objects::collectBlend() {
    blend_.clear();
    std::uint32_t first = 0;
    for (std::size_t m = 0; m < models_.size(); ++m) {
        const Model& model = models_[m];
        for (const ModelPrimitive& p : model.lods[0].primitives) {
            if (model.materials[std::size_t(p.material)].alpha_mode != AlphaMode::Blend || p.index_count == 0) continue;
            glm::vec3 lo(1e30f), hi(-1e30f);
            for (std::uint32_t i = 0; i < p.index_count; ++i) {
                const glm::vec3& v = model.vertices[model.indices[p.first_index + i]].position;
                lo = glm::min(lo, v);
                hi = glm::max(hi, v);
            }
            blend_.push_back({int(m), p, 0.5f * (lo + hi), first});
        }
        first += std::uint32_t(placed_[m].size());
    }
}

void Objects::addTransparentPass(FrameGraph& graph, const RenderContext& rc, const ObjectsSettings& s,
                                 const ForwardLight& light, SceneTargets& targets) {
    if (blend_.empty()) return;
    // Back to front by the squared distance of each (instance, primitive) centre, in double.
    struct Item {
        double distance2;
        std::uint32_t instance;
        int blend;
    };
    std::vector<Item> items;
    const double max2 = double(s.max_distance_m) * double(s.max_distance_m);
    for (std::size_t b = 0; b < blend_.size(); ++b) {
        const Blend& bl = blend_[b];
        const auto& list = placed_[std::size_t(bl.model)];
        for (std::size_t j = 0; j < list.size(); ++j) {
            const PlacedObject& p = list[j];
            const double c = std::cos(double(p.yaw_rad)), sn = std::sin(double(p.yaw_rad));
            const glm::dvec3 q = glm::dvec3(bl.centre) * double(p.scale);
            const glm::dvec3 centre = p.position + glm::dvec3(c * q.x + sn * q.z, q.y, -sn * q.x + c * q.z);
            const glm::dvec3 d = centre - rc.view.position;
            const double d2 = glm::dot(d, d);
            if (d2 <= max2) items.push_back({d2, bl.first_instance + std::uint32_t(j), int(b)});
        }
    }
    transparent_dropped_ = 0;
    if (items.size() > kMaxTransparentItems) {
        std::nth_element(items.begin(), items.begin() + kMaxTransparentItems, items.end(),
                         [](const Item& a, const Item& b) { return a.distance2 < b.distance2; });
        transparent_dropped_ = items.size() - kMaxTransparentItems;
        items.resize(kMaxTransparentItems);
    }
    if (sort_transparent_)
        std::stable_sort(items.begin(), items.end(), [](const Item& a, const Item& b) { return a.distance2 > b.distance2; });
    transparent_drawn_ = items.size();
    if (items.empty()) return;
    std::vector<std::uint32_t> order(items.size());
    for (std::size_t i = 0; i < items.size(); ++i) order[i] = items[i].instance;
    if (forward_list_.size() < GLsizeiptr(order.size() * 4))
        forward_list_ = gl::Buffer::create(GLsizeiptr(kMaxTransparentItems * 4), nullptr, GL_DYNAMIC_STORAGE_BIT, "objects transparent order");
    glNamedBufferSubData(forward_list_.id(), 0, GLsizeiptr(order.size() * 4), order.data());

    struct Data {
        TextureHandle hdr, depth;
    };
    const Data& d = graph.addPass<Data>("objects.transparent",
        [&](PassBuilder& b, Data& data) {
            data.hdr = b.write(targets.hdr);
            data.depth = b.write(targets.depth);
        },
        [this, &rc, light, items = std::move(items)](const Data& data, PassContext& ctx) {
            const TextureDesc& desc = ctx.desc(data.hdr);
            bindTarget(rc.device.framebuffer({ctx.texture(data.hdr)}, ctx.texture(data.depth)), desc.width, desc.height);
            glEnable(GL_DEPTH_TEST);
            glDepthFunc(GL_GREATER);
            // Depth written like the sea's, so the aerial perspective fogs the glass at its own
            // distance; drawn back to front, each item is nearer than what it covers.
            glDepthMask(GL_TRUE);
            glEnable(GL_BLEND);
            glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
            std::vector<std::string> defines{"FORWARD"};
            if (!light.lights_define.empty()) defines.push_back(light.lights_define);
            const GLuint program = rc.shaders.get("renderer/meshes/shaders/object.glsl", defines)->id();
            const bool lit = !light.lights_define.empty();
            const std::uint32_t chunks = lit ? std::max<std::uint32_t>(light.light_chunks, 1) : 1;
            GLuint chunk_program = 0;
            if (chunks > 1) {
                defines.push_back("LIGHT_CHUNK");
                chunk_program = rc.shaders.get("renderer/meshes/shaders/object.glsl", defines)->id();
            }
            glUseProgram(program);
            if (light.bind_lights) light.bind_lights();
            const glm::vec3 camera = glm::vec3(rc.view.position - anchor_);
            for (GLuint p : {program, chunk_program}) {
                if (p == 0) continue;
                glProgramUniform3f(p, 1, camera.x, camera.y, camera.z);
                glProgramUniformMatrix4fv(p, 16, 1, GL_FALSE, &rc.matrices.view_proj[0][0]);
            }
            glProgramUniform3f(program, 7, light.sun_irradiance.r, light.sun_irradiance.g, light.sun_irradiance.b);
            glProgramUniform3f(program, 8, light.sky_up.r, light.sky_up.g, light.sky_up.b);
            glProgramUniform3f(program, 9, light.ground_up.r, light.ground_up.g, light.ground_up.b);
            if (lit) glProgramUniform2ui(program, 10, 0, light.light_chunk);
            glBindVertexArray(vao_.id());
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kObjectInstances, instances_.id());
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kObjectVisible, forward_list_.id());
            for (int u = 0; u < 5; ++u) glBindSampler(GLuint(binding::kTex0 + u), sampler_.id());
            for (std::size_t i = 0; i < items.size(); ++i) {
                const Blend& bl = blend_[std::size_t(items[i].blend)];
                auto draw = [&] {
                    glDrawElementsInstancedBaseVertex(
                        GL_TRIANGLES, GLsizei(bl.primitive.index_count), GL_UNSIGNED_INT,
                        reinterpret_cast<const void*>(std::size_t(index_base_[std::size_t(bl.model)] + bl.primitive.first_index) * 4),
                        1, GLint(vertex_base_[std::size_t(bl.model)]));
                };
                glProgramUniform1ui(program, 0, GLuint(i));  // the instance is order[i]
                setMaterial(program, bl.model, bl.primitive.material, emissive_nits_, false);
                draw();
                if (chunks == 1) continue;
                glUseProgram(chunk_program);
                glProgramUniform1ui(chunk_program, 0, GLuint(i));
                setMaterial(chunk_program, bl.model, bl.primitive.material, emissive_nits_, false);
                glDepthFunc(GL_EQUAL);
                glDepthMask(GL_FALSE);
                for (std::uint32_t k = 1; k < chunks; ++k) {
                    glProgramUniform2ui(chunk_program, 10, k * light.light_chunk, light.light_chunk);
                    draw();
                }
                glDepthFunc(GL_GREATER);
                glDepthMask(GL_TRUE);
                glUseProgram(program);
            }
            for (int u = 0; u < 5; ++u) glBindSampler(GLuint(binding::kTex0 + u), 0);
            glBindVertexArray(rc.empty_vao);
            glDisable(GL_CULL_FACE);
            glDisable(GL_BLEND);
            glDisable(GL_DEPTH_TEST);
        });
    targets.hdr = d.hdr;
    targets.depth = d.depth;
}

}  // namespace vista
