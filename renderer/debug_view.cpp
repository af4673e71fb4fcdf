// Debug views of scene targets.
#include "renderer/debug_view.h"

namespace vista {

TextureHandle addDebugViewPass(FrameGraph& graph, const RenderContext& rc, DebugView view, const SceneTargets& targets) {
    struct Data {
        TextureHandle source, out;
    };
    (void)view;  // one view so far: depth
    const Data& d = graph.addPass<Data>("debug.view",
        [&](PassBuilder& b, Data& data) {
            data.source = b.read(targets.depth);
            TextureDesc desc = b.desc(targets.depth);
            desc.format = PixelFormat::RGBA8;
            data.out = b.write(b.create("debug.view", desc));
        },
        [&rc](const Data& data, PassContext& ctx) {
            const TextureDesc& desc = ctx.desc(data.out);
            bindTarget(rc.device.framebuffer({ctx.texture(data.out)}), desc.width, desc.height);
            glUseProgram(rc.shaders.get("renderer/shaders/debug_depth.glsl")->id());
            glBindTextureUnit(0, ctx.texture(data.source));
            drawFullscreen(rc);
        });
    return d.out;
}

}  // namespace vista
