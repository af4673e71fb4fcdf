// Camera motion blur after McGuire, Hennessy, Bukowski and Osman 2012 ("A reconstruction filter
// for plausible motion blur"): "postfx.motion_blur.velocity" scales the frame's shared motion
// vectors ("temporal.velocity", renderer/velocity.h) by the shutter (half the blur vector in
// pixels and the view distance),
// "postfx.motion_blur.tiles" keeps the longest vector of each k x k tile (k = max_blur_px / 2),
// "postfx.motion_blur.neighbors" the longest of the 3x3 tiles around, and
// "postfx.motion_blur.gather" samples along that dominant vector, weighting each tap by whether
// it is in front (its own blur reaches this pixel) or behind (this pixel's blur reaches it).
//
// The blur covers the camera's motion during the exposure, shutter_deg / 360 / frame_rate
// seconds: the per-frame displacement is scaled by exposure / (time since the last frame), so
// the blur length does not depend on the rate frames are rendered at. No pass while the camera
// is still, on the first frame, or when time did not advance.
#pragma once

#include "postfx/motion_blur_settings.h"
#include "renderer/render_context.h"

#include <glm/mat4x4.hpp>

#include <string>
#include <utility>
#include <vector>

namespace vista {

// Maps this frame's clip coordinates (x, y, reversed-Z depth, 1) to the previous frame's clip
// coordinates. Both frames render camera-relative, so the camera's translation between them
// (a difference of large world positions) is taken in double precision here.
glm::dmat4 reprojectionMatrix(const ViewParams& previous, const ViewParams& current);

class MotionBlur {
public:
    // Blurs image by the camera's motion since the last call (dt_s earlier; reset: there is no
    // usable previous frame). Returns image itself when there is nothing to blur. motion: the
    // frame's "temporal.velocity" target; invalid: this effect adds one from its own previous camera.
    TextureHandle addPasses(FrameGraph& graph, const RenderContext& rc, TextureHandle image, TextureHandle depth,
                            TextureHandle motion, const MotionBlurSettings& s, double dt_s, bool reset);

private:
    ViewParams previous_;
    bool has_previous_ = false;
};

ProgramList motionBlurPrograms();

}  // namespace vista
