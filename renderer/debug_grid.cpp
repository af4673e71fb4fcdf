// The reference grid: a full-screen ray/plane intersection, so it reaches the horizon.
#include "renderer/debug_grid.h"

#include <cmath>

namespace vista {

void addGridPass(FrameGraph& graph, const RenderContext& rc, const DebugSettings& debug, const SkySettings& sky,
                 SceneTargets& targets) {
    struct Data {
        SceneTargets t;
    };
    // The grid pattern repeats every 10 minor cells, so the camera's position modulo that
    // period (taken in double) keeps the lines exact at any distance from the origin.
    double period = 10.0 * double(debug.grid_spacing);
    glm::vec2 origin(float(std::fmod(rc.view.position.x, period)), float(std::fmod(rc.view.position.z, period)));
    float height = float(rc.view.position.y);
    float spacing = debug.grid_spacing;
    bool has_sky = sky.enabled;
    const Data& d = graph.addPass<Data>("debug.grid",
        [&](PassBuilder& b, Data& data) {
            data.t.hdr = b.write(targets.hdr);
            data.t.depth = b.write(targets.depth);
        },
        [&rc, origin, height, spacing, has_sky](const Data& data, PassContext& ctx) {
            const TextureDesc& desc = ctx.desc(data.t.hdr);
            bindTarget(rc.device.framebuffer({ctx.texture(data.t.hdr)}, ctx.texture(data.t.depth)), desc.width,
                       desc.height);
            GLuint program = rc.shaders.id("renderer/shaders/grid.glsl");
            glUseProgram(program);
            glProgramUniform2f(program, 0, origin.x, origin.y);
            glProgramUniform1f(program, 1, height);
            glProgramUniform1f(program, 2, spacing);
            glProgramUniform1f(program, 3, has_sky ? 1.0f : 0.0f);
            glEnable(GL_DEPTH_TEST);
            glDepthFunc(GL_GREATER);
            glDepthMask(GL_TRUE);
            drawFullscreen(rc);
            glDisable(GL_DEPTH_TEST);
        });
    targets = d.t;
}

}  // namespace vista
