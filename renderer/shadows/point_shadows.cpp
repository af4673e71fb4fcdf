// Shadowed point lights: which lights, their cube faces, the cube pass (see point_shadows.h).
#include "renderer/shadows/point_shadows.h"

#include "renderer/bindings.h"
#include "renderer/pass_kit.h"
#include "renderer/shadows/shadow_view.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace vista {

namespace {

// std140 mirror of PointShadowUniforms in renderer/shadows/shaders/point_shadows.glsl.
struct PointShadowUniforms {
    glm::vec4 light[kMaxPointShadows];  // camera-relative light position (m), unused
    glm::vec4 range[kMaxPointShadows];  // near (m), far (m), texel footprint per metre of face distance, unused
    glm::vec4 params;                   // filter, taps, face px, max penumbra texels
    glm::vec4 bias;                     // normal offset texels, depth bias texels, PCF radius texels, light radius m
};

// GL's cube-map faces: the axis each looks along and its up vector (the texel rows' direction).
constexpr std::array<glm::dvec3, kCubeFaces> kFaceAxis{
    glm::dvec3(1, 0, 0), glm::dvec3(-1, 0, 0), glm::dvec3(0, 1, 0), glm::dvec3(0, -1, 0), glm::dvec3(0, 0, 1), glm::dvec3(0, 0, -1)};
constexpr std::array<glm::dvec3, kCubeFaces> kFaceUp{
    glm::dvec3(0, -1, 0), glm::dvec3(0, -1, 0), glm::dvec3(0, 0, 1), glm::dvec3(0, 0, -1), glm::dvec3(0, -1, 0), glm::dvec3(0, -1, 0)};

}  // namespace

PointShadowView pointShadowView(const Light& light, const glm::dvec3& camera) {
    PointShadowView v;
    v.far_m = double(light.radius_m);
    v.near_m = std::min(std::clamp(v.far_m * 0.005, 0.02, 1.0), v.far_m * 0.5);  // as the spot tiles
    const double n = v.near_m, f = v.far_m;
    glm::dmat4 proj(0.0);  // 90 deg square frustum, reversed-Z (spotShadowView's with tan = 1)
    proj[0][0] = 1.0;
    proj[1][1] = 1.0;
    proj[2][2] = n / (f - n);
    proj[3][2] = n * f / (f - n);
    proj[2][3] = -1.0;
    const glm::dvec3 eye = light.position - camera;
    v.position = eye;
    for (int face = 0; face < kCubeFaces; ++face)
        v.view_proj[std::size_t(face)] = proj * glm::lookAt(eye, eye + kFaceAxis[std::size_t(face)], kFaceUp[std::size_t(face)]);
    return v;
}

double pointFaceDepth(const glm::dvec3& d, double near_m, double far_m) {
    const glm::dvec3 a = glm::abs(d);
    const double z = std::max({a.x, a.y, a.z});
    return near_m * (far_m - z) / (z * (far_m - near_m));
}

int pointCubeFace(const glm::dvec3& d) {
    const glm::dvec3 a = glm::abs(d);
    if (a.x >= a.y && a.x >= a.z) return d.x >= 0.0 ? 0 : 1;
    if (a.y >= a.z) return d.y >= 0.0 ? 2 : 3;
    return d.z >= 0.0 ? 4 : 5;
}

PointShadows::PointShadows() = default;
bool PointShadows::prepare(const ShadowSettings& s, std::span<const Light> lights, const ViewParams& view,
                           const ViewMatrices& m) {
    settings_ = s;
    camera_ = view.position;
    stats_ = {};
    picks_ = pickShadowedLights(lights, LightType::Point, view, m, std::clamp(s.point_max_lights, 1, kMaxPointShadows),
                                s.point_min_screen_px, stats_.candidates);
    stats_.unshadowed = stats_.candidates - picks_.size();
    views_.clear();
    frusta_.clear();
    for (const SpotShadowPick& p : picks_) {
        views_.push_back(pointShadowView(lights[p.light], camera_));
        for (const glm::dmat4& vp : views_.back().view_proj) frusta_.push_back(frustumFromViewProj(vp));
    }
    return !picks_.empty();
}

void PointShadows::allocate(int resolution, int cubes) {
    if (cubes_ && resolution_ == resolution && cube_count_ == cubes) return;
    GLuint id = 0;
    glCreateTextures(GL_TEXTURE_CUBE_MAP_ARRAY, 1, &id);
    glTextureStorage3D(id, 1, GL_DEPTH_COMPONENT32F, resolution, resolution, kCubeFaces * cubes);
    cubes_ = gl::Texture::adopt(id, resolution, resolution, GL_DEPTH_COMPONENT32F);
    cubes_.label("point shadow cubes");
    resolution_ = resolution;
    cube_count_ = cubes;
    fb_ = gl::createFramebuffer("point shadow face");
    glNamedFramebufferDrawBuffer(fb_.id(), GL_NONE);
    objects_.create(sizeof(PointShadowUniforms), GL_GEQUAL, "point shadow");
}

PointShadowInput PointShadows::addPass(FrameGraph& graph, const RenderContext& rc, TerrainCaster* terrain,
                                       const ShadowCaster& extra) {
    const ShadowSettings& s = settings_;
    const std::size_t count = picks_.size();
    instances_.resize(count * kCubeFaces);
    tess_.assign(instances_.size(), 0);
    slots_.assign(count, -1);
    PointShadowUniforms u{};
    int drawn = 0;
    for (std::size_t k = 0; k < count; ++k) {
        std::size_t faces = 0;
        for (std::size_t f = 0; f < kCubeFaces; ++f) {
            auto& list = instances_[k * kCubeFaces + f];
            list.clear();
            tess_[k * kCubeFaces + f] = terrain ? terrain->pick(frusta_[k * kCubeFaces + f], list, true) : 0;
            stats_.caster_instances += std::int64_t(list.size());
            faces += list.size();
        }
        if (faces == 0) continue;  // no terrain near the light: it stays unshadowed (lit), no cube drawn
        slots_[k] = int(k);
        ++drawn;
        const PointShadowView& v = views_[k];
        u.light[k] = glm::vec4(glm::vec3(v.position), 0.0f);
        u.range[k] = glm::vec4(float(v.near_m), float(v.far_m), 2.0f / float(s.point_resolution), 0.0f);
    }
    stats_.shadowed = std::uint64_t(drawn);
    if (drawn == 0) return {};
    const int cubes = std::clamp(s.point_max_lights, 1, kMaxPointShadows);
    allocate(s.point_resolution, cubes);
    u.params = glm::vec4(float(int(s.spot_filter)), float(s.spot_taps), float(s.point_resolution), s.spot_max_penumbra_texels);
    u.bias = glm::vec4(s.point_normal_offset_texels, s.point_depth_bias_texels, s.spot_filter_radius_texels,
                       s.spot_light_size_m);
    glNamedBufferSubData(objects_.uniforms.id(), 0, sizeof u, &u);

    TextureHandle cubes_handle = graph.importTexture(
        "shadows.point_cubes", {s.point_resolution, s.point_resolution, PixelFormat::Depth32F}, cubes_.id());
    struct Data {
        TextureHandle cubes;
    };
    const Data& d = graph.addPass<Data>("shadows.point_cubes",
        [&](PassBuilder& b, Data& data) {
            data.cubes = b.write(cubes_handle);
            if (extra.valid()) b.read(extra.reads);
        },
        [this, &rc, terrain, extra](const Data&, PassContext&) {
            const int res = resolution_;
            // Face f of cube k is layer 6 k + f; every drawn light's faces start at the light's radius.
            auto bindFace = [&](std::size_t k, std::size_t f) {
                glNamedFramebufferTextureLayer(fb_.id(), GL_DEPTH_ATTACHMENT, cubes_.id(), 0, GLint(k * kCubeFaces + f));
                bindTarget(fb_.id(), res, res);
            };
            glDepthMask(GL_TRUE);
            glClearDepth(0.0);  // reversed-Z: 0 is the light's radius
            for (std::size_t k = 0; k < slots_.size(); ++k)
                if (slots_[k] >= 0)
                    for (std::size_t f = 0; f < kCubeFaces; ++f) {
                        bindFace(k, f);
                        glClear(GL_DEPTH_BUFFER_BIT);
                    }
            glEnable(GL_DEPTH_TEST);
            glDepthFunc(GL_GREATER);
            glEnable(GL_POLYGON_OFFSET_FILL);
            glPolygonOffset(-settings_.point_slope_bias, 0.0f);  // away from the light is smaller depth
            GLuint program = terrain->program(rc);
            glUseProgram(program);
            terrain->drawLists(rc, program, instances_, tess_, [&](std::size_t i) {
                bindFace(i / kCubeFaces, i % kCubeFaces);
                return glm::mat4(views_[i / kCubeFaces].view_proj[i % kCubeFaces]);
            });
            if (extra.valid())
                for (std::size_t k = 0; k < slots_.size(); ++k) {
                    if (slots_[k] < 0) continue;
                    std::array<glm::mat4, kCubeFaces> faces;
                    for (std::size_t f = 0; f < kCubeFaces; ++f) faces[f] = glm::mat4(views_[k].view_proj[f]);
                    auto before = [&](std::size_t f) {
                        bindFace(k, f);
                        glEnable(GL_DEPTH_TEST);
                        glDepthFunc(GL_GREATER);
                        glEnable(GL_POLYGON_OFFSET_FILL);
                        glPolygonOffset(-settings_.point_slope_bias, 0.0f);
                    };
                    if (extra.draw_near) {  // only the casters within the light's radius
                        extra.draw_near(camera_ + views_[k].position, views_[k].far_m, faces, before);
                    } else {
                        for (std::size_t f = 0; f < kCubeFaces; ++f) {
                            before(f);
                            extra.draw(faces[f]);
                        }
                    }
                }
            glDisable(GL_POLYGON_OFFSET_FILL);
            glDisable(GL_DEPTH_TEST);
        });
    return {d.cubes, objects_.uniforms.id(), objects_.compare.id(), objects_.depth.id()};
}

TextureHandle addPointShadowViewPass(FrameGraph& graph, const RenderContext& rc, const PointShadowInput& shadows,
                                     int cubes) {
    return addShadowViewPass(graph, rc, {"shadows.point_view", "renderer/shadows/shaders/point_shadow_view.glsl",
                                         shadows.cubes, shadows.depth_sampler, binding::kPointShadowDepth, {cubes, 0, 0, 0}});
}

}  // namespace vista
