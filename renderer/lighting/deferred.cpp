// Deferred sun and ambient light.
#include "renderer/lighting/deferred.h"

#include "renderer/bindings.h"
#include "renderer/pass_kit.h"
#include "sky/shaders/sky_bindings.glsl"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>

namespace vista {
namespace {
#include "renderer/lighting/shaders/sun_block.glsl"
}  // namespace

SunAndSky sunAndSky(const SkyLighting& sky, const SkySettings& settings) {
    SunAndSky out;
    // The key light: the sun, or the moon once it gives more (after sunset; no pop, as the sun's
    // direct light is 0 by then). The night's floor of starlight and airglow joins the sky.
    out.sun_irradiance = glm::vec3(sky.keyIlluminance());
    out.sky_up = glm::vec3(sky.sky_irradiance_up + sky.night_irradiance_up);
    const float sun_up = float(std::max(sky.keyDirection().y, 0.0));
    out.ground_up = settings.ground_albedo * (out.sun_irradiance * sun_up + out.sky_up);
    return out;
}

ProgramList lightingPrograms() { return variantPrograms<SunVariant>(); }

void addSunLightingPass(FrameGraph& graph, const RenderContext& rc, const SunAndSky& light, SceneTargets& targets,
                        const SunShadowInput& shadows, DebugView debug) {
    struct Data {
        TextureHandle depth, albedo, normal, ao, cloud_shadow, hdr, shadow;
    };
    const Data& d = graph.addPass<Data>("lighting.sun",
        [&](PassBuilder& b, Data& data) {
            data.depth = b.read(targets.depth);
            data.albedo = b.read(targets.albedo);
            data.normal = b.read(targets.normal);
            if (targets.ao.valid()) data.ao = b.read(targets.ao);
            if (targets.cloud_shadow.valid()) data.cloud_shadow = b.read(targets.cloud_shadow);
            if (shadows.valid()) data.shadow = b.read(shadows.map);
            data.hdr = b.write(targets.hdr);
        },
        [&rc, light, shadows, debug](const Data& data, PassContext& ctx) {
            const TextureDesc& desc = ctx.desc(data.hdr);
            bindTarget(rc.device.framebuffer({ctx.texture(data.hdr)}), desc.width, desc.height);
            SunVariant variant;
            variant.ao = data.ao.valid();
            variant.cloud_shadow = data.cloud_shadow.valid();
            variant.sun_shadow = data.shadow.valid();
            variant.pcss = !variant.sun_shadow || shadows.pcss;
            if (debug == DebugView::Shadow) variant.debug = SunVariant::Debug::ShadowTerm;
            if (debug == DebugView::Cascades && variant.sun_shadow) variant.debug = SunVariant::Debug::Cascades;
            if (data.shadow.valid()) shadows.bind(ctx.texture(data.shadow));
            const GLuint program = rc.shaders.id(variant.key());
            glUseProgram(program);
            if (data.ao.valid()) glBindTextureUnit(binding::kTex3, ctx.texture(data.ao));
            if (data.cloud_shadow.valid()) glBindTextureUnit(SKY_TEX_CLOUD_SHADOW, ctx.texture(data.cloud_shadow));
            SunBlock block{};
            block.u_sun_irradiance = light.sun_irradiance;
            block.u_sky_up = light.sky_up;
            block.u_ground_up = light.ground_up;
            block.u_cloud_shadow_map = light.cloud_shadow_map;
            bindPassBlock(rc, program, block);
            glBindTextureUnit(binding::kTex0, ctx.texture(data.depth));
            glBindTextureUnit(binding::kTex1, ctx.texture(data.albedo));
            glBindTextureUnit(binding::kTex2, ctx.texture(data.normal));
            glEnable(GL_BLEND);
            glBlendFunc(GL_ONE, GL_ONE);
            drawFullscreen(rc);
            glDisable(GL_BLEND);
            if (data.shadow.valid()) SunShadowInput::unbind();
        });
    targets.hdr = d.hdr;
}

}  // namespace vista
