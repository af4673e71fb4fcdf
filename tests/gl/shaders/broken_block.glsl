// A pass block whose first row breaks std140 (a vec3 after a float moves to the next row in
// GLSL): the kit must refuse it (tests/gl/pass_kit_test.cpp).
#include "../../../renderer/shaders/pass_block.glsl"
PASS_BLOCK(BrokenBlock)
    float u_x; vec3 u_y;
    float u_z0; float u_z1; float u_z2; float u_z3;
PASS_BLOCK_END
