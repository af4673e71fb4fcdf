// The exposure scale a pass multiplies its input by: u_exposure (manual: 2^ev), or with
// EXPOSURE_AUTO the scale "postfx.exposure.adapt" left in the exposure state buffer.
#include "postfx_bindings.glsl"

#ifdef EXPOSURE_AUTO
layout(std430, binding = POSTFX_BINDING_EXPOSURE) readonly buffer ExposureState {
    float e_adapted_log2;
    float e_scale;
    float e_target_log2;
    float e_valid;
};
float exposureScale(float manual) { return e_scale; }
#else
float exposureScale(float manual) { return manual; }
#endif
