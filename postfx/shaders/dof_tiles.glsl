// "postfx.dof.tiles" (mode 0): the largest near-field CoC radius (-CoC where negative) of each
// DOF_TILE x DOF_TILE block. "postfx.dof.dilate" (mode 1): the largest of the tiles within
// `reach` tiles, so every pixel a blurred foreground disc can reach knows how far to gather.
#include "../../renderer/shaders/fullscreen.glsl"

#ifdef FRAGMENT_SHADER
#include "postfx_bindings.glsl"
#include "../../renderer/shaders/bindings.glsl"
layout(binding = BINDING_TEX_0) uniform sampler2D u_in;
#include "dof_block.glsl"
layout(location = 0) out vec4 o_near;

void main() {
    ivec2 t = ivec2(gl_FragCoord.xy);
    ivec2 size = textureSize(u_in, 0);
    float near = 0.0;
    if (u_tile_mode == 0) {
        ivec2 end = min(t * DOF_TILE + DOF_TILE, size);
        for (int y = t.y * DOF_TILE; y < end.y; ++y)
            for (int x = t.x * DOF_TILE; x < end.x; ++x) near = max(near, -texelFetch(u_in, ivec2(x, y), 0).a);
    } else {
        int r = u_tile_reach;
        for (int y = max(t.y - r, 0); y <= min(t.y + r, size.y - 1); ++y)
            for (int x = max(t.x - r, 0); x <= min(t.x + r, size.x - 1); ++x)
                near = max(near, texelFetch(u_in, ivec2(x, y), 0).r);
    }
    o_near = vec4(near, 0.0, 0.0, 1.0);
}
#endif
