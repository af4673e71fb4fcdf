// Grading and the night-vision scope: one full-screen pass each.
#include "postfx/grade.h"

#include "renderer/pass_kit.h"

#include <glm/common.hpp>

#include <cmath>

namespace vista {
namespace {
#include "postfx/shaders/grade_block.glsl"
#include "postfx/shaders/night_vision_block.glsl"
}  // namespace

TextureHandle addGradePass(FrameGraph& graph, const RenderContext& rc, TextureHandle image, const GradeSettings& g,
                           const GradeLut* lut) {
    GradeBlock block{};
    block.u_lift = g.lift;
    block.u_inv_gamma = 1.0f / glm::max(g.gamma, glm::vec3(1e-3f));
    block.u_gain = g.gain;
    block.u_saturation = g.saturation;
    block.u_vignette = g.vignette;
    block.u_vignette_start = g.vignette_start;
    block.u_grain = g.grain;
    // The grain pattern changes grain_rate times per second of scene time: the same time gives
    // the same image.
    block.u_grain_index = float(std::floor(rc.time_s * double(g.grain_rate)));
    FullscreenPass pass("postfx.grade", {"postfx/shaders/grade.glsl", {}}, {image}, "graded");
    if (lut && lut->texture) {
        // Input domain to texture coordinates: the first and last entries at texel centres.
        const glm::vec3 scale = float(lut->size - 1) / float(lut->size) / (lut->domain_max - lut->domain_min);
        block.u_lut_scale = scale;
        block.u_lut_offset = 0.5f / float(lut->size) - lut->domain_min * scale;
        pass.program.defines.push_back("GRADE_LUT");
        pass.textures.emplace_back(1, lut->texture);
    }
    return addFullscreenPass(graph, rc, std::move(pass), block);
}

TextureHandle addNightVisionPass(FrameGraph& graph, const RenderContext& rc, TextureHandle image,
                                 const NightVisionSettings& n) {
    NightVisionBlock block{};
    block.u_tint = n.tint;
    block.u_gain = n.gain;
    block.u_noise = n.noise;
    block.u_scope_vignette = n.vignette;
    block.u_noise_index = float(std::floor(rc.time_s * double(n.noise_rate)));
    return addFullscreenPass(
        graph, rc, FullscreenPass("postfx.night_vision", {"postfx/shaders/night_vision.glsl", {}}, {image}, "night_vision"),
        block);
}

ProgramList gradePrograms() {
    return {{"postfx/shaders/grade.glsl", {}}, {"postfx/shaders/grade.glsl", {"GRADE_LUT"}},
            {"postfx/shaders/night_vision.glsl", {}}};
}

}  // namespace vista
