// "postfx.motion_blur.tiles" (mode 0): the longest velocity of each k x k block of pixels.
// "postfx.motion_blur.neighbors" (mode 1): the longest of the 3x3 tiles around each tile.
#include "../../renderer/shaders/fullscreen.glsl"

#ifdef FRAGMENT_SHADER
#include "../../renderer/shaders/bindings.glsl"
layout(binding = BINDING_TEX_0) uniform sampler2D u_in;
#include "motion_blur_block.glsl"
layout(location = 0) out vec4 o_max;

void main() {
    ivec2 t = ivec2(gl_FragCoord.xy);
    ivec2 size = textureSize(u_in, 0);
    vec2 longest = vec2(0.0);
    float len2 = 0.0;
    ivec2 lo = u_tiles.x == 0 ? t * u_tiles.y : max(t - 1, ivec2(0));
    ivec2 hi = u_tiles.x == 0 ? min(t * u_tiles.y + u_tiles.y, size) - 1 : min(t + 1, size - 1);
    for (int y = lo.y; y <= hi.y; ++y)
        for (int x = lo.x; x <= hi.x; ++x) {
            vec2 v = texelFetch(u_in, ivec2(x, y), 0).rg;
            float l2 = dot(v, v);
            if (l2 > len2) longest = v, len2 = l2;
        }
    o_max = vec4(longest, 0.0, 1.0);
}
#endif
