// Debug views of scene targets.
#include "renderer/debug_view.h"

#include "renderer/bindings.h"

namespace vista {

TextureHandle addDebugViewPass(FrameGraph& graph, const RenderContext& rc, const DebugSettings& debug,
                               const SceneTargets& targets) {
    struct Data {
        TextureHandle depth, source, normal, out;
        int view = 1;
    };
    const Data& d = graph.addPass<Data>("debug.view",
        [&](PassBuilder& b, Data& data) {
            TextureHandle source;
            if (debug.view == DebugView::Albedo) source = targets.albedo;
            if (debug.view == DebugView::Normals) source = targets.normal;
            if (debug.view == DebugView::Lights) source = targets.light_heat;
            if (debug.view == DebugView::Shadow) source = targets.hdr;  // lighting.sun wrote the sun's visibility there
            // Without local lights there is no heat target: the lights view shows 0 everywhere.
            const bool no_heat = debug.view == DebugView::Lights && !source.valid();
            data.view = source.valid() || no_heat ? int(debug.view) : int(DebugView::Depth);
            data.depth = b.read(targets.depth);
            if (source.valid()) data.source = b.read(source);
            TextureDesc desc = b.desc(targets.depth);
            desc.format = PixelFormat::RGBA8;
            data.out = b.write(b.create("debug.view", desc));
        },
        [&rc, heat_max = debug.heat_max](const Data& data, PassContext& ctx) {
            const TextureDesc& desc = ctx.desc(data.out);
            bindTarget(rc.device.framebuffer({ctx.texture(data.out)}), desc.width, desc.height);
            glUseProgram(rc.shaders.id("renderer/shaders/debug_view.glsl"));
            glUniform1i(0, data.view);
            glUniform1f(1, data.source.valid() ? heat_max : -1.0f);  // < 0: no heat target, 0 lights
            glBindTextureUnit(binding::kTex0, ctx.texture(data.depth));
            if (data.source.valid()) glBindTextureUnit(binding::kTex1, ctx.texture(data.source));
            drawFullscreen(rc);
        });
    return d.out;
}

}  // namespace vista
