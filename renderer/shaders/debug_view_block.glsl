// debug.view's uniforms: renderer/debug_view.cpp fills them, debug_view.glsl reads them.
#include "pass_block.glsl"
PASS_BLOCK(DebugViewBlock)
    ivec4 u_debug_view;  // x: the view (config DebugView), unused
    vec4 u_heat;   // x: the heat ramp's top (lights per pixel), < 0: no heat target (no local lights); unused
PASS_BLOCK_END
