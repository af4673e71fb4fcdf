// Shadowed spot lights: which lights, their views, the atlas pass (see spot_shadows.h).
#include "renderer/shadows/spot_shadows.h"

#include "renderer/bindings.h"
#include "renderer/pass_kit.h"
#include "renderer/shadows/shadow_view.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace vista {

namespace {

// std140 mirror of SpotShadowUniforms in renderer/shadows/shaders/spot_shadows.glsl.
struct SpotShadowUniforms {
    glm::mat4 matrix[kMaxSpotShadows];  // camera-relative world -> clip (reversed-Z perspective)
    glm::vec4 rect[kMaxSpotShadows];    // atlas uv offset xy, uv scale zw
    glm::vec4 range[kMaxSpotShadows];   // near (m), far (m), texel footprint per metre of distance, unused
    glm::vec4 params;                   // filter, taps, tile px, max penumbra texels
    glm::vec4 bias;                     // normal offset texels, depth bias texels, PCF radius texels, light radius m
};

}  // namespace

std::vector<SpotShadowPick> pickShadowedSpots(std::span<const Light> lights, const ViewParams& view,
                                              const ViewMatrices& m, int max_lights, float min_screen_px,
                                              std::uint64_t& candidates) {
    return pickShadowedLights(lights, LightType::Spot, view, m, max_lights, min_screen_px, candidates);
}

std::vector<SpotShadowPick> pickShadowedLights(std::span<const Light> lights, LightType type, const ViewParams& view,
                                               const ViewMatrices& m, int max_lights, float min_screen_px,
                                               std::uint64_t& candidates) {
    std::vector<SpotShadowPick> picks;
    candidates = 0;
    const double ty = std::tan(glm::radians(view.fov_deg) * 0.5);
    const double tx = ty * double(view.width) / double(std::max(view.height, 1));
    const double kx = std::sqrt(1.0 + tx * tx), ky = std::sqrt(1.0 + ty * ty);
    const double px_per_tan = 0.5 * double(view.height) / ty;
    for (std::size_t i = 0; i < lights.size(); ++i) {
        const Light& l = lights[i];
        if (l.type != type || !l.shadow || l.radius_m <= 0.0f || l.intensity <= 0.0f) continue;
        if (type == LightType::Spot && (l.outer_deg >= kMaxShadowedSpotDeg || glm::length(l.direction) <= 0.0f)) continue;
        const Sphere sphere = boundingSphere(l);
        const glm::dvec3 rel = sphere.center - view.position;
        const glm::dvec3 c{glm::dot(rel, m.right), glm::dot(rel, m.up), glm::dot(rel, m.forward)};
        const double r = sphere.radius;
        if (c.z < view.near_m - r || std::abs(c.x) > c.z * tx + r * kx || std::abs(c.y) > c.z * ty + r * ky) continue;
        const double d2 = glm::dot(rel, rel);
        const double screen = d2 <= r * r ? std::numeric_limits<double>::infinity() : r / std::sqrt(d2 - r * r) * px_per_tan;
        if (screen < double(min_screen_px)) continue;
        picks.push_back({std::uint32_t(i), screen});
    }
    candidates = picks.size();
    std::stable_sort(picks.begin(), picks.end(),
                     [](const SpotShadowPick& a, const SpotShadowPick& b) { return a.screen_px > b.screen_px; });
    if (picks.size() > std::size_t(std::max(max_lights, 0))) picks.resize(std::size_t(std::max(max_lights, 0)));
    return picks;
}

SpotShadowView spotShadowView(const Light& light, const glm::dvec3& camera) {
    SpotShadowView v;
    v.far_m = double(light.radius_m);
    v.near_m = std::min(std::clamp(v.far_m * 0.005, 0.02, 1.0), v.far_m * 0.5);
    v.tan_half = std::tan(glm::radians(std::min(double(light.outer_deg), double(kMaxShadowedSpotDeg))));
    const glm::dvec3 dir = glm::normalize(glm::dvec3(light.direction));
    // Any up vector not along the axis; the least aligned world axis keeps the basis well conditioned.
    const glm::dvec3 a = glm::abs(dir);
    const glm::dvec3 up = a.y <= a.x && a.y <= a.z ? glm::dvec3(0, 1, 0) : a.x <= a.z ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 0, 1);
    const glm::dvec3 eye = light.position - camera;
    const glm::dmat4 view = glm::lookAt(eye, eye + dir, up);
    const double n = v.near_m, f = v.far_m;
    glm::dmat4 proj(0.0);
    proj[0][0] = 1.0 / v.tan_half;
    proj[1][1] = 1.0 / v.tan_half;
    proj[2][2] = n / (f - n);      // depth = n (f - z) / (z (f - n)), z = -view z
    proj[3][2] = n * f / (f - n);
    proj[2][3] = -1.0;
    v.view_proj = proj * view;
    return v;
}

double spotLinearDepth(double depth, double near_m, double far_m) {
    return near_m * far_m / (near_m + depth * (far_m - near_m));
}

int spotAtlasTilesPerSide(int max_lights) {
    int n = 1;
    while (n * n < max_lights) ++n;
    return n;
}

bool SpotShadows::prepare(const ShadowSettings& s, std::span<const Light> lights, const ViewParams& view,
                          const ViewMatrices& m) {
    settings_ = s;
    camera_ = view.position;
    stats_ = {};
    picks_ = pickShadowedSpots(lights, view, m, std::min(s.spot_max_lights, kMaxSpotShadows), s.spot_min_screen_px,
                               stats_.candidates);
    stats_.unshadowed = stats_.candidates - picks_.size();
    views_.clear();
    frusta_.clear();
    for (const SpotShadowPick& p : picks_) {
        views_.push_back(spotShadowView(lights[p.light], camera_));
        frusta_.push_back(frustumFromViewProj(views_.back().view_proj));
    }
    return !picks_.empty();
}

void SpotShadows::allocate(int resolution) {
    if (atlas_ && atlas_resolution_ == resolution) return;
    atlas_ = gl::Texture::create2D(resolution, resolution, GL_DEPTH_COMPONENT32F, 1, "spot shadow atlas");
    atlas_resolution_ = resolution;
    atlas_fb_ = gl::createFramebuffer("spot shadow atlas");
    glNamedFramebufferTexture(atlas_fb_.id(), GL_DEPTH_ATTACHMENT, atlas_.id(), 0);
    glNamedFramebufferDrawBuffer(atlas_fb_.id(), GL_NONE);
    objects_.create(sizeof(SpotShadowUniforms), GL_GEQUAL, "spot shadow");
}

SpotShadowInput SpotShadows::addPass(FrameGraph& graph, const RenderContext& rc, TerrainCaster* terrain,
                                     const ShadowCaster& extra) {
    const ShadowSettings& s = settings_;
    const std::size_t count = picks_.size();
    tiles_per_side_ = spotAtlasTilesPerSide(std::min(s.spot_max_lights, kMaxSpotShadows));
    const int tile = s.spot_atlas_resolution / tiles_per_side_;
    instances_.resize(count);
    tess_.assign(instances_.size(), 0);
    slots_.assign(count, -1);
    SpotShadowUniforms u{};
    int drawn = 0;
    for (std::size_t k = 0; k < count; ++k) {
        auto& list = instances_[k];
        list.clear();
        tess_[k] = terrain ? terrain->pick(frusta_[k], list, true) : 0;
        stats_.caster_instances += std::int64_t(list.size());
        if (list.empty()) continue;  // nothing casts: the light stays unshadowed (lit), no tile drawn
        slots_[k] = int(k);
        ++drawn;
        const SpotShadowView& v = views_[k];
        const int tx = int(k) % tiles_per_side_, ty = int(k) / tiles_per_side_;
        const float scale = float(tile) / float(s.spot_atlas_resolution);
        u.matrix[k] = glm::mat4(v.view_proj);
        u.rect[k] = glm::vec4(float(tx) * scale, float(ty) * scale, scale, scale);
        u.range[k] = glm::vec4(float(v.near_m), float(v.far_m), float(2.0 * v.tan_half / double(tile)), 0.0f);
    }
    stats_.shadowed = std::uint64_t(drawn);
    if (drawn == 0) return {};
    allocate(s.spot_atlas_resolution);
    u.params = glm::vec4(float(int(s.spot_filter)), float(s.spot_taps), float(tile), s.spot_max_penumbra_texels);
    u.bias = glm::vec4(s.spot_normal_offset_texels, s.spot_depth_bias_texels, s.spot_filter_radius_texels,
                       s.spot_light_size_m);
    glNamedBufferSubData(objects_.uniforms.id(), 0, sizeof u, &u);
    stats_.memory_bytes = memoryBytes();

    TextureHandle atlas = graph.importTexture(
        "shadows.spot_atlas", {s.spot_atlas_resolution, s.spot_atlas_resolution, PixelFormat::Depth32F}, atlas_.id());
    struct Data {
        TextureHandle atlas;
    };
    const Data& d = graph.addPass<Data>("shadows.spot_atlas",
        [&](PassBuilder& b, Data& data) {
            data.atlas = b.write(atlas);
            if (extra.valid()) b.read(extra.reads);
        },
        [this, &rc, terrain, tile, extra](const Data&, PassContext&) {
            const int res = settings_.spot_atlas_resolution;
            bindTarget(atlas_fb_.id(), res, res);
            glDepthMask(GL_TRUE);
            glClearDepth(0.0);  // reversed-Z: 0 is the light's radius
            glClear(GL_DEPTH_BUFFER_BIT);
            glEnable(GL_DEPTH_TEST);
            glDepthFunc(GL_GREATER);
            glEnable(GL_SCISSOR_TEST);
            glEnable(GL_POLYGON_OFFSET_FILL);
            glPolygonOffset(-settings_.spot_slope_bias, 0.0f);  // away from the light is smaller depth
            GLuint program = terrain->program(rc);
            glUseProgram(program);
            auto bindTile = [&](std::size_t k) {
                const int x = int(k) % tiles_per_side_ * tile, y = int(k) / tiles_per_side_ * tile;
                glViewport(x, y, tile, tile);
                glScissor(x, y, tile, tile);
            };
            terrain->drawLists(rc, program, instances_, tess_, [&](std::size_t k) {
                bindTile(k);
                return glm::mat4(views_[k].view_proj);
            });
            if (extra.valid())
                for (std::size_t k = 0; k < slots_.size(); ++k) {
                    if (slots_[k] < 0) continue;
                    bindTile(k);
                    extra.draw(glm::mat4(views_[k].view_proj));
                }
            glDisable(GL_POLYGON_OFFSET_FILL);
            glDisable(GL_SCISSOR_TEST);
            glDisable(GL_DEPTH_TEST);
        });
    return {d.atlas, objects_.uniforms.id(), objects_.compare.id(), objects_.depth.id()};
}

TextureHandle addSpotAtlasViewPass(FrameGraph& graph, const RenderContext& rc, const SpotShadowInput& shadows,
                                   int tiles_per_side) {
    return addShadowViewPass(graph, rc, {"shadows.spot_view", "renderer/shadows/shaders/spot_atlas_view.glsl", shadows.atlas,
                                         shadows.depth_sampler, binding::kSpotShadowDepth, {tiles_per_side, 0, 0, 0}});
}

}  // namespace vista
