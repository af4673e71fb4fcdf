// debug.grid's uniforms: renderer/debug_grid.cpp fills them, grid.glsl reads them.
#include "pass_block.glsl"
PASS_BLOCK(GridBlock)
    vec2 u_origin; float u_height; float u_spacing;  // camera xz modulo the pattern period; its height above the plane (m); minor line spacing (m)
    vec4 u_sky;  // x: 1 when a sky lights the scene; unused
PASS_BLOCK_END
