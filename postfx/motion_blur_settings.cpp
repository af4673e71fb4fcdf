// [postfx.motion_blur]: the keys, units, ranges and help text.
#include "postfx/motion_blur_settings.h"

namespace vista {

void describe(SettingsVisitor& v, MotionBlurSettings& s) {
    v.section("postfx.motion_blur", "camera motion blur: depth reprojection, tile/neighbour max, McGuire 2012 gather");
    v.field({"enabled", "", "blur by the camera's motion (needs the scene depth)"}, s.enabled);
    v.field({"shutter_deg", "deg", "shutter angle: exposure = shutter / 360 / frame_rate seconds"}, s.shutter_deg, 0.0f, 360.0f);
    v.field({"frame_rate", "1/s", "film rate the shutter angle refers to (not the render rate)"}, s.frame_rate, 1.0f, 1000.0f);
    v.field({"max_blur_px", "px", "longest blur, half on each side of a pixel; also the tile size"}, s.max_blur_px, 2.0f, 64.0f);
    v.field({"samples", "", "gather taps per pixel (quality knob)"}, s.samples, 2, 64);
    v.field({"depth_extent", "", "relative depth difference over which foreground and background blend"},
            s.depth_extent, 0.001f, 1.0f);
}

}  // namespace vista
