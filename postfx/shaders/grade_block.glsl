// postfx.grade's uniforms: postfx/grade.cpp fills them, grade.glsl reads them.
#include "../../renderer/shaders/pass_block.glsl"
PASS_BLOCK(GradeBlock)
    vec3 u_lift; float u_saturation;
    vec3 u_inv_gamma; float u_vignette;      // 1 / gamma; vignette strength
    vec3 u_gain; float u_vignette_start;
    vec3 u_lut_scale; float u_grain;         // LUT domain to texture coordinates: c * scale + offset; grain amplitude
    vec3 u_lut_offset; float u_grain_index;  // grain pattern index (from scene time)
PASS_BLOCK_END
