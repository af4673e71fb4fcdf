// "postfx.grade": colour grading and film grain (postfx/shaders/grade.glsl); same size and
// format. Night vision, a look of its own, lives here too.
#pragma once

#include "config/settings.h"
#include "renderer/render_context.h"

#include <string>
#include <utility>
#include <vector>

namespace vista {

TextureHandle addGradePass(FrameGraph& graph, const RenderContext& rc, TextureHandle image, const GradeSettings& s);

// "postfx.night_vision" (postfx/shaders/night_vision.glsl): same size and format.
TextureHandle addNightVisionPass(FrameGraph& graph, const RenderContext& rc, TextureHandle image,
                                 const NightVisionSettings& s);

std::vector<std::pair<std::string, std::vector<std::string>>> gradePrograms();

}  // namespace vista
