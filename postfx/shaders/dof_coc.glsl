// "postfx.dof.coc": the colour with NaN/Inf replaced by 0 and clamped to the half-float range
// (so no bad pixel spreads through the gather), and the signed circle of confusion radius in
// pixels (positive behind the focus, negative in front), thin lens (postfx/dof.h):
//     radius = 0.5 * f^2 / N * (P - 1/S) / (1 - f P) / sensor_height * image_height
// with 1/S = depth / near (reversed-Z, infinite far plane: the sky is 1/S = 0).
#include "../../renderer/shaders/fullscreen.glsl"

#ifdef FRAGMENT_SHADER
#include "postfx_bindings.glsl"
#include "../../renderer/shaders/bindings.glsl"
layout(binding = BINDING_TEX_0) uniform sampler2D u_image;
layout(binding = BINDING_TEX_1) uniform sampler2D u_depth;
#ifdef DOF_AUTOFOCUS
layout(std430, binding = POSTFX_BINDING_DOF_FOCUS) readonly buffer DofFocus {
    float diopters;
    float target;
    float valid;
    float pad;
};
#endif
#include "dof_block.glsl"
layout(location = 0) out vec4 o_coc;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec3 c = texelFetch(u_image, p, 0).rgb;
    c = (any(isnan(c)) || any(isinf(c))) ? vec3(0.0) : clamp(c, vec3(0.0), vec3(65504.0));
#ifdef DOF_AUTOFOCUS
    float focus = isnan(diopters) ? 0.0 : clamp(diopters, 0.0, u_max_diopters);
#else
    float focus = u_manual_diopters;
#endif
    float d = texelFetch(u_depth, p, 0).r;
    float inv_distance = (d > 0.0 && !isnan(d)) ? min(d, 1.0) / u_near_m : 0.0;  // NaN: infinitely far
    float f = u_focal_m;
    float radius = 0.5 * f * f / u_f_stop * (focus - inv_distance) / (1.0 - f * focus) / u_sensor_m * u_height_px;
    o_coc = vec4(c, clamp(radius, -u_max_coc_px, u_max_coc_px));
}
#endif
