// NaN/Inf pixel counter.
#include "renderer/nonfinite.h"

#include "renderer/bindings.h"

namespace vista {

void addNonfiniteCountPass(FrameGraph& graph, const RenderContext& rc, TextureHandle hdr, CounterReadback& readback) {
    struct Data {
        TextureHandle hdr;
    };
    graph.addPass<Data>("debug.nonfinite",
        [&](PassBuilder& b, Data& data) {
            data.hdr = b.read(hdr);
            b.sideEffect();
        },
        [&rc, &readback](const Data& data, PassContext& ctx) {
            const TextureDesc& desc = ctx.desc(data.hdr);
            GLuint counter = readback.request(rc.frame, "nonfinite_pixels");
            glUseProgram(rc.shaders.id("renderer/shaders/nonfinite.glsl"));
            glBindTextureUnit(binding::kTex0, ctx.texture(data.hdr));
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kCounters, counter);
            glDispatchCompute(GLuint((desc.width + 7) / 8), GLuint((desc.height + 7) / 8), 1);
            glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
        });
}

}  // namespace vista
