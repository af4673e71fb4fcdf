// SSAO: the raw pass stores view distance beside the visibility so that the blur needs one
// fetch per tap for both; with full size and no blur the raw target is the result.
#include "postfx/ssao.h"

#include <algorithm>

namespace vista {

TextureHandle addSsaoPasses(FrameGraph& graph, const RenderContext& rc, const SceneTargets& scene, const SsaoSettings& s) {
    struct Raw {
        TextureHandle depth, normal, ao;
    };
    const int scale = s.half_resolution ? 2 : 1;
    const glm::vec4 params{s.radius_m, s.intensity, s.bias, float(scale)};
    const glm::ivec2 counts{s.directions, s.steps};
    const Raw& raw = graph.addPass<Raw>("postfx.ssao",
        [&](PassBuilder& b, Raw& d) {
            d.depth = b.read(scene.depth);
            d.normal = b.read(scene.normal);
            const TextureDesc& full = b.desc(scene.depth);
            TextureDesc desc{std::max(1, (full.width + scale - 1) / scale), std::max(1, (full.height + scale - 1) / scale),
                             PixelFormat::RG16F};
            d.ao = b.write(b.create("ssao.raw", desc));
        },
        [&rc, params, counts](const Raw& d, PassContext& ctx) {
            const TextureDesc& desc = ctx.desc(d.ao);
            bindTarget(rc.device.framebuffer({ctx.texture(d.ao)}), desc.width, desc.height);
            GLuint program = rc.shaders.id("postfx/shaders/ssao.glsl");
            glUseProgram(program);
            glProgramUniform4f(program, 0, params.x, params.y, params.z, params.w);
            glProgramUniform2i(program, 1, counts.x, counts.y);
            glBindTextureUnit(0, ctx.texture(d.depth));
            glBindTextureUnit(1, ctx.texture(d.normal));
            drawFullscreen(rc);
        });
    if (scale == 1 && !s.blur) return raw.ao;

    struct Blur {
        TextureHandle raw, depth, ao;
    };
    const glm::vec3 blur{s.blur_depth_tolerance, s.blur ? 1.0f : 0.0f, float(scale)};
    return graph.addPass<Blur>("postfx.ssao.blur",
        [&](PassBuilder& b, Blur& d) {
            d.raw = b.read(raw.ao);
            d.depth = b.read(scene.depth);
            const TextureDesc& full = b.desc(scene.depth);
            d.ao = b.write(b.create("scene.ao", {full.width, full.height, PixelFormat::R16F}));
        },
        [&rc, blur](const Blur& d, PassContext& ctx) {
            const TextureDesc& desc = ctx.desc(d.ao);
            bindTarget(rc.device.framebuffer({ctx.texture(d.ao)}), desc.width, desc.height);
            GLuint program = rc.shaders.id("postfx/shaders/ssao_blur.glsl");
            glUseProgram(program);
            glProgramUniform3f(program, 0, blur.x, blur.y, blur.z);
            glBindTextureUnit(0, ctx.texture(d.raw));
            glBindTextureUnit(1, ctx.texture(d.depth));
            drawFullscreen(rc);
        }).ao;
}

ProgramList ssaoPrograms() {
    return {{"postfx/shaders/ssao.glsl", {}}, {"postfx/shaders/ssao_blur.glsl", {}}};
}

}  // namespace vista
