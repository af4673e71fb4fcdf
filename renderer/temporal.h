// What every temporal technique (TAA, the clouds' history) shares on the CPU: the sub-pixel
// jitter sequence, camera-cut detection and the reprojection of this frame's camera-relative
// points into the previous frame's clip space (in double: both frames render camera-relative,
// and the camera may be 10,000 km from the origin). docs/temporal.md describes the whole.
#pragma once

#include "renderer/camera.h"

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

#include <cstdint>

namespace vista {

// The radical inverse of index in base (index >= 1 gives the Halton sequence's terms).
double radicalInverse(std::uint64_t index, int base);

// The TAA jitter of frame `index` in pixels, each axis in (-0.5, 0.5): Halton(2, 3) terms
// 1..8, repeating (Karis 2014: 8 samples are enough with a 0.1 blend).
glm::dvec2 taaJitterPx(std::uint64_t index);

// Shifts the projection (and view_proj, inv_view_proj) by jitter_px pixels, so every pass that
// reconstructs positions from depth through the frame uniforms stays consistent.
void applyJitter(ViewMatrices& m, glm::dvec2 jitter_px, int width, int height);

// True when the camera jumped between two consecutive frames: moved more than distance_m or
// turned (view direction or field of view) more than angle_deg. History is rejected there.
bool cameraCut(const ViewParams& previous, const ViewParams& current, double distance_m, double angle_deg);

// Maps a point camera-relative to `current` (world axes, metres) to the previous frame's clip
// coordinates (unjittered). The camera's translation is taken in double.
glm::dvec4 reprojectPoint(const ViewParams& previous, const ViewParams& current, const glm::dvec3& relative);

// prev_view_proj * translate(current - previous): the same mapping as a matrix (for shaders;
// rounding to float is safe as the translation between frames is small).
glm::dmat4 previousClipFromRelative(const ViewParams& previous, const ViewParams& current);

}  // namespace vista
