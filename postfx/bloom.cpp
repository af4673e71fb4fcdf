// Bloom: each level is a transient RGBA16F target; the upsample chain mixes rather than adds
// (up = mix(down, tent(coarser), radius), then image = mix(image, tent(up1), intensity)), so
// the weights of all levels sum to one: bloom moves energy around and never creates it.
#include "postfx/bloom.h"

#include <algorithm>

namespace vista {
namespace {

struct Pair {
    TextureHandle a, b, out;
};

TextureHandle addUpPass(FrameGraph& graph, const RenderContext& rc, const std::string& name, TextureHandle coarse,
                        TextureHandle fine, float mix, bool composite) {
    const Pair& p = graph.addPass<Pair>(name,
        [&](PassBuilder& b, Pair& d) {
            d.a = b.read(coarse);
            d.b = b.read(fine);
            TextureDesc desc = b.desc(fine);
            desc.levels = 1;
            d.out = b.write(b.create(composite ? "bloom.out" : "bloom." + name.substr(name.rfind('.') + 1), desc));
        },
        [&rc, mix, composite](const Pair& d, PassContext& ctx) {
            const TextureDesc& desc = ctx.desc(d.out);
            bindTarget(rc.device.framebuffer({ctx.texture(d.out)}), desc.width, desc.height);
            std::vector<std::string> defines;
            if (composite) defines.push_back("BLOOM_COMPOSITE");
            GLuint program = rc.shaders.id("postfx/shaders/bloom_up.glsl", defines);
            glUseProgram(program);
            glProgramUniform1f(program, 0, mix);
            glBindTextureUnit(0, ctx.texture(d.a));
            glBindTextureUnit(1, ctx.texture(d.b));
            drawFullscreen(rc);
        });
    return p.out;
}

}  // namespace

TextureHandle addBloomPasses(FrameGraph& graph, const RenderContext& rc, TextureHandle image, const BloomSettings& s) {
    struct Down {
        TextureHandle in, out;
    };
    std::vector<TextureHandle> levels;
    TextureHandle source = image;
    const float clamp = s.clamp;
    for (int level = 1; level <= std::max(1, s.levels); ++level) {
        const bool first = level == 1;
        const Down& d = graph.addPass<Down>("postfx.bloom.down" + std::to_string(level),
            [&](PassBuilder& b, Down& data) {
                data.in = b.read(source);
                const TextureDesc& in = b.desc(source);
                TextureDesc desc{std::max(1, in.width / 2), std::max(1, in.height / 2), PixelFormat::RGBA16F};
                data.out = b.write(b.create("bloom.down" + std::to_string(level), desc));
            },
            [&rc, first, clamp](const Down& data, PassContext& ctx) {
                const TextureDesc& in = ctx.desc(data.in);
                const TextureDesc& desc = ctx.desc(data.out);
                bindTarget(rc.device.framebuffer({ctx.texture(data.out)}), desc.width, desc.height);
                std::vector<std::string> defines;
                if (first) defines.push_back("BLOOM_FIRST");
                GLuint program = rc.shaders.id("postfx/shaders/bloom_down.glsl", defines);
                glUseProgram(program);
                glProgramUniform2f(program, 0, 1.0f / float(in.width), 1.0f / float(in.height));
                glProgramUniform1f(program, 1, clamp);
                glBindTextureUnit(0, ctx.texture(data.in));
                drawFullscreen(rc);
            });
        levels.push_back(d.out);
        source = d.out;
    }
    TextureHandle up = levels.back();
    for (int level = int(levels.size()) - 1; level >= 1; --level)
        up = addUpPass(graph, rc, "postfx.bloom.up" + std::to_string(level), up, levels[std::size_t(level - 1)], s.radius,
                       false);
    return addUpPass(graph, rc, "postfx.bloom.composite", up, image, s.intensity, true);
}

ProgramList bloomPrograms() {
    return {{"postfx/shaders/bloom_down.glsl", {}},
            {"postfx/shaders/bloom_down.glsl", {"BLOOM_FIRST"}},
            {"postfx/shaders/bloom_up.glsl", {}},
            {"postfx/shaders/bloom_up.glsl", {"BLOOM_COMPOSITE"}}};
}

}  // namespace vista
