// The reference grid: a full-screen ray/plane intersection, so it reaches the horizon.
#include "renderer/debug_grid.h"

#include "renderer/pass_kit.h"

#include <cmath>

namespace vista {
namespace {
#include "renderer/shaders/grid_block.glsl"
}  // namespace

void addGridPass(FrameGraph& graph, const RenderContext& rc, const DebugSettings& debug, bool sky_enabled,
                 SceneTargets& targets) {
    struct Data {
        SceneTargets t;
    };
    // The grid pattern repeats every 10 minor cells, so the camera's position modulo that
    // period (taken in double) keeps the lines exact at any distance from the origin.
    const double period = 10.0 * double(debug.grid_spacing);
    GridBlock block{};
    block.u_origin = {float(std::fmod(rc.view.position.x, period)), float(std::fmod(rc.view.position.z, period))};
    block.u_height = float(rc.view.position.y);
    block.u_spacing = debug.grid_spacing;
    block.u_sky.x = sky_enabled ? 1.0f : 0.0f;
    const Data& d = graph.addPass<Data>("debug.grid",
        [&](PassBuilder& b, Data& data) {
            data.t.hdr = b.write(targets.hdr);
            data.t.depth = b.write(targets.depth);
        },
        [&rc, block](const Data& data, PassContext& ctx) {
            const TextureDesc& desc = ctx.desc(data.t.hdr);
            bindTarget(rc.device.framebuffer({ctx.texture(data.t.hdr)}, ctx.texture(data.t.depth)), desc.width,
                       desc.height);
            const GLuint program = rc.shaders.id("renderer/shaders/grid.glsl");
            glUseProgram(program);
            bindPassBlock(rc, program, block);
            const PipelineState state{.depth = PipelineState::Depth::GreaterWrite};
            state.apply();
            drawFullscreen(rc);
            PipelineState{}.apply();
        });
    targets = d.t;
}

}  // namespace vista
