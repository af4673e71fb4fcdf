// "sky.background": an analytic sky gradient with a sun disk behind everything already
// drawn (pixels whose depth is still at infinity). The physically based atmosphere
// replaces it when the sky issue lands.
#pragma once

#include "config/settings.h"
#include "renderer/render_context.h"
#include "renderer/scene_targets.h"

namespace vista {

// targets.depth may be invalid (nothing drawn yet): then the sky covers the whole image.
void addSkyBackgroundPass(FrameGraph& graph, const RenderContext& rc, const SkySettings& sky, SceneTargets& targets);

}  // namespace vista
