// TAA: the CPU keeps the ping-ponged history, decides when history is usable and adds one
// pass; where each pixel was in the previous frame comes from the frame's motion vectors.
#include "postfx/taa.h"

#include "renderer/pass_kit.h"
#include "renderer/temporal.h"

namespace vista {
namespace {
#include "postfx/shaders/taa_block.glsl"
}  // namespace

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
    TaaBlock block{};
    block.u_jitter = {rc.jitter_ndc.x, rc.jitter_ndc.y, float(rc.view.near_m), s.disocclusion};
    block.u_params = {s.blend, s.clip_gamma, s.sharpen, history ? 0.0f : 1.0f};
    const TextureHandle history_in = graph.importTexture("taa.history", {w, h, PixelFormat::RGBA16F}, colour_[read].id());
    const TextureHandle depth_in = graph.importTexture("taa.depth", {w, h, PixelFormat::R32F}, depth_[read].id());
    FullscreenPass pass("postfx.taa", {"postfx/shaders/taa.glsl", {}}, {image, depth, history_in, depth_in, velocity}, "taa.out");
    pass.format = PixelFormat::RGBA16F;
    pass.also_writes = {graph.importTexture("taa.history_next", {w, h, PixelFormat::RGBA16F}, colour_[write].id()),
                        graph.importTexture("taa.depth_next", {w, h, PixelFormat::R32F}, depth_[write].id())};
    return addFullscreenPass(graph, rc, std::move(pass), block);
}

ProgramList taaPrograms() {
    return {{"postfx/shaders/taa.glsl", {}}};
}

}  // namespace vista
