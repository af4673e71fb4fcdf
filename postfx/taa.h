// Temporal anti-aliasing ([postfx.taa], postfx/shaders/taa.glsl, docs/temporal.md). The
// FrameRenderer jitters the projection by jitterPx() (a Halton(2, 3) sequence) and adds
// "postfx.taa" on the scene's HDR image before the post chain: in linear HDR, before tone
// mapping, so HDR captures and every post effect see the resolved image. History (colour and
// depth, ping-ponged) lives here across frames; reset() drops it (FrameRenderer::resetHistory),
// and a camera cut (renderer/temporal.h) rejects it for one frame.
#pragma once

#include "postfx/taa_settings.h"
#include "renderer/gl/objects.h"
#include "renderer/render_context.h"

#include <glm/vec2.hpp>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace vista {

class TemporalAA {
public:
    // The sub-pixel jitter of the frame with this temporal index, in pixels.
    static glm::dvec2 jitterPx(std::uint64_t index);
    // Resolves image (rendered with rc.jitter_ndc) against the history, found through the
    // frame's motion vectors (velocity: renderer/velocity.h); returns the image for the post
    // chain. cut: drop the history.
    TextureHandle addPass(FrameGraph& graph, const RenderContext& rc, TextureHandle image, TextureHandle depth,
                          TextureHandle velocity, const TaaSettings& s, bool cut);
    void reset() { valid_ = false; }
    // Tells the device its history textures are going (it caches framebuffers by texture name);
    // call before destroying this object.
    void release(GlDevice& device);
    // Frames resolved since the last reset or cut (0: the next frame has no history).
    int historyFrames() const { return valid_ ? frames_ : 0; }
    std::size_t memoryBytes() const;

private:
    gl::Texture colour_[2], depth_[2];
    int current_ = 0;
    int frames_ = 0;
    bool valid_ = false;
};

ProgramList taaPrograms();

}  // namespace vista
