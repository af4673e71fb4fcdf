// FXAA: one full-screen pass.
#include "postfx/fxaa.h"

namespace vista {

TextureHandle addFxaaPass(FrameGraph& graph, const RenderContext& rc, TextureHandle image, const FxaaSettings& s, bool hdr) {
    struct Data {
        TextureHandle in, out;
    };
    const glm::vec3 params{s.edge_threshold, s.edge_threshold_min, s.subpixel};
    const Data& d = graph.addPass<Data>("postfx.fxaa",
        [&](PassBuilder& b, Data& data) {
            data.in = b.read(image);
            TextureDesc desc = b.desc(image);
            desc.levels = 1;
            data.out = b.write(b.create("fxaa", desc));
        },
        [&rc, params, hdr](const Data& data, PassContext& ctx) {
            const TextureDesc& desc = ctx.desc(data.out);
            bindTarget(rc.device.framebuffer({ctx.texture(data.out)}), desc.width, desc.height);
            std::vector<std::string> defines;
            if (hdr) defines.push_back("FXAA_HDR");
            GLuint program = rc.shaders.id("postfx/shaders/fxaa.glsl", defines);
            glUseProgram(program);
            glProgramUniform3f(program, 0, params.x, params.y, params.z);
            glBindTextureUnit(0, ctx.texture(data.in));
            drawFullscreen(rc);
        });
    return d.out;
}

ProgramList fxaaPrograms() {
    return {{"postfx/shaders/fxaa.glsl", {}}, {"postfx/shaders/fxaa.glsl", {"FXAA_HDR"}}};
}

}  // namespace vista
