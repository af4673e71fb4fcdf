// A pass block with every kind of row the kit allows (tests/gl/pass_kit_test.cpp).
#include "../../../renderer/shaders/pass_block.glsl"
PASS_BLOCK(ProbeBlock)
    vec3 u_a; float u_b;
    vec2 u_c; vec2 u_d;
    float u_e; float u_f; vec2 u_g;
    int u_h; int u_i; float u_j; float u_k;
    vec4 u_l;
    mat4 u_m;
PASS_BLOCK_END
