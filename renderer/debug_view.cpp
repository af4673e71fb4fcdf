// Debug views of scene targets.
#include "renderer/debug_view.h"

#include "renderer/pass_kit.h"

namespace vista {
namespace {
#include "renderer/shaders/debug_view_block.glsl"
}  // namespace


TextureHandle addDebugViewPass(FrameGraph& graph, const RenderContext& rc, const DebugSettings& debug,
                               const SceneTargets& targets) {
    TextureHandle source;
    if (debug.view == DebugView::Albedo) source = targets.albedo;
    if (debug.view == DebugView::Normals) source = targets.normal;
    if (debug.view == DebugView::Lights) source = targets.light_heat;
    if (debug.view == DebugView::Shadow) source = targets.hdr;  // lighting.sun wrote the sun's visibility there
    // Without local lights there is no heat target: the lights view shows 0 everywhere.
    const bool no_heat = debug.view == DebugView::Lights && !source.valid();
    DebugViewBlock block{};
    block.u_debug_view.x = source.valid() || no_heat ? int(debug.view) : int(DebugView::Depth);
    block.u_heat.x = source.valid() ? debug.heat_max : -1.0f;
    FullscreenPass pass("debug.view", {"renderer/shaders/debug_view.glsl", {}}, {targets.depth}, "debug.view");
    if (source.valid()) pass.inputs.push_back(source);
    pass.format = PixelFormat::RGBA8;
    return addFullscreenPass(graph, rc, std::move(pass), block);
}

}  // namespace vista
