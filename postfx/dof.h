// Depth of field: "postfx.dof.focus" (autofocus: the median of 5 depth samples around the
// screen centre, smoothed exponentially in time into a persistent state), "postfx.dof.coc"
// (sanitised colour and the signed circle of confusion per pixel), "postfx.dof.tiles" and
// "postfx.dof.dilate" (the largest near-field radius per 16x16 tile, spread to the tiles it
// can reach) and "postfx.dof.gather" (a disk gather with separate far and near fields, so the
// blurred foreground covers what is in focus behind it).
//
// Thin lens: an object at distance S seen through a lens of focal length f and f-number N
// focused at S1 images as a disk of diameter
//     c = f^2 / (N (S1 - f)) * |S - S1| / S   (on the sensor, same units as f)
//       = f^2 / N * |P - 1/S| / (1 - f P)     with P = 1/S1 (the focus in diopters).
// In pixels: c / sensor_height * image_height. Distances are along the view axis; the field
// of view comes from [camera] fov_deg, so focal length and sensor only set the blur.
#pragma once

#include "postfx/dof_settings.h"
#include "postfx/postfx_bindings.h"
#include "renderer/gl/objects.h"
#include "renderer/render_context.h"

#include <string>
#include <utility>
#include <vector>

namespace vista {

namespace postfx {
// std430 mirror of DofFocus in postfx/shaders/dof_focus.glsl.
struct DofFocusState {
    float diopters = 0.0f;  // 1 / focus distance (m), smoothed
    float target = 0.0f;    // this frame's measured 1 / distance at the screen centre
    float valid = 0.0f;     // 0 until the first measurement
    float pad = 0.0f;
};
}  // namespace postfx

// The signed CoC radius in pixels (positive behind the focus, negative in front), unclamped,
// for an object at distance_m (infinity allowed) and a focus at focus_m; the closed form above.
double dofCocRadiusPx(double distance_m, double focus_m, const DofSettings& s, int image_height);

// The focus in diopters the passes use: 1 / focus_distance_m, kept at or below 1 / (2 f).
float dofClampDiopters(float diopters, const DofSettings& s);

class DepthOfField {
public:
    DepthOfField();
    // Blurs image by depth (reversed-Z, infinite far; near_m from rc.view). dt_s is the time
    // since the last frame (autofocus smoothing); reset takes the measured focus at once.
    TextureHandle addPasses(FrameGraph& graph, const RenderContext& rc, TextureHandle image, TextureHandle depth,
                            const DofSettings& s, double dt_s, bool reset);
    // Reads the autofocus state back (tests, panel; stalls).
    postfx::DofFocusState read() const;
    std::size_t memoryBytes() const { return std::size_t(state_.size()); }  // GPU bytes held across frames

private:
    gl::Buffer state_;
};

// "postfx.dof.coc" alone: RGBA16F, rgb the sanitised colour, a the signed CoC radius (px,
// clamped to max_coc_px). focus: the autofocus state, or invalid for the manual distance.
TextureHandle addDofCocPass(FrameGraph& graph, const RenderContext& rc, TextureHandle image, TextureHandle depth,
                            const DofSettings& s, BufferHandle focus);

ProgramList dofPrograms();

}  // namespace vista
