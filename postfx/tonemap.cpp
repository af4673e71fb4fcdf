// Exposure, tone mapping and sRGB encoding in one full-screen pass.
#include "postfx/tonemap.h"

#include <cmath>

namespace vista {
namespace {

const char* operatorDefine(Tonemapper op) {
    switch (op) {
        case Tonemapper::Reinhard: return "TONEMAP_REINHARD";
        case Tonemapper::Aces: return "TONEMAP_ACES";
        case Tonemapper::Clamp: break;
    }
    return "TONEMAP_CLAMP";
}

}  // namespace

std::vector<std::pair<std::string, std::vector<std::string>>> tonemapPrograms() {
    std::vector<std::pair<std::string, std::vector<std::string>>> programs;
    for (Tonemapper op : {Tonemapper::Reinhard, Tonemapper::Aces, Tonemapper::Clamp})
        programs.push_back({"postfx/shaders/tonemap.glsl", {operatorDefine(op)}});
    return programs;
}

TextureHandle addTonemapPass(FrameGraph& graph, const RenderContext& rc, TextureHandle hdr, const Settings& s) {
    struct Data {
        TextureHandle hdr, ldr;
    };
    bool chain = s.postfx.enabled;
    Tonemapper op = chain && s.tonemap.enabled ? s.tonemap.op : Tonemapper::Clamp;
    float exposure = chain && s.exposure.enabled ? std::exp2(s.exposure.ev) : 1.0f;
    float white = s.tonemap.white;
    const Data& d = graph.addPass<Data>("postfx.tonemap",
        [&](PassBuilder& b, Data& data) {
            data.hdr = b.read(hdr);
            TextureDesc desc = b.desc(hdr);
            desc.format = PixelFormat::RGBA8;
            data.ldr = b.write(b.create("ldr", desc));
        },
        [&rc, op, exposure, white](const Data& data, PassContext& ctx) {
            const TextureDesc& desc = ctx.desc(data.ldr);
            bindTarget(rc.device.framebuffer({ctx.texture(data.ldr)}), desc.width, desc.height);
            GLuint program = rc.shaders.get("postfx/shaders/tonemap.glsl", {operatorDefine(op)})->id();
            glUseProgram(program);
            glProgramUniform1f(program, 0, exposure);
            glProgramUniform1f(program, 1, white);
            glBindTextureUnit(0, ctx.texture(data.hdr));
            drawFullscreen(rc);
        });
    return d.ldr;
}

}  // namespace vista
