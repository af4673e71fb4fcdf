// The motion-vector pass: the reprojection matrix in double, one full-screen pass on the GPU.
#include "renderer/velocity.h"

#include "renderer/bindings.h"
#include "renderer/pass_kit.h"
#include "renderer/temporal.h"

#include <glm/matrix.hpp>

namespace vista {
namespace {
#include "renderer/shaders/velocity_block.glsl"
}  // namespace

glm::dmat4 clipReprojection(const ViewParams& previous, const ViewParams& current) {
    // inverse(view_proj) takes clip to camera-relative points; previousClipFromRelative adds the
    // translation between the cameras (in double) and projects with the previous camera.
    const glm::dmat4 inv_current = glm::inverse(glm::dmat4(viewMatrices(current).view_proj));
    return previousClipFromRelative(previous, current) * inv_current;
}

glm::dvec4 cpuVelocity(const ViewParams& previous, const ViewParams& current, glm::dvec2 ndc, double depth) {
    const glm::dvec4 prev = clipReprojection(previous, current) * glm::dvec4(ndc, depth, 1.0);
    if (!(prev.w > 1e-6)) return glm::dvec4(0.0);
    return {(ndc.x - prev.x / prev.w) * 0.5, (ndc.y - prev.y / prev.w) * 0.5, prev.z / prev.w, 1.0};
}

TextureHandle addVelocityPass(FrameGraph& graph, const RenderContext& rc, TextureHandle depth, const ViewParams& previous) {
    const VelocityBlock block{glm::mat4(clipReprojection(previous, rc.view)),
                              glm::vec4(rc.jitter_ndc.x, rc.jitter_ndc.y, 0.0f, 0.0f)};
    struct Data {
        TextureHandle depth, velocity;
    };
    return graph.addPass<Data>("temporal.velocity",
        [&](PassBuilder& b, Data& d) {
            const TextureDesc& desc = b.desc(depth);
            d.depth = b.read(depth);
            d.velocity = b.write(b.create("temporal.velocity", {desc.width, desc.height, PixelFormat::RGBA32F}));
        },
        [&rc, block](const Data& d, PassContext& ctx) {
            const TextureDesc& desc = ctx.desc(d.velocity);
            bindTarget(rc.device.framebuffer({ctx.texture(d.velocity)}), desc.width, desc.height);
            const GLuint program = rc.shaders.id("renderer/shaders/velocity.glsl");
            glUseProgram(program);
            bindPassBlock(rc, program, block);
            glBindTextureUnit(binding::kTex0, ctx.texture(d.depth));
            drawFullscreen(rc);
        }).velocity;
}

ProgramList velocityPrograms() {
    return {{"renderer/shaders/velocity.glsl", {}}};
}

}  // namespace vista
