// Sun shadow cascades on the GPU (see sun_shadows.h).
#include "renderer/shadows/sun_shadows.h"

#include "renderer/bindings.h"
#include "renderer/pass_kit.h"
#include "renderer/shadows/shadow_view.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

namespace vista {

namespace {

// std140 mirror of ShadowUniforms in renderer/shadows/shaders/shadows.glsl.
struct ShadowUniforms {
    glm::mat4 matrix[kMaxSunCascades];
    glm::vec4 range[kMaxSunCascades];  // near, far (view depth, m), texel (m), depth extent (m)
    glm::vec4 info[kMaxSunCascades];   // has casters, PCF radius (texels)
    glm::vec4 params;                  // count, blend band, taps, filter
    glm::vec4 bias;                    // normal offset, depth bias (texels), PCSS radius per metre, max penumbra
};

}  // namespace

bool sunCastsShadows(const ShadowSettings& s, const glm::dvec3& sun_dir) {
    return s.enabled && sun_dir.y > std::sin(glm::radians(double(s.min_sun_elevation_deg))) && sun_dir.y > 0.0;
}

std::vector<std::pair<double, double>> cascadeSlices(const ShadowSettings& s, double near_m) {
    std::vector<std::pair<double, double>> slices;
    const double far = std::max(double(s.max_distance_m), near_m * 2.0);
    const auto d = pssmSplits(near_m, far, s.cascades, s.split_lambda);
    for (int i = 0; i < std::clamp(s.cascades, 1, kMaxSunCascades - 1); ++i)
        slices.emplace_back(d[std::size_t(i)], d[std::size_t(i + 1)]);
    if (s.far_cascade && s.far_distance_m > far) slices.emplace_back(far, double(s.far_distance_m));
    return slices;
}

void SunShadows::prepare(const ShadowSettings& s, float sun_angular_radius_deg, const glm::dvec3& sun_dir,
                         const ViewParams& view, const ViewParams& fit_view, std::uint64_t sequence_frame) {
    sequence_frame_ = sequence_frame;
    camera_ = view.position;
    const ViewMatrices vm = viewMatrices(view);
    forward_ = vm.forward;
    const Frustum frustum = frustumFromViewProj(glm::dmat4(vm.view_proj));
    for (std::size_t p = 0; p < view_sides_.size(); ++p)  // left, right, bottom, top: unit normals, for margins in metres
        view_sides_[p] = frustum[p] / std::max(glm::length(glm::dvec3(frustum[p])), 1e-12);
    tan_sun_radius_ = float(std::tan(glm::radians(double(sun_angular_radius_deg)))) * s.sun_size_scale;
    const auto slices = cascadeSlices(s, view.near_m);
    const bool keep = s.freeze && frozen_ && cascades_.size() == slices.size() && settings_.resolution == s.resolution;
    settings_ = s;
    if (keep) {  // frozen: the boxes stay in world space, only the camera-relative matrices move
        for (ShadowCascade& c : cascades_) c.matrix = cascadeMatrix(light_, c, camera_);
        return;
    }
    light_ = lightBasis(sun_dir);
    const ViewMatrices m = viewMatrices(fit_view);
    CascadeView cv;
    cv.position = fit_view.position;
    cv.forward = m.forward;
    cv.up = m.up;
    cv.tan_half_fov_y = std::tan(glm::radians(fit_view.fov_deg) * 0.5);
    cv.aspect = double(fit_view.width) / double(std::max(fit_view.height, 1));
    cascades_.clear();
    for (auto [near, far] : slices) {
        cascades_.push_back(fitCascade(light_, cv, near, far, s.resolution, s.stabilize));
        cascades_.back().matrix = cascadeMatrix(light_, cascades_.back(), camera_);
    }
    frozen_ = s.freeze;
}

std::array<glm::dvec4, 6> SunShadows::casterFrustum(const glm::dmat4& view_proj) const {
    // The view frustum widened towards the sun: the view's receivers and everything that can
    // shadow them. (A union with the cascade boxes is not convex; this superset is.)
    return extrudeTowardsSun(frustumFromViewProj(view_proj), light_.dir);
}

void SunShadows::forgetKept() { kept_.clear(); }

bool SunShadows::keeps(int i, bool draws_extra) const {
    const ShadowSettings& s = settings_;
    const int count = int(cascades_.size());
    if (s.cache_frames <= 1 || i < count - s.cache_cascades || draws_extra) return false;
    if (sequence_frame_ % std::uint64_t(s.cache_frames) == 0) return false;  // the periodic redraw
    if (std::size_t(i) >= kept_.size() || !kept_[std::size_t(i)].valid) return false;
    // The layer holds exactly this cascade's view of the casters when the box (snapped to whole
    // texels: it moves once the view moved a texel or turned) and the sun are the ones it was
    // drawn with; only the casters' morphing for the camera may have moved since. The caster
    // cull's margin (several texels) covers the view's move or turn while the box stays put
    // (under a texel at the box's centre).
    const Kept& k = kept_[std::size_t(i)];
    const ShadowCascade& c = cascades_[std::size_t(i)];
    return k.sun == light_.dir && k.box.center_world == c.center_world && k.box.radius_m == c.radius_m &&
           k.box.texel_m == c.texel_m && k.box.near_m == c.near_m && k.box.far_m == c.far_m;
}

void SunShadows::allocate(int resolution, int layers) {
    if (map_ && map_resolution_ == resolution && map_layers_ == layers) return;
    GLuint id = 0;
    glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &id);
    glTextureStorage3D(id, 1, GL_DEPTH_COMPONENT32F, resolution, resolution, layers);
    map_ = gl::Texture::adopt(id, resolution, resolution, GL_DEPTH_COMPONENT32F);
    map_.label("sun shadow cascades");
    map_resolution_ = resolution;
    map_layers_ = layers;
    layer_fbs_.clear();
    for (int i = 0; i < layers; ++i) {
        layer_fbs_.push_back(gl::createFramebuffer("sun shadow cascade"));
        glNamedFramebufferTextureLayer(layer_fbs_.back().id(), GL_DEPTH_ATTACHMENT, id, 0, i);
        glNamedFramebufferDrawBuffer(layer_fbs_.back().id(), GL_NONE);
    }
    objects_.create(sizeof(ShadowUniforms), GL_LEQUAL, "shadow");
}

SunShadowInput SunShadows::addPasses(FrameGraph& graph, const RenderContext& rc, TerrainCaster* terrain,
                                     const ShadowCaster& extra, double receivers_above_m) {
    const ShadowSettings& s = settings_;
    const int count = int(cascades_.size());
    stats_ = {};
    stats_.cascades = count;
    instances_.resize(std::size_t(count));
    tess_.assign(std::size_t(count), 0);
    // A kept layer is only good in the map it was drawn into.
    if (!map_ || map_resolution_ != s.resolution || map_layers_ != count) forgetKept();
    kept_.resize(std::size_t(count));
    std::vector<bool> reuse(std::size_t(count), false);
    ShadowUniforms u{};
    const double texel0 = count > 0 ? cascades_[0].texel_m : 1.0;
    // Casters matter up to where a ray towards the sun clears the terrain's whole height span.
    double reach = std::numeric_limits<double>::infinity();
    if (terrain) {
        const glm::dvec2 span = terrain->heightRange();
        reach = (span.y - span.x) / std::max(light_.dir.y, 1e-3) + 1.0;
    }
    for (int i = 0; i < count; ++i) {
        const ShadowCascade& c = cascades_[std::size_t(i)];
        auto& list = instances_[std::size_t(i)];
        list.clear();
        // The PCF kernel keeps cascade 0's world size, and at least a texel (or the set radius if smaller).
        float radius = std::max(float(s.filter_radius_texels * texel0 / c.texel_m), std::min(s.filter_radius_texels, 1.0f));
        // This cascade is read from the nearer one's cross-fade band on (shadows.glsl sunShadow).
        const ShadowCascade* prev = i > 0 ? &cascades_[std::size_t(i - 1)] : nullptr;
        const double serves_from = prev ? prev->far_m - double(s.blend_band) * (prev->far_m - prev->near_m) : 0.0;
        tess_[std::size_t(i)] = 0;
        u.matrix[i] = glm::mat4(c.matrix);
        u.range[i] = glm::vec4(float(c.near_m), float(c.far_m), float(c.texel_m), float(2.0 * c.radius_m));
        if (keeps(i, extra.valid() && c.near_m < extra.reach_m)) {
            reuse[std::size_t(i)] = true;  // its layer still holds what a pass would draw: no pass, no casters
            ++stats_.cached;
            u.info[i] = glm::vec4(1.0f, radius, 0.0f, 0.0f);
            ++stats_.drawn;
            continue;
        }
        kept_[std::size_t(i)].valid = false;  // until its pass has run (a culled pass draws nothing)
        if (terrain) {
            std::function<bool(const glm::dvec3&, const glm::dvec3&)> keep;
            if (s.caster_cull) {
                // The receivers that read this cascade lie in the view's frustum between the
                // view depth it serves from and its far end. A lookup lands up to the normal
                // offset, the filter kernel (or the PCSS search) and a bilinear texel from its
                // receiver, so every plane and the floor give way by that twice.
                const double kernel = std::max(double(radius), s.filter == ShadowFilter::Pcss ? double(s.max_penumbra_texels) : 0.0);
                const double margin = 2.0 * c.texel_m * (double(s.normal_offset_texels) + kernel + 2.0);
                const double floor = receivers_above_m - camera_.y - margin;
                std::array<glm::dvec4, 6> region;
                for (std::size_t p = 0; p < view_sides_.size(); ++p) region[p] = view_sides_[p] + glm::dvec4(0.0, 0.0, 0.0, margin);
                region[4] = glm::dvec4(forward_, margin - serves_from);
                region[5] = glm::dvec4(-forward_, c.far_m + margin);
                keep = [this, floor, region](const glm::dvec3& lo, const glm::dvec3& hi) {
                    return std::all_of(region.begin(), region.end(), [&](const glm::dvec4& plane) {
                        return casterReachesPlane(lo, hi, plane, light_.dir, floor);
                    });
                };
            }
            // Tessellated casters where the cascade serves displaced ground.
            std::size_t skipped = 0;
            // The map holds one depth per texel: a caster grid finer than caster_step_texels of them
            // is drawn coarser.
            tess_[std::size_t(i)] = terrain->pick(casterPlanes(light_, c, camera_, reach), list,
                                                  serves_from < terrain->tessReach(), keep, &skipped,
                                                  double(s.caster_step_texels) * c.texel_m);
            stats_.casters_skipped += std::int64_t(skipped);
            stats_.caster_triangles += terrain->triangles(list);
        }
        stats_.caster_instances += std::int64_t(list.size());
        u.info[i] = glm::vec4(list.empty() ? 0.0f : 1.0f, radius, 0.0f, 0.0f);
        if (!list.empty()) ++stats_.drawn;
    }
    if (stats_.drawn == 0) return {};  // nothing casts: no passes, lighting.sun reads no shadows
    allocate(s.resolution, count);
    u.params = glm::vec4(float(count), s.blend_band, float(s.pcf_taps), float(int(s.filter)));
    u.bias = glm::vec4(s.normal_offset_texels, s.depth_bias_texels, tan_sun_radius_, s.max_penumbra_texels);
    glNamedBufferSubData(objects_.uniforms.id(), 0, sizeof u, &u);
    stats_.memory_bytes = std::size_t(s.resolution) * std::size_t(s.resolution) * 4u * std::size_t(count) + sizeof u;

    TextureHandle map = graph.importTexture("shadows.map", {s.resolution, s.resolution, PixelFormat::Depth32F}, map_.id());
    struct Data {
        TextureHandle map;
    };
    for (int i = 0; i < count; ++i) {
        if (u.info[i].x == 0.0f || reuse[std::size_t(i)]) continue;  // nothing to draw, or kept from an earlier frame
        const bool draw_extra = extra.valid() && cascades_[std::size_t(i)].near_m < extra.reach_m;
        const Data& d = graph.addPass<Data>("shadows.cascade" + std::to_string(i),
            [&](PassBuilder& b, Data& data) {
                data.map = b.write(map);
                if (draw_extra) b.read(extra.reads);
            },
            [this, &rc, terrain, i, extra = draw_extra ? extra : ShadowCaster{}](const Data&, PassContext&) {
                const int res = settings_.resolution;
                bindTarget(layer_fbs_[std::size_t(i)].id(), res, res);
                glDepthMask(GL_TRUE);
                glClearDepth(1.0);
                glClear(GL_DEPTH_BUFFER_BIT);
                glEnable(GL_DEPTH_TEST);
                glDepthFunc(GL_LESS);
                glEnable(GL_DEPTH_CLAMP);  // casters between the box and the sun land on depth 0
                glEnable(GL_POLYGON_OFFSET_FILL);
                glPolygonOffset(settings_.slope_bias, 0.0f);
                GLuint program = terrain->program(rc);
                glUseProgram(program);
                const glm::mat4 m = glm::mat4(cascades_[std::size_t(i)].matrix);
                // Seen from the sun, the terrain's back faces lie behind its front faces (a
                // heightfield): culling them leaves the same depths for less rasterising.
                glEnable(GL_CULL_FACE);
                glCullFace(GL_BACK);
                glFrontFace(GL_CCW);
                terrain->draw(rc, program, m, instances_[std::size_t(i)], tess_[std::size_t(i)], i);
                glDisable(GL_CULL_FACE);
                if (extra.valid()) extra.draw(m);
                glDisable(GL_POLYGON_OFFSET_FILL);
                glDisable(GL_DEPTH_CLAMP);
                glDisable(GL_DEPTH_TEST);
                glClearDepth(0.0);  // back to the scene's reversed-Z clear value
                kept_[std::size_t(i)] = {true, cascades_[std::size_t(i)], light_.dir};
            });
        map = d.map;
    }
    unsigned drawn = 0;
    for (int i = 0; i < count; ++i)
        if (u.info[i].x != 0.0f) drawn |= 1u << i;
    return {map, objects_.uniforms.id(), objects_.compare.id(), objects_.depth.id(), drawn,
            settings_.filter == ShadowFilter::Pcss};
}

TextureHandle addShadowMapViewPass(FrameGraph& graph, const RenderContext& rc, const SunShadowInput& shadows,
                                   int cascades) {
    return addShadowViewPass(graph, rc, {"shadows.view", "renderer/shadows/shaders/shadow_view.glsl", shadows.map,
                                         shadows.depth_sampler, binding::kShadowDepth, {cascades, int(shadows.drawn), 0, 0}});
}

}  // namespace vista
