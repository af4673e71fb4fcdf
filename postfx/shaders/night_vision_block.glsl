// postfx.night_vision's uniforms: postfx/grade.cpp fills them, night_vision.glsl reads them.
#include "../../renderer/shaders/pass_block.glsl"
PASS_BLOCK(NightVisionBlock)
    vec3 u_tint; float u_gain;
    float u_noise; float u_scope_vignette; float u_noise_index; float u_unused;
PASS_BLOCK_END
