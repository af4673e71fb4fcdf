// "postfx.grade": colour grading and film grain (postfx/shaders/grade.glsl); same size and
// format. Night vision, a look of its own, lives here too.
#pragma once

#include "postfx/grade_settings.h"
#include "postfx/night_vision_settings.h"
#include "renderer/render_context.h"

#include <string>
#include <utility>
#include <vector>

namespace vista {

// A 3D LUT the grade applies (postfx/lut.h): texture, and the input range its ends map.
struct GradeLut {
    GLuint texture = 0;
    int size = 0;
    glm::vec3 domain_min{0.0f}, domain_max{1.0f};
};

TextureHandle addGradePass(FrameGraph& graph, const RenderContext& rc, TextureHandle image, const GradeSettings& s,
                           const GradeLut* lut = nullptr);

// "postfx.night_vision" (postfx/shaders/night_vision.glsl): same size and format.
TextureHandle addNightVisionPass(FrameGraph& graph, const RenderContext& rc, TextureHandle image,
                                 const NightVisionSettings& s);

ProgramList gradePrograms();

}  // namespace vista
