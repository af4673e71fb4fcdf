// "weather.splash": short-lived splashes on the terrain around the camera (sky/weather/weather_model.h):
// slot j of ground cell m splashes once per period at a place hashed from (m, j, cycle), for
// the first quarter of the period; a camera-facing sprite centred a little above the terrain
// surface (the full-resolution surface, as tiles.glsl) draws a growing, fading crown ring.
// Lit like the drops; premultiplied alpha over scene.hdr, depth-tested (reversed-Z).
#include "../../../renderer/shaders/common.glsl"
#include "../../../renderer/shaders/counters.glsl"
#include "../../../terrain/shaders/tiles.glsl"
#include "weather_common.glsl"

#include "weather_splash_block.glsl"
layout(binding = BINDING_TEX_0) uniform sampler2DArray u_height;

layout(std430, binding = BINDING_COUNTERS) buffer Counters { uint u_count_lo; uint u_count_hi; };

const float kLife = 0.25;  // share of the period a splash is visible

#ifdef VERTEX_SHADER
out vec2 v_uv;            // sprite coordinates in [-1, 1]^2
flat out vec3 v_look;     // ring radius (uv), alpha, unused

void main() {
    const int cells = u_layout.x, slots = u_layout.z;
    int cell_index = gl_InstanceID / slots, j = gl_InstanceID - cell_index * slots;
    ivec2 o = ivec2(cell_index % cells, cell_index / cells);
    uvec2 cell = uvec2(u_box) + uvec2(o);
    uint h = weatherHash(cell.x, cell.y, uint(j), 0x51ab5u);
    float u = u_cycle.z + weatherRandom(h, 0u);
    float whole = floor(u), age = u - whole;
    uint cycle = u_cycle_index.x + uint(whole);
    uint hk = weatherHash(cell.x, cell.y, uint(j), cycle);
    vec2 xz = (vec2(o - u_layout.y) + vec2(weatherRandom(hk, 1u), weatherRandom(hk, 2u)) - u_cycle.xy) * u_look.w;
    float keep = weatherRandom(hk, 3u);
    v_uv = vec2(0.0);
    v_look = vec3(0.0);
    if (float(j) + keep >= u_cycle.w || age >= kLife || length(xz) > u_look.y) {
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
        return;
    }
    float height = u_height_map.y + u_height_map.x * tileSurfaceSample(u_height, (xz - u_map_min) / u_texel_m, u_tiles, u_tile_layer);
    if (length(vec3(xz.x, height, xz.y)) > u_look.y) {  // the ground is far below (or above) the camera
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
        return;
    }
    float a = age / kLife;  // 0..1 over the splash's life
    float size = u_look.x * (0.4 + 0.6 * sqrt(a));
    vec3 base = vec3(xz.x, height, xz.y);
    vec3 centre = base + vec3(0.0, 0.5 * size, 0.0);
    float d = length(centre);
    float px_m = 2.0 * d / (u_proj[1][1] * u_viewport.y);
    float w = max(size, 2.0 * px_m);
    if (u_layout.w != 0 && gl_VertexID == 0 && (u_view * vec4(centre, 0.0)).z < 0.0)
        ADD_COUNTER64(u_count_lo, u_count_hi, 1u);
    vec2 corner = vec2((gl_VertexID & 1) == 0 ? -1.0 : 1.0, gl_VertexID >= 2 ? 1.0 : -1.0);
    vec3 right = vec3(u_view[0][0], u_view[1][0], u_view[2][0]);  // camera axes in world space
    vec3 up = vec3(u_view[0][1], u_view[1][1], u_view[2][1]);
    v_uv = corner * (w / size);
    v_look = vec3(0.3 + 0.7 * a, u_look.z * (1.0 - a) * (1.0 - a) * size / w, 0.0);
    gl_Position = u_view_proj * vec4(centre + (right * corner.x + up * corner.y) * w, 1.0);
}
#endif

#ifdef FRAGMENT_SHADER
in vec2 v_uv;
flat in vec3 v_look;
layout(location = 0) out vec4 o_color;

void main() {
    // A crown: the upper part of a ring that widens over the splash's life.
    float r = length(v_uv);
    float ring = (1.0 - smoothstep(0.0, 0.2, abs(r - v_look.x))) * smoothstep(-0.4, 0.3, v_uv.y);
    float a = clamp(ring * v_look.y, 0.0, 1.0);
    o_color = vec4((u_ambient.rgb + u_sun.rgb * 0.3) * a, a);
}
#endif
