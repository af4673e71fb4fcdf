// "shadows.view" ([debug] view = shadow_map): the sun cascades' depth maps side by side, depth
// 0 (nearest the sun) black to 1 white; grey where there are no shadows this frame and for
// cascades with no casters.
#include "../../shaders/fullscreen.glsl"

#ifdef FRAGMENT_SHADER
#include "../../shaders/common.glsl"
layout(binding = BINDING_SHADOW_DEPTH) uniform sampler2DArray u_shadow_depth;
#include "shadow_view_block.glsl"
layout(location = 0) out vec4 o_color;

void main() {
    vec2 uv = gl_FragCoord.xy * u_viewport.zw;
    if (u_shadow_view.x == 0) {
        o_color = vec4(vec3(0.3), 1.0);
        return;
    }
    // Square tiles in a row, as large as the screen allows.
    float tile = min(u_viewport.x / float(u_shadow_view.x), u_viewport.y);
    vec2 p = gl_FragCoord.xy / tile;
    int c = int(p.x);
    if (c >= u_shadow_view.x || p.y >= 1.0) {
        o_color = vec4(0.0, 0.0, 0.0, 1.0);
        return;
    }
    if (((u_shadow_view.y >> c) & 1) == 0) {  // no casters: not drawn this frame, read as lit
        o_color = vec4(vec3(0.3), 1.0);
        return;
    }
    float d = textureLod(u_shadow_depth, vec3(fract(p.x), p.y, float(c)), 0.0).r;
    o_color = vec4(vec3(d), 1.0);
}
#endif
