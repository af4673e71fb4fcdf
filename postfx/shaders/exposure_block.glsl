// The exposure passes' uniforms: postfx/exposure.cpp fills them, exposure_adapt.glsl and
// exposure_apply.glsl read them.
#include "../../renderer/shaders/pass_block.glsl"
PASS_BLOCK(ExposureBlock)
    vec2 u_percent; vec2 u_ev_range;  // adapt: low, high fractions of the counted pixels; min_ev, max_ev
    vec2 u_speed; float u_dt; float u_reset;  // towards brighter, towards darker (1/s); s since the last frame; 1: take the target at once
    // The image holds radiance times the frame's pre-exposure (sky/night_light.h): metering and
    // adaptation happen on the physical value (HDR units of [sky] sun_illuminance), so a change of
    // pre-exposure between frames moves nothing. x log2 pre-exposure, y log2 cd/m^2 per HDR unit,
    // z night_ev; w 2^ev.
    vec3 u_units; float u_compensation;
    float u_exposure; float u_unused0; float u_unused1; float u_unused2;  // apply: the manual scale
PASS_BLOCK_END
