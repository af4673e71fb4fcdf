// The frame's motion vectors ("temporal.velocity", docs/temporal.md): each pixel's depth
// reprojected into the previous frame by the camera's motion, built in double on the CPU
// (renderer/temporal.h). One target every temporal consumer reads instead of reprojecting on
// its own (TAA, motion blur). The sea adds its waves' own motion (terrain/water/water.h addVelocityPass)
// and the grass its blades' motion in the wind (terrain/grass/grass.h addVelocityPass), the rain
// and snow their drops' (sky/weather/weather.h addVelocityPass).
//
// RGBA32F: rg = this pixel's unjittered UV minus the UV its point had in the previous frame
// (the previous position is uv - rg), b = that point's reversed-Z depth in the previous frame
// (for disocclusion tests), a = 1 where the point was in front of the previous camera, else 0
// (rg, b then 0). The sky (depth 0) moves with the camera's rotation only.
#pragma once

#include "renderer/camera.h"
#include "renderer/render_context.h"

#include <glm/mat4x4.hpp>

#include <string>
#include <utility>
#include <vector>

namespace vista {

// This frame's unjittered clip coordinates (x, y, reversed-Z depth, 1) to the previous frame's
// clip coordinates; the camera's translation between them taken in double.
glm::dmat4 clipReprojection(const ViewParams& previous, const ViewParams& current);

// The velocity as the pass writes it, on the CPU (tests): uv_velocity for a pixel at this frame's
// unjittered NDC `ndc` and depth `depth`; w false behind the previous camera.
glm::dvec4 cpuVelocity(const ViewParams& previous, const ViewParams& current, glm::dvec2 ndc, double depth);

// Adds "temporal.velocity" from depth; previous == rc.view (no previous frame) gives zero motion.
TextureHandle addVelocityPass(FrameGraph& graph, const RenderContext& rc, TextureHandle depth, const ViewParams& previous);

ProgramList velocityPrograms();

}  // namespace vista
