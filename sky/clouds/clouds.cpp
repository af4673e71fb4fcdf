// Cloud passes: per-frame uniforms from the settings (the time-dependent parts in double), the
// shadow map pass and the shell pass. Shaders: sky/clouds/shaders/clouds.glsl, cloud_shadow.glsl.
#include "sky/clouds/clouds.h"

#include "renderer/bindings.h"
#include "renderer/pass_kit.h"
#include "renderer/temporal.h"
#include "sky/atmosphere.h"
#include "sky/clouds/cloud_model.h"
#include "sky/shaders/sky_bindings.glsl"

#include <glm/common.hpp>
#include <glm/vec2.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace vista {
namespace {
#include "sky/clouds/shaders/clouds_temporal_block.glsl"
}  // namespace

int cloudSubsetStride(int march_subset) { return march_subset >= 16 ? 4 : march_subset >= 4 ? 2 : 1; }

// std140 mirror of CloudUniforms in sky/clouds/shaders/clouds_common.glsl.
struct Clouds::Gpu {
    struct Layer {
        glm::vec4 shell, noise, shape;
    } layers[kMaxCloudLayers];
    glm::ivec4 count;
    glm::vec4 planet, ambient, shadow, sun, jitter;
};

ProgramList cloudPrograms() {
    return {{"sky/clouds/shaders/clouds.glsl", {}},
            {"sky/clouds/shaders/clouds.glsl", {"HALF_RES"}},
            {"sky/clouds/shaders/clouds.glsl", {"TEMPORAL"}},
            {"sky/clouds/shaders/clouds.glsl", {"HALF_RES", "TEMPORAL"}},
            {"sky/clouds/shaders/clouds.glsl", {"TEMPORAL", "SUBSET"}},
            {"sky/clouds/shaders/clouds.glsl", {"HALF_RES", "TEMPORAL", "SUBSET"}},
            {"sky/clouds/shaders/clouds_temporal.glsl", {}},
            {"sky/clouds/shaders/clouds_temporal.glsl", {"SUBSET"}},
            {"sky/clouds/shaders/clouds_composite.glsl", {}},
            {"sky/clouds/shaders/cloud_shadow.glsl", {}}};
}

void Clouds::release(GlDevice& device) {
    for (int i = 0; i < 2; ++i) {
        if (history_[i].id() != 0) device.destroyTexture(history_[i].id());
        if (history_distance_[i].id() != 0) device.destroyTexture(history_distance_[i].id());
        history_[i] = {};
        history_distance_[i] = {};
    }
    history_valid_ = false;
}

std::size_t Clouds::memoryBytes() const {
    return std::size_t(uniforms_.size()) + history_[0].bytes() + history_[1].bytes() + history_distance_[0].bytes() +
           history_distance_[1].bytes();
}

Clouds::Clouds() : uniforms_(gl::Buffer::create(sizeof(Gpu), nullptr, GL_DYNAMIC_STORAGE_BIT, "cloud uniforms")) {}

int Clouds::prepare(const RenderContext& rc, const CloudsSettings& clouds, const SkySettings& sky,
                    const glm::dvec3& sky_irradiance_up) {
    static_assert(sizeof(Gpu) == 3 * 16 * kMaxCloudLayers + 6 * 16, "Gpu must match the std140 block");
    Gpu g{};
    const double ground_r = double(sky.planet_radius_km) * 1e3;
    const double altitude = std::max(rc.view.position.y, 0.0);  // as the sky: the ground is y = 0
    const glm::dvec2 camera_xz(rc.view.position.x, rc.view.position.z);
    int n = 0;
    for (const CloudLayerSettings* layer : {&clouds.low, &clouds.high}) {
        if (!cloudLayerActive(*layer)) continue;
        Gpu::Layer& l = g.layers[n++];
        const double base = double(layer->base_m), thick = double(layer->thickness_m);
        l.shell = glm::vec4(float(ground_r + base), float(ground_r + base + thick), float(base), float(thick));
        const glm::dvec2 origin = cloudNoiseOrigin(*layer, camera_xz, rc.time_s);
        l.noise = glm::vec4(float(origin.x), float(origin.y), float(1.0 / double(layer->scale_m)), float(layer->octaves));
        l.shape = glm::vec4(float(cloudCoverage(*layer, clouds, rc.time_s)), layer->density, float(layer->steps),
                            float(layer->seed));
    }
    const glm::dvec3 sun = sunDirection(sky);
    const double slant = std::max(sun.y, 0.05);
    temporal_ = clouds.temporal && clouds.temporal_blend < 1.0f;
    subset_stride_ = temporal_ ? cloudSubsetStride(clouds.march_subset) : 1;
    g.count = glm::ivec4(n, clouds.light_samples, subset_stride_, subset_stride_);
    g.planet = glm::vec4(float(ground_r), float(ground_r + altitude), clouds.max_distance_km * 1e3f, clouds.phase_g);
    g.ambient = glm::vec4(glm::vec3(sky_irradiance_up / std::numbers::pi) * clouds.ambient, 0.0f);
    // z: whether the frame is jittered (TAA; frame.cpp's own test), so the subset march takes offsets.
    g.jitter = glm::vec4(rc.jitter_ndc, rc.jitter_ndc != glm::vec2(0.0f) ? 1.0f : 0.0f, 0.0f);
    // The shadow map's centre: where the sun's ray through the camera meets y = 0, snapped to
    // whole texels in world space (in double) so the map does not crawl as the camera moves.
    const double extent = double(clouds.shadow_extent_km) * 1e3, texel = extent / double(clouds.shadow_size);
    const glm::dvec2 centre = camera_xz - glm::dvec2(sun.x, sun.z) / slant * rc.view.position.y;
    const glm::dvec2 snapped = glm::round(centre / texel) * texel;
    const glm::dvec2 rel = snapped - camera_xz;
    g.shadow = glm::vec4(float(rel.x), float(rel.y), float(extent), float(altitude));
    g.sun = glm::vec4(glm::vec3(sun), float(slant));
    shadow_size_ = clouds.shadow_size;
    half_resolution_ = clouds.half_resolution;
    temporal_blend_ = clouds.temporal_blend;
    temporal_parallax_decay_ = clouds.temporal_parallax_decay;
    if (!temporal_) release(rc.device);  // history off keeps nothing
    shadow_map_ = glm::vec4(float(rel.x), float(rel.y), float(1.0 / extent), float(slant));
    // Written while the graph is built: both passes of this frame read the same block.
    glNamedBufferSubData(uniforms_.id(), 0, sizeof g, &g);
    return n;
}

void Clouds::bind() const { glBindBufferBase(GL_UNIFORM_BUFFER, SKY_BINDING_CLOUDS, uniforms_.id()); }

TextureHandle Clouds::addShadowPass(FrameGraph& graph, const RenderContext& rc, glm::vec4& map) {
    struct Data {
        TextureHandle shadow;
    };
    map = shadow_map_;
    const int size = shadow_size_;
    return graph.addPass<Data>("clouds.shadow",
        [&](PassBuilder& b, Data& d) {
            d.shadow = b.write(b.create("clouds.shadow_map", {size, size, PixelFormat::R16F}));
        },
        [this, &rc](const Data& d, PassContext& ctx) {
            const GLuint tex = ctx.texture(d.shadow);
            const TextureDesc& desc = ctx.desc(d.shadow);
            bind();
            bindTarget(rc.device.framebuffer({tex}), desc.width, desc.height);
            glUseProgram(rc.shaders.id("sky/clouds/shaders/cloud_shadow.glsl"));
            drawFullscreen(rc);
            // Sampled bilinearly; beyond the map the edge texels continue.
            glTextureParameteri(tex, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
            glTextureParameteri(tex, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
            glTextureParameteri(tex, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
            glTextureParameteri(tex, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        }).shadow;
}

void Clouds::addShellPass(FrameGraph& graph, const RenderContext& rc, const SkyAtmosphere& sky, SceneTargets& targets,
                          bool cut) {
    struct Data {
        TextureHandle out, distance, depth, transmittance;
    };
    const TextureHandle transmittance = sky.frameTransmittance();
    const bool half = half_resolution_, temporal = temporal_;
    const bool own_target = half || temporal;  // else blended straight over targets.hdr
    const TextureDesc cloud_desc = half ? TextureDesc{(rc.view.width + 1) / 2, (rc.view.height + 1) / 2, PixelFormat::RGBA16F}
                                        : TextureDesc{rc.view.width, rc.view.height, PixelFormat::RGBA16F};
    // A subset march (clouds_subset.glsl) writes one texel per stride x stride block of cloud_desc.
    // A frame without usable history (the first, after a cut or a resize) marches every pixel, so
    // it is as clean as a frame without the subset march, not an upsampled 1/stride^2 of it.
    const bool history_usable = temporal && history_valid_ && !cut && history_[0].width() == cloud_desc.width &&
                                history_[0].height() == cloud_desc.height;
    // (That whole march is the variant without SUBSET, which does not read the block's stride.)
    frame_stride_ = history_usable ? subset_stride_ : 1;
    const int stride = frame_stride_;
    const TextureDesc march_desc{(cloud_desc.width + stride - 1) / stride, (cloud_desc.height + stride - 1) / stride,
                                 PixelFormat::RGBA16F};
    marched_pixels_ = (long long)(march_desc.width) * march_desc.height;
    std::vector<std::string> defines;
    if (half) defines.push_back("HALF_RES");
    if (temporal) defines.push_back("TEMPORAL");
    if (stride > 1) defines.push_back("SUBSET");
    const Data& d = graph.addPass<Data>("clouds.shell",
        [&](PassBuilder& b, Data& data) {
            data.transmittance = b.read(transmittance);
            data.depth = b.read(targets.depth);
            if (own_target) {
                data.out = b.write(b.create(stride > 1 ? "clouds.subset" : half ? "clouds.half" : "clouds.full", march_desc));
                if (temporal)
                    data.distance = b.write(
                        b.create("clouds.distance", {march_desc.width, march_desc.height, PixelFormat::R32F}));
            } else {
                data.out = b.write(targets.hdr);
            }
        },
        [this, &rc, &sky, own_target, temporal, defines](const Data& data, PassContext& ctx) {
            bind();
            sky.bindFrameUniforms();
            const TextureDesc& desc = ctx.desc(data.out);
            if (temporal)
                bindTarget(rc.device.framebuffer({ctx.texture(data.out), ctx.texture(data.distance)}), desc.width,
                           desc.height);
            else
                bindTarget(rc.device.framebuffer({ctx.texture(data.out)}), desc.width, desc.height);
            if (own_target) {
                glClearColor(0, 0, 0, 0);
                glClear(GL_COLOR_BUFFER_BIT);
            }
            glUseProgram(rc.shaders.id("sky/clouds/shaders/clouds.glsl", defines));
            glBindTextureUnit(binding::kTex0, ctx.texture(data.transmittance));
            glBindTextureUnit(binding::kTex1, ctx.texture(data.depth));
            if (!own_target) {
                glEnable(GL_BLEND);
                glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);  // premultiplied: hdr = clouds + hdr * (1 - a)
            }
            drawFullscreen(rc);
            glDisable(GL_BLEND);
            glBlendFunc(GL_ONE, GL_ZERO);
        });
    if (!own_target) {
        targets.hdr = d.out;
        return;
    }
    TextureHandle clouds = d.out;
    if (temporal) clouds = addTemporalPass(graph, rc, d.out, d.distance, cloud_desc, cut);
    struct Composite {
        TextureHandle clouds, depth, hdr;
    };
    const Composite& c = graph.addPass<Composite>("clouds.composite",
        [&](PassBuilder& b, Composite& data) {
            data.clouds = b.read(clouds);
            data.depth = b.read(targets.depth);
            data.hdr = b.write(targets.hdr);
        },
        [this, &rc](const Composite& data, PassContext& ctx) {
            bind();
            const TextureDesc& desc = ctx.desc(data.hdr);
            bindTarget(rc.device.framebuffer({ctx.texture(data.hdr)}), desc.width, desc.height);
            glUseProgram(rc.shaders.id("sky/clouds/shaders/clouds_composite.glsl"));
            const GLuint tex = ctx.texture(data.clouds);
            glTextureParameteri(tex, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
            glTextureParameteri(tex, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
            glTextureParameteri(tex, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
            glTextureParameteri(tex, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
            glBindTextureUnit(binding::kTex0, tex);
            glBindTextureUnit(binding::kTex1, ctx.texture(data.depth));
            glEnable(GL_BLEND);
            glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
            drawFullscreen(rc);
            glDisable(GL_BLEND);
            glBlendFunc(GL_ONE, GL_ZERO);
        });
    targets.hdr = c.hdr;
}

TextureHandle Clouds::addTemporalPass(FrameGraph& graph, const RenderContext& rc, TextureHandle march,
                                      TextureHandle distance, const TextureDesc& desc, bool cut) {
    const int w = desc.width, h = desc.height;
    if (history_[0].width() != w || history_[0].height() != h) {
        release(rc.device);
        for (int i = 0; i < 2; ++i) {
            history_[i] = gl::Texture::create2D(w, h, GL_RGBA16F, 1, "clouds.temporal history");
            history_distance_[i] = gl::Texture::create2D(w, h, GL_RG16F, 1, "clouds.temporal distance (km, frames)");
            // Distances are not interpolated: a blend of a cloud's distance and "none" is neither.
            glTextureParameteri(history_distance_[i].id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
            glTextureParameteri(history_distance_[i].id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        }
        history_valid_ = false;
    }
    const bool history = history_valid_ && !cut;
    history_frames_ = history ? std::min(history_frames_ + 1, int(std::lround(1.0 / temporal_blend_))) : 1;
    const CloudsTemporalBlock block{
        glm::mat4(history ? previousClipFromRelative(history_view_, rc.view) : glm::dmat4(1.0)),
        glm::vec4(glm::vec3(history ? rc.view.position - history_view_.position : glm::dvec3(0.0)), float(frame_stride_)),
        glm::vec4(temporal_blend_, history ? 0.0f : 1.0f, rc.jitter_ndc.x, rc.jitter_ndc.y),
        glm::vec4(temporal_parallax_decay_, 0.0f, 0.0f, 0.0f)};
    history_view_ = rc.view;
    history_valid_ = true;
    const int read = history_current_, write = 1 - history_current_;
    history_current_ = write;

    struct Data {
        TextureHandle march, distance, history, history_distance, out, out_distance;
    };
    const TextureHandle h_in = graph.importTexture("clouds.history", {w, h, PixelFormat::RGBA16F}, history_[read].id());
    const TextureHandle hd_in = graph.importTexture("clouds.history_distance", {w, h, PixelFormat::RG16F},
                                                    history_distance_[read].id());
    const TextureHandle h_out = graph.importTexture("clouds.history_next", {w, h, PixelFormat::RGBA16F}, history_[write].id());
    const TextureHandle hd_out = graph.importTexture("clouds.history_distance_next", {w, h, PixelFormat::RG16F},
                                                     history_distance_[write].id());
    return graph.addPass<Data>("clouds.temporal",
        [&](PassBuilder& b, Data& d) {
            d.march = b.read(march);
            d.distance = b.read(distance);
            d.history = b.read(h_in);
            d.history_distance = b.read(hd_in);
            d.out = b.write(h_out);
            d.out_distance = b.write(hd_out);
        },
        [&rc, block, subset = frame_stride_ > 1](const Data& d, PassContext& ctx) {
            const TextureDesc& out = ctx.desc(d.out);
            bindTarget(rc.device.framebuffer({ctx.texture(d.out), ctx.texture(d.out_distance)}), out.width, out.height);
            const GLuint program = subset ? rc.shaders.id("sky/clouds/shaders/clouds_temporal.glsl", {"SUBSET"})
                                          : rc.shaders.id("sky/clouds/shaders/clouds_temporal.glsl");
            glUseProgram(program);
            bindPassBlock(rc, program, block);
            const GLuint history = ctx.texture(d.history);
            glTextureParameteri(history, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
            glTextureParameteri(history, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
            glTextureParameteri(history, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
            glTextureParameteri(history, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
            glBindTextureUnit(binding::kTex0, ctx.texture(d.march));
            glBindTextureUnit(binding::kTex1, ctx.texture(d.distance));
            glBindTextureUnit(binding::kTex2, history);
            glBindTextureUnit(binding::kTex3, ctx.texture(d.history_distance));
            drawFullscreen(rc);
        }).out;
}

}  // namespace vista
