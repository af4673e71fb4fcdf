// Binding points and sizes shared by the post effects' C++ and GLSL (one source:
// postfx/shaders/postfx_bindings.glsl, included here as C++).
#pragma once

#include "postfx/shaders/postfx_bindings.glsl"

namespace vista::postfx {

constexpr int kHistogramBinding = POSTFX_BINDING_HISTOGRAM;  // shader storage: uint bins[EXPOSURE_BINS]
constexpr int kExposureBinding = POSTFX_BINDING_EXPOSURE;    // shader storage: ExposureState
constexpr int kHistogramBins = EXPOSURE_BINS;
constexpr float kHistogramLogMin = float(EXPOSURE_LOG_MIN);  // log2 luminance of bin 1's lower edge
constexpr float kHistogramLogMax = float(EXPOSURE_LOG_MAX);  // log2 luminance of the last bin's upper edge
constexpr int kHistogramGroup = EXPOSURE_GROUP;              // compute workgroup side
constexpr int kDofFocusBinding = POSTFX_BINDING_DOF_FOCUS;   // shader storage: DofFocusState (postfx/dof.h)
constexpr int kFlareVisibilityBinding = POSTFX_BINDING_FLARE_VISIBILITY;  // shader storage: FlareVisibility (postfx/lens_flare.h)
constexpr int kDofTile = DOF_TILE;                           // px per side of a depth-of-field near tile

// std430 mirror of ExposureState in postfx/shaders/exposure_adapt.glsl.
struct ExposureState {
    float adapted_log2 = 0.0f;  // log2 of the adapted (metered, smoothed) average luminance
    float scale = 1.0f;         // what the image is multiplied by
    float target_log2 = 0.0f;   // this frame's metered value, before adaptation
    float valid = 0.0f;         // 0 until the first metering
};

}  // namespace vista::postfx
