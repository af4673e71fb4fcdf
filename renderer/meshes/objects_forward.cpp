// "objects.transparent": the BLEND materials of the objects, forward shaded and sorted back to
// front (see objects.h). The G-buffer holds one surface per pixel, so glass cannot go there: it
// is lit by the sun, the ambient and the same forward light lists the sea reads (with the sun's
// cascades, the spot atlas and the point cubes), and blended premultiplied over what is behind.
// Sorting is per (instance, primitive) by the distance of the primitive's centre, on the CPU:
// transparent parts are few (windows), and the nearest kMaxTransparentItems are drawn, one draw each.
// With the sea, the items are split at the wave band's far edge (gl_ClipDistance): what lies
// beyond it from the eye is drawn before the sea copies the scene, so the sea refracts and absorbs
// it as it does an opaque object there; the rest after the sea and the aerial perspective, each
// fragment fogging itself with the aerial volume at its own distance (AERIAL_FOG). Depth is
// written like the sea's, so the clouds, the water's absorption under it and the rain stop at the
// nearest glass.
// Local lights past the first chunk (ForwardLight::light_chunks > 1: more lights than one shader
// invocation may loop over on llvmpipe) are added to each item right after its blended draw, one
// draw per chunk with depth test EQUAL (variant LIGHT_CHUNK: the light only, alpha 0). The blend
// adds them unattenuated, as the item's own light, before anything nearer is blended over it, so
// back-to-front order stays exact. Where an item's own faces overlap on screen, only the layer
// left in the depth buffer (its nearest drawn) gets the further chunks.
#include "renderer/meshes/objects.h"

#include "renderer/bindings.h"
#include "renderer/gl_device.h"
#include "renderer/pass_kit.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace vista {

#include "renderer/meshes/shaders/object_block.glsl"

std::vector<std::string> forwardDefines(const std::string& lights_define, bool spot_shadows, bool point_shadows, bool fog) {
    std::vector<std::string> defines{"FORWARD"};
    if (!lights_define.empty()) defines.push_back(lights_define);
    if (spot_shadows) defines.push_back("HAS_SPOT_SHADOWS");
    if (point_shadows) defines.push_back("HAS_POINT_SHADOWS");
    if (fog) defines.push_back("AERIAL_FOG");
    return defines;
}

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
            blend_.push_back({int(m), p, 0.5f * (lo + hi), lo.y, hi.y, first});
        }
        first += std::uint32_t(placed_[m].size());
    }
}

void Objects::sortTransparent(const RenderContext& rc, const ObjectDrawSettings& s, double water_level_m, double wave_height_m) {
    for (Side& side : sides_) side = Side{};
    transparent_drawn_ = transparent_dropped_ = 0;
    transparent_top_ = -std::numeric_limits<double>::infinity();
    if (blend_.empty()) return;
    // Back to front by the squared distance of each (instance, primitive) centre, in double.
    struct Item {
        double distance2;
        std::uint32_t instance;
        int blend;
        double low_y, high_y;  // world
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
            if (d2 <= max2)
                items.push_back({d2, bl.first_instance + std::uint32_t(j), int(b), p.position.y + double(bl.low_y) * double(p.scale),
                                 p.position.y + double(bl.high_y) * double(p.scale)});
        }
    }
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

    // The water plane: each side keeps the items reaching into it, clipped at the split. The split
    // is the edge of the wave band beyond the eye (the level - wave height for an eye above the
    // water): glass within the band is drawn after the sea, depth-tested against the moving
    // surface, so a crest in front of it hides it and it shows over a trough behind it; only what
    // lies beyond every trough is drawn before the sea and seen through the water.
    const bool water = std::isfinite(water_level_m);
    const float sign = rc.view.position.y >= water_level_m ? 1.0f : -1.0f;  // the eye above the still level: 1
    const double split = water_level_m - double(sign) * std::max(wave_height_m, 0.0);
    const double eye_above = rc.view.position.y - split;
    Side& beyond = sides_[std::size_t(TransparentSide::BeyondWater)];
    Side& eye = sides_[std::size_t(TransparentSide::EyeSide)];
    // Camera-relative p is at world height p.y + eye y: kept by the eye side where
    // sign * (p.y + eye_above) >= 0, by the other where it is <= 0.
    if (water) {
        eye.clip = glm::vec4(0.0f, sign, 0.0f, sign * float(eye_above));
        beyond.clip = -eye.clip;
        eye.clipped = beyond.clipped = true;
    }
    std::vector<std::uint32_t> order;
    order.reserve(2 * items.size());
    for (int k : {0, 1}) {
        Side& side = sides_[std::size_t(k)];
        for (const Item& it : items) {
            const bool above = it.high_y > split, below = it.low_y < split;
            const bool on_eye_side = !water || (sign > 0.0f ? above : below);
            const bool on_far_side = water && (sign > 0.0f ? below : above);
            if (k == int(TransparentSide::BeyondWater) ? !on_far_side : !on_eye_side) continue;
            side.items.push_back({std::uint32_t(order.size()), it.blend});
            order.push_back(it.instance);
            if (k == int(TransparentSide::EyeSide)) transparent_top_ = std::max(transparent_top_, it.high_y);
        }
    }
    if (forward_list_.size() < GLsizeiptr(order.size() * 4))
        forward_list_ = gl::Buffer::create(GLsizeiptr(2 * kMaxTransparentItems * 4), nullptr, GL_DYNAMIC_STORAGE_BIT,
                                           "objects transparent order");
    glNamedBufferSubData(forward_list_.id(), 0, GLsizeiptr(order.size() * 4), order.data());
}

void Objects::addTransparentPass(FrameGraph& graph, const RenderContext& rc, const ForwardLight& light, SceneTargets& targets,
                                 TransparentSide which, const AerialVolume& fog) {
    const Side& side = sides_[std::size_t(which)];
    if (side.items.empty()) return;
    struct Data {
        TextureHandle hdr, depth, sun, spot, point, inscatter, transmittance;
    };
    const bool lit = !light.lights_define.empty();
    const char* name = which == TransparentSide::EyeSide ? "objects.transparent" : "objects.transparent_beyond_water";
    const Data& d = graph.addPass<Data>(name,
        [&](PassBuilder& b, Data& data) {
            if (light.sun_shadow.valid()) data.sun = b.read(light.sun_shadow.map);
            if (lit && light.spot_shadows.valid()) data.spot = b.read(light.spot_shadows.map);
            if (lit && light.point_shadows.valid()) data.point = b.read(light.point_shadows.map);
            if (fog.valid()) {
                data.inscatter = b.read(fog.inscatter);
                data.transmittance = b.read(fog.transmittance);
            }
            data.hdr = b.write(targets.hdr);
            data.depth = b.write(targets.depth);
        },
        [this, &rc, light, side, lit, layout = fog.layout](const Data& data, PassContext& ctx) {
            const TextureDesc& desc = ctx.desc(data.hdr);
            bindTarget(rc.device.framebuffer({ctx.texture(data.hdr)}, ctx.texture(data.depth)), desc.width, desc.height);
            glEnable(GL_DEPTH_TEST);
            glDepthFunc(GL_GREATER);
            // Depth written like the sea's: what comes after (clouds, the view under water, rain)
            // stops at the nearest glass; drawn back to front, each item is nearer than what it covers.
            glDepthMask(GL_TRUE);
            glEnable(GL_BLEND);
            glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
            if (side.clipped) glEnable(GL_CLIP_DISTANCE0);
            // Variants: the local lights' method, their spot and point shadows, and the aerial
            // perspective when the pass comes after it; the further chunks shade the same lights.
            std::vector<std::string> defines =
                forwardDefines(light.lights_define, data.spot.valid(), data.point.valid(), data.inscatter.valid());
            if (data.inscatter.valid()) {
                glBindTextureUnit(binding::kAerialInscatter, ctx.texture(data.inscatter));
                glBindTextureUnit(binding::kAerialTransmittance, ctx.texture(data.transmittance));
            }
            const std::uint32_t chunks = lit ? std::max<std::uint32_t>(light.light_chunks, 1) : 1;
            GLuint chunk_program = 0;
            if (chunks > 1) {
                std::vector<std::string> chunk_defines = defines;
                chunk_defines.push_back("LIGHT_CHUNK");
                chunk_program = rc.shaders.id("renderer/meshes/shaders/object.glsl", chunk_defines);
            }
            // The sun's cascades shade the glass as they shade the G-buffer (a variant; the local
            // lights' further chunks need no sun).
            if (data.sun.valid()) {
                defines.push_back("HAS_SUN_SHADOW");
                light.sun_shadow.bind(ctx.texture(data.sun));
            }
            if (data.spot.valid()) light.spot_shadows.bind(ctx.texture(data.spot));
            if (data.point.valid()) light.point_shadows.bind(ctx.texture(data.point));
            const GLuint program = rc.shaders.id("renderer/meshes/shaders/object.glsl", defines);
            glUseProgram(program);
            if (light.bind_lights) light.bind_lights();
            // The further chunks' programs shade the local lights only: no sun and sky.
            ObjectBlock chunk_block{};
            chunk_block.u_camera = glm::vec3(rc.view.position - anchor_);
            chunk_block.u_matrix = rc.matrices.view_proj;
            chunk_block.u_clip = side.clip;
            if (data.inscatter.valid()) chunk_block.u_aerial = layout;
            ObjectBlock block = chunk_block;
            block.u_sun_irradiance = light.sun_irradiance;
            block.u_sky_up = light.sky_up;
            block.u_ground_up = light.ground_up;
            if (lit) block.u_light_chunk = {0u, light.light_chunk};
            glBindVertexArray(vao_.id());
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kObjectInstances, instances_.id());
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kObjectVisible, forward_list_.id());
            for (int u = 0; u < 5; ++u) glBindSampler(GLuint(binding::kTex0 + u), sampler_.id());
            for (const SortedItem& item : side.items) {
                const Blend& bl = blend_[std::size_t(item.blend)];
                auto draw = [&] {
                    glDrawElementsInstancedBaseVertex(
                        GL_TRIANGLES, GLsizei(bl.primitive.index_count), GL_UNSIGNED_INT,
                        reinterpret_cast<const void*>(std::size_t(index_base_[std::size_t(bl.model)] + bl.primitive.first_index) * 4),
                        1, GLint(vertex_base_[std::size_t(bl.model)]));
                };
                block.u_region = GLuint(item.slot);  // the instance is forward_list_[slot]
                setMaterial(block, bl.model, bl.primitive.material, emissive_nits_, false);
                bindPassBlock(rc, program, block);
                draw();
                if (chunks == 1) continue;
                glUseProgram(chunk_program);
                chunk_block.u_region = GLuint(item.slot);
                setMaterial(chunk_block, bl.model, bl.primitive.material, emissive_nits_, false);
                glDepthFunc(GL_EQUAL);
                glDepthMask(GL_FALSE);
                for (std::uint32_t k = 1; k < chunks; ++k) {
                    chunk_block.u_light_chunk = {k * light.light_chunk, light.light_chunk};
                    bindPassBlock(rc, chunk_program, chunk_block);
                    draw();
                }
                glDepthFunc(GL_GREATER);
                glDepthMask(GL_TRUE);
                glUseProgram(program);
            }
            for (int u = 0; u < 5; ++u) glBindSampler(GLuint(binding::kTex0 + u), 0);
            for (const auto& [map, shadow] : {std::pair{data.sun, &light.sun_shadow}, std::pair{data.spot, &light.spot_shadows},
                                              std::pair{data.point, &light.point_shadows}})
                if (map.valid() && shadow->unbind) shadow->unbind();
            glBindVertexArray(rc.empty_vao);
            glDisable(GL_CLIP_DISTANCE0);
            glDisable(GL_CULL_FACE);
            glDisable(GL_BLEND);
            glDisable(GL_DEPTH_TEST);
        });
    targets.hdr = d.hdr;
    targets.depth = d.depth;
}

}  // namespace vista
