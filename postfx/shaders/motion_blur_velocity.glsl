// "postfx.motion_blur.velocity": the blur vectors from the frame's shared motion vectors
// ("temporal.velocity", renderer/velocity.h: this pixel's UV minus its UV in the previous frame,
// the camera's motion reprojected in double on the CPU). Writes rg = half the blur vector in
// pixels (displacement * exposure / frame time / 2, clamped to the tile size k), b = view
// distance. A point behind the previous camera (velocity a = 0) blurs as far as allowed.
#include "../../renderer/shaders/fullscreen.glsl"

#ifdef FRAGMENT_SHADER
#include "../../renderer/shaders/bindings.glsl"
layout(binding = BINDING_TEX_0) uniform sampler2D u_depth;
layout(binding = BINDING_TEX_1) uniform sampler2D u_motion;  // temporal.velocity
#include "motion_blur_block.glsl"
layout(location = 0) out vec4 o_velocity;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec2 size = vec2(textureSize(u_depth, 0));
    float d = texelFetch(u_depth, p, 0).r;
    d = (d > 0.0 && !isnan(d)) ? min(d, 1.0) : 0.0;
    vec4 motion = texelFetch(u_motion, p, 0);
    vec2 half_v = vec2(0.0);
    if (motion.a > 0.5) {
        half_v = motion.xy * size * (0.5 * u_vel_pass.x);
    } else {
        half_v = vec2(u_vel_pass.y, 0.0);  // behind the previous camera: as long as allowed
    }
    float len = length(half_v);
    if (isnan(len) || isinf(len)) half_v = vec2(0.0), len = 0.0;
    if (len > u_vel_pass.y) half_v *= u_vel_pass.y / len;
    float distance = d > 0.0 ? min(u_vel_pass.z / d, 65000.0) : 65000.0;
    o_velocity = vec4(half_v, distance, 1.0);
}
#endif
