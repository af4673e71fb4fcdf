// Grading: one full-screen pass.
#include "postfx/grade.h"

#include <glm/common.hpp>

namespace vista {

TextureHandle addGradePass(FrameGraph& graph, const RenderContext& rc, TextureHandle image, const GradeSettings& s) {
    struct Data {
        TextureHandle in, out;
    };
    const GradeSettings g = s;
    const Data& d = graph.addPass<Data>("postfx.grade",
        [&](PassBuilder& b, Data& data) {
            data.in = b.read(image);
            TextureDesc desc = b.desc(image);
            desc.levels = 1;
            data.out = b.write(b.create("graded", desc));
        },
        [&rc, g](const Data& data, PassContext& ctx) {
            const TextureDesc& desc = ctx.desc(data.out);
            bindTarget(rc.device.framebuffer({ctx.texture(data.out)}), desc.width, desc.height);
            GLuint program = rc.shaders.get("postfx/shaders/grade.glsl")->id();
            glUseProgram(program);
            const glm::vec3 inv_gamma = 1.0f / glm::max(g.gamma, glm::vec3(1e-3f));
            glProgramUniform3f(program, 0, g.lift.x, g.lift.y, g.lift.z);
            glProgramUniform3f(program, 1, inv_gamma.x, inv_gamma.y, inv_gamma.z);
            glProgramUniform3f(program, 2, g.gain.x, g.gain.y, g.gain.z);
            glProgramUniform3f(program, 3, g.saturation, g.vignette, g.vignette_start);
            glBindTextureUnit(0, ctx.texture(data.in));
            drawFullscreen(rc);
        });
    return d.out;
}

std::vector<std::pair<std::string, std::vector<std::string>>> gradePrograms() {
    return {{"postfx/shaders/grade.glsl", {}}};
}

}  // namespace vista
