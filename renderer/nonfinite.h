// "debug.nonfinite": counts NaN and Inf pixels of the HDR target on the GPU (before tone
// mapping could hide them); the count comes back through CounterReadback frames later as
// the stats counter "nonfinite_pixels".
#pragma once

#include "renderer/pass_timers.h"
#include "renderer/render_context.h"

namespace vista {

void addNonfiniteCountPass(FrameGraph& graph, const RenderContext& rc, TextureHandle hdr, CounterReadback& readback);

}  // namespace vista
