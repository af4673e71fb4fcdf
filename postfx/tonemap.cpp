// Exposure, tone mapping and sRGB encoding in one full-screen pass.
#include "postfx/tonemap.h"

#include "postfx/postfx_bindings.h"
#include "renderer/pass_kit.h"

namespace vista {
namespace {

#include "postfx/shaders/tonemap_block.glsl"

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
    const bool automatic = exposure.state.valid();
    FullscreenPass pass(name, {"postfx/shaders/tonemap.glsl", defines(op, automatic)}, {hdr}, "ldr");
    pass.format = PixelFormat::RGBA8;
    if (automatic) pass.buffers.emplace_back(postfx::kExposureBinding, exposure.state);
    return addFullscreenPass(graph, rc, std::move(pass), TonemapBlock{exposure.manual, white, 0.0f, 0.0f});
}

}  // namespace vista
