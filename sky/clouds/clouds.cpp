// Cloud passes: per-frame uniforms from the settings (the time-dependent parts in double), the
// shadow map pass and the shell pass. Shaders: sky/clouds/shaders/clouds.glsl, cloud_shadow.glsl.
#include "sky/clouds/clouds.h"

#include "renderer/bindings.h"
#include "sky/atmosphere.h"
#include "sky/clouds/cloud_model.h"
#include "sky/shaders/sky_bindings.glsl"

#include <glm/common.hpp>
#include <glm/vec2.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace vista {

// std140 mirror of CloudUniforms in sky/shaders/clouds_common.glsl.
struct Clouds::Gpu {
    struct Layer {
        glm::vec4 shell, noise, shape;
    } layers[kMaxCloudLayers];
    glm::ivec4 count;
    glm::vec4 planet, ambient, shadow, sun;
};

std::vector<ProgramKeyText> cloudPrograms() {
    return {{"sky/clouds/shaders/clouds.glsl", {}}, {"sky/clouds/shaders/clouds.glsl", {"HALF_RES"}},
            {"sky/clouds/shaders/clouds_composite.glsl", {}}, {"sky/clouds/shaders/cloud_shadow.glsl", {}}};
}

Clouds::Clouds() : uniforms_(gl::Buffer::create(sizeof(Gpu), nullptr, GL_DYNAMIC_STORAGE_BIT, "cloud uniforms")) {}

int Clouds::prepare(const RenderContext& rc, const CloudsSettings& clouds, const SkySettings& sky,
                    const glm::dvec3& sky_irradiance_up) {
    static_assert(sizeof(Gpu) == 3 * 16 * kMaxCloudLayers + 5 * 16, "Gpu must match the std140 block");
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
    g.count = glm::ivec4(n, clouds.light_samples, 0, 0);
    g.planet = glm::vec4(float(ground_r), float(ground_r + altitude), clouds.max_distance_km * 1e3f, clouds.phase_g);
    g.ambient = glm::vec4(glm::vec3(sky_irradiance_up / std::numbers::pi) * clouds.ambient, 0.0f);
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
            glUseProgram(rc.shaders.get("sky/clouds/shaders/cloud_shadow.glsl")->id());
            drawFullscreen(rc);
            // Sampled bilinearly; beyond the map the edge texels continue.
            glTextureParameteri(tex, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
            glTextureParameteri(tex, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
            glTextureParameteri(tex, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
            glTextureParameteri(tex, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        }).shadow;
}

void Clouds::addShellPass(FrameGraph& graph, const RenderContext& rc, const SkyAtmosphere& sky, SceneTargets& targets) {
    struct Data {
        TextureHandle out, depth, transmittance;
    };
    const TextureHandle transmittance = sky.frameTransmittance();
    const bool half = half_resolution_;
    const Data& d = graph.addPass<Data>("clouds.shell",
        [&](PassBuilder& b, Data& data) {
            data.transmittance = b.read(transmittance);
            data.depth = b.read(targets.depth);
            if (half) {
                const TextureDesc desc{(rc.view.width + 1) / 2, (rc.view.height + 1) / 2, PixelFormat::RGBA16F};
                data.out = b.write(b.create("clouds.half", desc));
            } else {
                data.out = b.write(targets.hdr);
            }
        },
        [this, &rc, &sky, half](const Data& data, PassContext& ctx) {
            bind();
            sky.bindFrameUniforms();
            const TextureDesc& desc = ctx.desc(data.out);
            bindTarget(rc.device.framebuffer({ctx.texture(data.out)}), desc.width, desc.height);
            if (half) {
                glClearColor(0, 0, 0, 0);
                glClear(GL_COLOR_BUFFER_BIT);
            }
            glUseProgram(rc.shaders.get("sky/clouds/shaders/clouds.glsl", half ? std::vector<std::string>{"HALF_RES"}
                                                                        : std::vector<std::string>{})->id());
            glBindTextureUnit(binding::kTex0, ctx.texture(data.transmittance));
            glBindTextureUnit(binding::kTex1, ctx.texture(data.depth));
            if (!half) {
                glEnable(GL_BLEND);
                glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);  // premultiplied: hdr = clouds + hdr * (1 - a)
            }
            drawFullscreen(rc);
            glDisable(GL_BLEND);
            glBlendFunc(GL_ONE, GL_ZERO);
        });
    if (!half) {
        targets.hdr = d.out;
        return;
    }
    struct Composite {
        TextureHandle clouds, depth, hdr;
    };
    const TextureHandle clouds = d.out;
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
            glUseProgram(rc.shaders.get("sky/clouds/shaders/clouds_composite.glsl")->id());
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

}  // namespace vista
