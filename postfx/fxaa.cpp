// FXAA: one full-screen pass.
#include "postfx/fxaa.h"

#include "renderer/pass_kit.h"

namespace vista {
namespace {
#include "postfx/shaders/fxaa_block.glsl"
}  // namespace

TextureHandle addFxaaPass(FrameGraph& graph, const RenderContext& rc, TextureHandle image, const FxaaSettings& s, bool hdr) {
    std::vector<std::string> defines;
    if (hdr) defines.push_back("FXAA_HDR");
    return addFullscreenPass(graph, rc, FullscreenPass("postfx.fxaa", {"postfx/shaders/fxaa.glsl", defines}, {image}, "fxaa"),
                             FxaaBlock{s.edge_threshold, s.edge_threshold_min, s.subpixel, 0.0f});
}

ProgramList fxaaPrograms() {
    return {{"postfx/shaders/fxaa.glsl", {}}, {"postfx/shaders/fxaa.glsl", {"FXAA_HDR"}}};
}

}  // namespace vista
