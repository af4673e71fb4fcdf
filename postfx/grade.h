// "postfx.grade": colour grading (postfx/shaders/grade.glsl); same size and format.
#pragma once

#include "config/settings.h"
#include "renderer/render_context.h"

#include <string>
#include <utility>
#include <vector>

namespace vista {

TextureHandle addGradePass(FrameGraph& graph, const RenderContext& rc, TextureHandle image, const GradeSettings& s);

std::vector<std::pair<std::string, std::vector<std::string>>> gradePrograms();

}  // namespace vista
