// Screen-space ambient occlusion: "postfx.ssao" (horizon based, postfx/shaders/ssao.glsl; half
// or full size) and "postfx.ssao.blur" (bilateral 3x3 and depth-aware upsample to full size).
// Runs before "lighting.sun", which multiplies its ambient term by the result.
#pragma once

#include "postfx/ssao_settings.h"
#include "renderer/render_context.h"
#include "renderer/scene_targets.h"

#include <string>
#include <utility>
#include <vector>

namespace vista {

// The full-size ambient visibility (r, 1 = open) for scene.ao. Needs scene.depth and scene.normal.
TextureHandle addSsaoPasses(FrameGraph& graph, const RenderContext& rc, const SceneTargets& scene, const SsaoSettings& s);

ProgramList ssaoPrograms();

}  // namespace vista
