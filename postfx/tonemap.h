// "postfx.tonemap": the end of the HDR pipeline. Applies exposure, a tone-mapping operator
// (a #define variant per operator) and the sRGB transfer function; writes RGBA8 holding
// sRGB-encoded values. With [postfx] or [postfx.tonemap] disabled it only clamps and encodes.
#pragma once

#include "config/settings.h"
#include "renderer/render_context.h"

namespace vista {

TextureHandle addTonemapPass(FrameGraph& graph, const RenderContext& rc, TextureHandle hdr, const Settings& s);

// Every program variant this module uses (for up-front compilation and tests).
std::vector<std::pair<std::string, std::vector<std::string>>> tonemapPrograms();

}  // namespace vista
