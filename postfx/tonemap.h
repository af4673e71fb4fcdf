// "postfx.tonemap": the end of the HDR pipeline. Applies a pending exposure, a tone-mapping
// operator (a #define variant per operator) and the sRGB transfer function; writes RGBA8
// holding sRGB-encoded values. "postfx.encode" is the same pass with the clamp operator, for a
// chain without an enabled tone map (or with [postfx] disabled).
#pragma once

#include "postfx/exposure.h"
#include "postfx/tonemap_settings.h"
#include "renderer/render_context.h"

namespace vista {

// name: "postfx.tonemap" or "postfx.encode". white: Reinhard's white point.
TextureHandle addTonemapPass(FrameGraph& graph, const RenderContext& rc, TextureHandle hdr, Tonemapper op, float white,
                             const ExposureInput& exposure, const char* name = "postfx.tonemap");

// Every program variant this module uses (for up-front compilation and tests).
ProgramList tonemapPrograms();

}  // namespace vista
