// "shadows.point_view": the point lights' depth cubes as grey levels, one row per cube (the first
// at the top) of its six faces +X -X +Y -Y +Z -Z, each upright as the face sees it; near the light
// bright, the light's radius black; magenta lines between the faces.
#include "../../shaders/fullscreen.glsl"

#ifdef FRAGMENT_SHADER
#include "../../shaders/common.glsl"

layout(binding = BINDING_POINT_SHADOW_DEPTH) uniform samplerCubeArray u_point_depth;
#include "shadow_view_block.glsl"
layout(location = 0) out vec4 o_color;

// The direction of face texel (s, t) (t = 0 the face's top row), as GL's cube-map table has it.
vec3 cubeDirection(int face, vec2 st) {
    vec2 c = st * 2.0 - 1.0;
    if (face == 0) return vec3(1.0, -c.y, -c.x);
    if (face == 1) return vec3(-1.0, -c.y, c.x);
    if (face == 2) return vec3(c.x, 1.0, c.y);
    if (face == 3) return vec3(c.x, -1.0, -c.y);
    if (face == 4) return vec3(c.x, -c.y, 1.0);
    return vec3(-c.x, -c.y, -1.0);
}

void main() {
    vec2 uv = gl_FragCoord.xy * u_viewport.zw;
    if (u_shadow_view.x == 0) {
        o_color = vec4(0.25, 0.25, 0.25, 1.0);
        return;
    }
    vec2 grid = vec2(6.0, float(u_shadow_view.x));
    vec2 cell = vec2(uv.x, 1.0 - uv.y) * grid;  // rows from the top
    ivec2 index = ivec2(min(floor(cell), grid - 1.0));
    vec2 st = fract(cell);
    vec2 edge = min(st, 1.0 - st) * u_viewport.xy / grid;  // screen pixels to the face's border
    if (min(edge.x, edge.y) < 1.0) {
        o_color = vec4(1.0, 0.0, 1.0, 1.0);
        return;
    }
    float depth = textureLod(u_point_depth, vec4(cubeDirection(index.x, st), float(index.y)), 0.0).r;
    // Reversed-Z depth is about near / distance: its fourth root spreads the metres a lamp lights.
    o_color = vec4(vec3(pow(clamp(depth, 0.0, 1.0), 0.25)), 1.0);
}
#endif
