// TAA: the CPU keeps the ping-ponged history, decides when history is usable and adds one
// pass; where each pixel was in the previous frame comes from the frame's motion vectors.
#include "postfx/taa.h"

#include "renderer/bindings.h"
#include "renderer/temporal.h"

#include <glm/gtc/type_ptr.hpp>

namespace vista {

glm::dvec2 TemporalAA::jitterPx(std::uint64_t index) { return taaJitterPx(index); }

void TemporalAA::release(GlDevice& device) {
    for (int i = 0; i < 2; ++i) {
        if (colour_[i].id() != 0) device.destroyTexture(colour_[i].id());
        if (depth_[i].id() != 0) device.destroyTexture(depth_[i].id());
        colour_[i] = {};
        depth_[i] = {};
    }
    valid_ = false;
}

std::size_t TemporalAA::memoryBytes() const {
    return colour_[0].bytes() + colour_[1].bytes() + depth_[0].bytes() + depth_[1].bytes();
}

TextureHandle TemporalAA::addPass(FrameGraph& graph, const RenderContext& rc, TextureHandle image, TextureHandle depth,
                                  TextureHandle velocity, const TaaSettings& s, bool cut) {
    const int w = rc.view.width, h = rc.view.height;
    if (colour_[0].width() != w || colour_[0].height() != h) {
        release(rc.device);
        for (int i = 0; i < 2; ++i) {
            colour_[i] = gl::Texture::create2D(w, h, GL_RGBA16F, 1, "postfx.taa history");
            depth_[i] = gl::Texture::create2D(w, h, GL_R32F, 1, "postfx.taa depth");
            glTextureParameteri(depth_[i].id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
            glTextureParameteri(depth_[i].id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        }
        valid_ = false;
    }
    const bool history = valid_ && !cut;
    frames_ = history ? frames_ + 1 : 1;
    valid_ = true;
    const int read = current_, write = 1 - current_;
    current_ = write;
    const glm::vec4 jitter(rc.jitter_ndc.x, rc.jitter_ndc.y, float(rc.view.near_m), 0.0f);
    const glm::vec4 params(s.blend, s.clip_gamma, s.sharpen, history ? 0.0f : 1.0f);
    const float disocclusion = s.disocclusion;

    struct Data {
        TextureHandle image, depth, velocity, history, prev_depth, out, new_history, new_depth;
    };
    const TextureHandle history_in = graph.importTexture("taa.history", {w, h, PixelFormat::RGBA16F}, colour_[read].id());
    const TextureHandle depth_in = graph.importTexture("taa.depth", {w, h, PixelFormat::R32F}, depth_[read].id());
    const TextureHandle history_out = graph.importTexture("taa.history_next", {w, h, PixelFormat::RGBA16F}, colour_[write].id());
    const TextureHandle depth_out = graph.importTexture("taa.depth_next", {w, h, PixelFormat::R32F}, depth_[write].id());
    return graph.addPass<Data>("postfx.taa",
        [&](PassBuilder& b, Data& d) {
            d.image = b.read(image);
            d.depth = b.read(depth);
            d.velocity = b.read(velocity);
            d.history = b.read(history_in);
            d.prev_depth = b.read(depth_in);
            d.out = b.write(b.create("taa.out", {w, h, PixelFormat::RGBA16F}));
            d.new_history = b.write(history_out);
            d.new_depth = b.write(depth_out);
        },
        [&rc, jitter, params, disocclusion](const Data& d, PassContext& ctx) {
            const TextureDesc& desc = ctx.desc(d.out);
            bindTarget(rc.device.framebuffer({ctx.texture(d.out), ctx.texture(d.new_history), ctx.texture(d.new_depth)}),
                       desc.width, desc.height);
            const GLuint program = rc.shaders.id("postfx/shaders/taa.glsl");
            glUseProgram(program);
            glProgramUniform4fv(program, 1, 1, glm::value_ptr(jitter));
            glProgramUniform4fv(program, 2, 1, glm::value_ptr(params));
            glProgramUniform1f(program, 3, disocclusion);
            glBindTextureUnit(binding::kTex0, ctx.texture(d.image));
            glBindTextureUnit(binding::kTex1, ctx.texture(d.depth));
            glBindTextureUnit(binding::kTex2, ctx.texture(d.history));
            glBindTextureUnit(binding::kTex3, ctx.texture(d.prev_depth));
            glBindTextureUnit(binding::kTex4, ctx.texture(d.velocity));
            drawFullscreen(rc);
        }).out;
}

ProgramList taaPrograms() {
    return {{"postfx/shaders/taa.glsl", {}}};
}

}  // namespace vista
