// The shadow debug views' uniforms (shadows.view, shadows.spot_view, shadows.point_view):
// renderer/shadows/shadow_view.cpp fills them, shadow_view.glsl, spot_atlas_view.glsl and
// point_shadow_view.glsl read them.
#ifndef SHADOW_VIEW_BLOCK_GLSL
#define SHADOW_VIEW_BLOCK_GLSL
#include "../../shaders/pass_block.glsl"
PASS_BLOCK(ShadowViewBlock)
    ivec4 u_shadow_view;  // x: cascades, atlas tiles per side or cubes (0: none this frame); y: bit c set when cascade c was drawn; unused
PASS_BLOCK_END
#endif
