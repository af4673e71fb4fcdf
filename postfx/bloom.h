// Bloom after Jimenez 2014 (Call of Duty: Advanced Warfare): "postfx.bloom.down1..N" halve
// the image N times with a 13-tap filter (the first with a Karis average, a highlight clamp
// and NaN/Inf removal), "postfx.bloom.up(N-1)..1" climb back with a 3x3 tent, and
// "postfx.bloom.composite" mixes the result into the image (same size and format).
#pragma once

#include "postfx/bloom_settings.h"
#include "renderer/render_context.h"

#include <string>
#include <utility>
#include <vector>

namespace vista {

TextureHandle addBloomPasses(FrameGraph& graph, const RenderContext& rc, TextureHandle image, const BloomSettings& s);

ProgramList bloomPrograms();

}  // namespace vista
