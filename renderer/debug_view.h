// "debug.view": shows an intermediate target instead of the final image ([debug] view):
// depth, the G-buffer's albedo or normals, or the heat map of local lights evaluated per
// pixel (renderer/shaders/debug_view.glsl says how each is drawn).
#pragma once

#include "renderer/debug_settings.h"
#include "renderer/render_context.h"
#include "renderer/scene_targets.h"

namespace vista {

// Returns the RGBA8 display image; the final image's passes are then culled by the graph.
// A view whose target this frame lacks (no G-buffer without terrain, no heat map without
// local lights) shows depth, or the sky colour when nothing was drawn.
TextureHandle addDebugViewPass(FrameGraph& graph, const RenderContext& rc, const DebugSettings& debug,
                               const SceneTargets& targets);

}  // namespace vista
