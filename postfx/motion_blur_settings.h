// [postfx.motion_blur]: camera motion blur (postfx/motion_blur.h).
// describe() is the one description of the keys; config/settings.h gathers them into Settings.
#pragma once

#include "config/visitor.h"

namespace vista {

//! Camera motion blur after McGuire et al. 2012: per-pixel velocity from depth reprojected with
//! the previous frame's camera, tile max and neighbour max velocity, and a gather with depth
//! comparisons. The blur covers the motion during the exposure shutter_deg / 360 / frame_rate
//! seconds, whatever the rate frames are rendered at.
struct MotionBlurSettings {
    bool enabled = false;
    float shutter_deg = 180.0f;   //!< deg, shutter angle: exposure = shutter / 360 of a frame at frame_rate, 0..360
    float frame_rate = 30.0f;     //!< 1/s, the film rate the shutter angle refers to, 1..1000
    float max_blur_px = 20.0f;    //!< px, longest blur (half each side; also the tile size), 2..64
    int samples = 12;             //!< gather taps per pixel, 2..64
    float depth_extent = 0.02f;   //!< relative depth difference over which foreground/background blend, 0.001..1
};

// Lists the keys of MotionBlurSettings to v, in file order.
void describe(SettingsVisitor& v, MotionBlurSettings& s);

}  // namespace vista
