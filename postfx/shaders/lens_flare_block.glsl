// The lens flare passes' uniforms: postfx/lens_flare.cpp fills them, lens_flare_visibility.glsl
// and lens_flare.glsl read them.
#include "../../renderer/shaders/pass_block.glsl"
PASS_BLOCK(LensFlareBlock)
    vec2 u_sun_uv; float u_radius_px; float u_strength;  // the sun on screen; visibility: sampling radius (px); flare: intensity * illuminance
    float u_dt; float u_rate; float u_reset; float u_starburst;  // visibility: s since the last frame, 1/s, 1: take the measurement at once
    float u_ghosts; float u_ghost_spacing; float u_halo_radius; float u_chromatic;
PASS_BLOCK_END
