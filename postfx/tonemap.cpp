// Exposure, tone mapping and sRGB encoding in one full-screen pass.
#include "postfx/tonemap.h"

#include "postfx/postfx_bindings.h"

namespace vista {
namespace {

const char* operatorDefine(Tonemapper op) {
    switch (op) {
        case Tonemapper::Reinhard: return "TONEMAP_REINHARD";
        case Tonemapper::Aces: return "TONEMAP_ACES";
        case Tonemapper::Agx: return "TONEMAP_AGX";
        case Tonemapper::Clamp: break;
    }
    return "TONEMAP_CLAMP";
}

std::vector<std::string> defines(Tonemapper op, bool automatic) {
    std::vector<std::string> d{operatorDefine(op)};
    if (automatic) d.push_back("EXPOSURE_AUTO");
    return d;
}

}  // namespace

ProgramList tonemapPrograms() {
    ProgramList programs;
    for (Tonemapper op : {Tonemapper::Reinhard, Tonemapper::Aces, Tonemapper::Clamp, Tonemapper::Agx})
        for (bool automatic : {false, true}) programs.push_back({"postfx/shaders/tonemap.glsl", defines(op, automatic)});
    return programs;
}

TextureHandle addTonemapPass(FrameGraph& graph, const RenderContext& rc, TextureHandle hdr, Tonemapper op, float white,
                             const ExposureInput& exposure, const char* name) {
    struct Data {
        TextureHandle hdr, ldr;
        BufferHandle exposure;
    };
    const bool automatic = exposure.state.valid();
    const float manual = exposure.manual;
    const Data& d = graph.addPass<Data>(name,
        [&](PassBuilder& b, Data& data) {
            data.hdr = b.read(hdr);
            if (automatic) data.exposure = b.read(exposure.state);
            TextureDesc desc = b.desc(hdr);
            desc.format = PixelFormat::RGBA8;
            desc.levels = 1;
            data.ldr = b.write(b.create("ldr", desc));
        },
        [&rc, op, manual, white, automatic](const Data& data, PassContext& ctx) {
            const TextureDesc& desc = ctx.desc(data.ldr);
            bindTarget(rc.device.framebuffer({ctx.texture(data.ldr)}), desc.width, desc.height);
            GLuint program = rc.shaders.id("postfx/shaders/tonemap.glsl", defines(op, automatic));
            glUseProgram(program);
            glProgramUniform1f(program, 0, manual);
            glProgramUniform1f(program, 1, white);
            glBindTextureUnit(0, ctx.texture(data.hdr));
            if (automatic) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, postfx::kExposureBinding, ctx.buffer(data.exposure));
            drawFullscreen(rc);
        });
    return d.ldr;
}

}  // namespace vista
