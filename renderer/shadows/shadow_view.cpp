// The shadow debug views' pass (see shadow_view.h).
#include "renderer/shadows/shadow_view.h"

#include "renderer/pass_kit.h"

namespace vista {
namespace {
#include "renderer/shadows/shaders/shadow_view_block.glsl"
}  // namespace

TextureHandle addShadowViewPass(FrameGraph& graph, const RenderContext& rc, ShadowViewPass pass) {
    struct Data {
        TextureHandle depth, out;
    };
    const Data& d = graph.addPass<Data>(pass.name,
        [&](PassBuilder& b, Data& data) {
            if (pass.depth.valid()) data.depth = b.read(pass.depth);
            data.out = b.write(b.create(pass.name, {rc.view.width, rc.view.height, PixelFormat::RGBA8}));
        },
        [&rc, pass](const Data& data, PassContext& ctx) {
            const TextureDesc& desc = ctx.desc(data.out);
            bindTarget(rc.device.framebuffer({ctx.texture(data.out)}), desc.width, desc.height);
            const GLuint program = rc.shaders.id(pass.program);
            glUseProgram(program);
            glm::ivec4 info = pass.info;
            if (!data.depth.valid()) info.x = 0;
            bindPassBlock(rc, program, ShadowViewBlock{info});
            if (data.depth.valid()) {
                glBindTextureUnit(GLuint(pass.unit), ctx.texture(data.depth));
                glBindSampler(GLuint(pass.unit), pass.sampler);
            }
            drawFullscreen(rc);
            glBindSampler(GLuint(pass.unit), 0);
        });
    return d.out;
}

ProgramList shadowPrograms() {
    return {{"renderer/shadows/shaders/shadow_view.glsl", {}}, {"renderer/shadows/shaders/spot_atlas_view.glsl", {}},
            {"renderer/shadows/shaders/point_shadow_view.glsl", {}}};
}

}  // namespace vista
