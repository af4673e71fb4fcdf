// Sky gradient behind the scene, drawn at depth 0 with a GEQUAL test so it only covers
// pixels nothing else wrote.
#include "sky/background.h"

namespace vista {

void addSkyBackgroundPass(FrameGraph& graph, const RenderContext& rc, const SkySettings& sky, SceneTargets& targets) {
    struct Data {
        TextureHandle hdr, depth;
    };
    glm::vec3 zenith = sky.zenith_color, horizon = sky.horizon_color;
    const Data& d = graph.addPass<Data>("sky.background",
        [&](PassBuilder& b, Data& data) {
            if (targets.depth.valid()) data.depth = b.read(targets.depth);
            data.hdr = b.write(targets.hdr);
        },
        [&rc, zenith, horizon](const Data& data, PassContext& ctx) {
            const TextureDesc& desc = ctx.desc(data.hdr);
            GLuint depth = data.depth.valid() ? ctx.texture(data.depth) : 0;
            bindTarget(rc.device.framebuffer({ctx.texture(data.hdr)}, depth), desc.width, desc.height);
            GLuint program = rc.shaders.get("sky/shaders/background.glsl")->id();
            glUseProgram(program);
            glProgramUniform3f(program, 0, zenith.r, zenith.g, zenith.b);
            glProgramUniform3f(program, 1, horizon.r, horizon.g, horizon.b);
            if (depth != 0) {
                glEnable(GL_DEPTH_TEST);
                glDepthFunc(GL_GEQUAL);  // the triangle is at depth 0: passes only where depth is 0
                glDepthMask(GL_FALSE);
            }
            drawFullscreen(rc);
            glDisable(GL_DEPTH_TEST);
            glDepthMask(GL_TRUE);
        });
    targets.hdr = d.hdr;
}

}  // namespace vista
