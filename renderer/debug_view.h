// "debug.view": shows an intermediate target instead of the final image ([debug] view).
// Depth: log-scaled distance from reversed-Z depth, near white to far dark, sky blue-black.
#pragma once

#include "config/settings.h"
#include "renderer/render_context.h"
#include "renderer/scene_targets.h"

namespace vista {

// Returns the RGBA8 display image; the final image's passes are then culled by the graph.
TextureHandle addDebugViewPass(FrameGraph& graph, const RenderContext& rc, DebugView view, const SceneTargets& targets);

}  // namespace vista
