// The cost unit of the stats: GPU time of one full-screen RGBA16F copy at a given size,
// measured in the same run as the passes it is compared with.
#pragma once

#include "renderer/pass_timers.h"
#include "renderer/render_context.h"

namespace vista {

// Median of `repeats` timed copies, in milliseconds (waits for the results), timed the
// same way as the passes (see TimerMode).
double measureReferenceCopyMs(const RenderContext& rc, TimerMode mode, int width, int height, int repeats = 7);

}  // namespace vista
