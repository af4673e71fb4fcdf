// "shadows.spot_view": the spot shadow atlas as grey levels, near the light bright, the light's
// radius (and tiles nothing was drawn into) black; magenta lines between the tiles.
#include "../../shaders/fullscreen.glsl"

#ifdef FRAGMENT_SHADER
#include "../../shaders/common.glsl"

layout(binding = BINDING_SPOT_SHADOW_DEPTH) uniform sampler2D u_spot_depth;
#include "shadow_view_block.glsl"
layout(location = 0) out vec4 o_color;

void main() {
    vec2 uv = gl_FragCoord.xy * u_viewport.zw;
    if (u_shadow_view.x == 0) {
        o_color = vec4(0.25, 0.25, 0.25, 1.0);
        return;
    }
    float depth = textureLod(u_spot_depth, uv, 0.0).r;
    vec2 cell = fract(uv * float(u_shadow_view.x));
    vec2 edge = min(cell, 1.0 - cell) * u_viewport.xy / float(u_shadow_view.x);  // screen pixels to the tile's border
    bool line = min(edge.x, edge.y) < 1.0;
    // Reversed-Z depth is about near / distance: its fourth root spreads the metres a lamp lights.
    o_color = line ? vec4(1.0, 0.0, 1.0, 1.0) : vec4(vec3(pow(clamp(depth, 0.0, 1.0), 0.25)), 1.0);
}
#endif
