// Grading: one full-screen pass.
#include "postfx/grade.h"

#include <glm/common.hpp>

#include <cmath>

namespace vista {

TextureHandle addGradePass(FrameGraph& graph, const RenderContext& rc, TextureHandle image, const GradeSettings& s,
                           const GradeLut* lut) {
    struct Data {
        TextureHandle in, out;
    };
    const GradeSettings g = s;
    const GradeLut l = lut ? *lut : GradeLut{};
    const Data& d = graph.addPass<Data>("postfx.grade",
        [&](PassBuilder& b, Data& data) {
            data.in = b.read(image);
            TextureDesc desc = b.desc(image);
            desc.levels = 1;
            data.out = b.write(b.create("graded", desc));
        },
        [&rc, g, l](const Data& data, PassContext& ctx) {
            const TextureDesc& desc = ctx.desc(data.out);
            bindTarget(rc.device.framebuffer({ctx.texture(data.out)}), desc.width, desc.height);
            GLuint program = rc.shaders.id("postfx/shaders/grade.glsl", l.texture ? std::vector<std::string>{"GRADE_LUT"}
                                                                                   : std::vector<std::string>{});
            glUseProgram(program);
            const glm::vec3 inv_gamma = 1.0f / glm::max(g.gamma, glm::vec3(1e-3f));
            glProgramUniform3f(program, 0, g.lift.x, g.lift.y, g.lift.z);
            glProgramUniform3f(program, 1, inv_gamma.x, inv_gamma.y, inv_gamma.z);
            glProgramUniform3f(program, 2, g.gain.x, g.gain.y, g.gain.z);
            glProgramUniform3f(program, 3, g.saturation, g.vignette, g.vignette_start);
            // The grain pattern changes grain_rate times per second of scene time: the same
            // time gives the same image.
            glProgramUniform2f(program, 4, g.grain, float(std::floor(rc.time_s * double(g.grain_rate))));
            glBindTextureUnit(0, ctx.texture(data.in));
            if (l.texture) {
                // Input domain to texture coordinates: the first and last entries at texel centres.
                const glm::vec3 scale = float(l.size - 1) / float(l.size) / (l.domain_max - l.domain_min);
                const glm::vec3 offset = 0.5f / float(l.size) - l.domain_min * scale;
                glProgramUniform3f(program, 5, scale.x, scale.y, scale.z);
                glProgramUniform3f(program, 6, offset.x, offset.y, offset.z);
                glBindTextureUnit(1, l.texture);
            }
            drawFullscreen(rc);
        });
    return d.out;
}

TextureHandle addNightVisionPass(FrameGraph& graph, const RenderContext& rc, TextureHandle image,
                                 const NightVisionSettings& s) {
    struct Data {
        TextureHandle in, out;
    };
    const NightVisionSettings n = s;
    return graph.addPass<Data>("postfx.night_vision",
        [&](PassBuilder& b, Data& data) {
            data.in = b.read(image);
            TextureDesc desc = b.desc(image);
            desc.levels = 1;
            data.out = b.write(b.create("night_vision", desc));
        },
        [&rc, n](const Data& data, PassContext& ctx) {
            const TextureDesc& desc = ctx.desc(data.out);
            bindTarget(rc.device.framebuffer({ctx.texture(data.out)}), desc.width, desc.height);
            GLuint program = rc.shaders.id("postfx/shaders/night_vision.glsl");
            glUseProgram(program);
            glProgramUniform4f(program, 0, n.gain, n.noise, n.vignette, float(std::floor(rc.time_s * double(n.noise_rate))));
            glProgramUniform3f(program, 1, n.tint.x, n.tint.y, n.tint.z);
            glBindTextureUnit(0, ctx.texture(data.in));
            drawFullscreen(rc);
        }).out;
}

ProgramList gradePrograms() {
    return {{"postfx/shaders/grade.glsl", {}}, {"postfx/shaders/grade.glsl", {"GRADE_LUT"}},
            {"postfx/shaders/night_vision.glsl", {}}};
}

}  // namespace vista
