// "debug.grid": an infinite reference grid on the y = 0 plane, lit by the sun, with
// anti-aliased minor and major lines. Writes scene colour and depth, so it also exercises
// camera-relative positions and reversed-Z depth far from the origin. sky_enabled: [sky] is on.
#pragma once

#include "renderer/debug_settings.h"
#include "renderer/render_context.h"
#include "renderer/scene_targets.h"

namespace vista {

void addGridPass(FrameGraph& graph, const RenderContext& rc, const DebugSettings& debug, bool sky_enabled,
                 SceneTargets& targets);

}  // namespace vista
