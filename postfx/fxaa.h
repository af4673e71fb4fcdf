// "postfx.fxaa": FXAA 3.11 on the chain's image (postfx/shaders/fxaa.glsl); same size and format.
#pragma once

#include "postfx/fxaa_settings.h"
#include "renderer/render_context.h"

#include <string>
#include <utility>
#include <vector>

namespace vista {

// hdr: the image is linear HDR (FXAA placed before the tone map): luma is compressed first.
TextureHandle addFxaaPass(FrameGraph& graph, const RenderContext& rc, TextureHandle image, const FxaaSettings& s, bool hdr);

ProgramList fxaaPrograms();

}  // namespace vista
