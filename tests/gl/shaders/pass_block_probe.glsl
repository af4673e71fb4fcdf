// Test probe (tests/gl/pass_kit_test.cpp): pixel x of a 9 x 1 target writes row x of ProbeBlock,
// so the test sees where GLSL read each member the C++ struct wrote. BROKEN reads BrokenBlock.
#include "../../../renderer/shaders/fullscreen.glsl"

#ifdef FRAGMENT_SHADER
// Included here, outside the #ifdef: the shader library pastes each file once, where first seen.
#include "../../../renderer/shaders/pass_block.glsl"
#ifdef BROKEN
#include "broken_block.glsl"
#else
#include "probe_block.glsl"
#endif
layout(location = 0) out vec4 o_probe;

void main() {
    int x = int(gl_FragCoord.x);
#ifdef BROKEN
    o_probe = vec4(u_x, u_y);
#else
    vec4 rows[9] = vec4[9](vec4(u_a, u_b), vec4(u_c, u_d), vec4(u_e, u_f, u_g), vec4(float(u_h), float(u_i), u_j, u_k),
                           u_l, u_m[0], u_m[1], u_m[2], u_m[3]);
    o_probe = rows[x];
#endif
}
#endif
