// "weather.rain": one camera-facing quad per drop candidate of the box around the camera
// (sky/weather/weather_model.h has the placement and its CPU mirror), evaluated in the vertex shader:
// instance i is drop j = i mod n of the i / n-th cell the CPU listed as visible (n drops
// drawn per cell), at the camera-relative place (cell - camera cell + hashed offset - camera
// fraction) x cell size.
// Rain: a streak from where the drop was streak_time ago (relative to the moving camera) to
// where it is, at least 1.5 px wide (thinner drops fade instead); SNOW: a round flake swaying
// sideways. Lit by the sun and sky irradiance at the camera (dark at night), premultiplied
// alpha over scene.hdr, depth-tested against scene.depth (reversed-Z).
// RAIN_VELOCITY ("weather.velocity"): the same quads again over the frame's motion vectors
// (renderer/velocity.h), after the camera's: where a drop is opaque enough to be what TAA
// should follow (u_velocity_cover.z), the pixel takes the drop's motion: its camera-relative
// point moved back by the drop's world velocity over the frame interval, projected by the
// previous camera (u_prev_clip); elsewhere the background's vector stays.
#include "../../../renderer/shaders/common.glsl"
#include "../../../renderer/shaders/counters.glsl"
#include "weather_common.glsl"

#include "weather_rain_block.glsl"

layout(std430, binding = BINDING_COUNTERS) buffer Counters { uint u_count_lo; uint u_count_hi; };
layout(std430, binding = BINDING_WEATHER_CELLS) readonly buffer Cells { uint u_cells[]; };  // o.x + cells (o.y + cells o.z)

#ifdef VERTEX_SHADER
out vec2 v_local;         // along the streak from its tail end (m), across (m)
flat out vec4 v_streak;   // length between the cap centres (m), half width (m), alpha, unused
flat out vec3 v_radiance;
#ifdef RAIN_VELOCITY
out vec4 v_prev_clip;
#endif

void main() {
    const int cells = u_box_min.w, per_cell = u_layout.y;
    int listed = gl_InstanceID / per_cell, j = gl_InstanceID - listed * per_cell;
    int code = int(u_cells[listed]);
    ivec3 o = ivec3(code % cells, (code / cells) % cells, code / (cells * cells));
    uvec3 cell = uvec3(u_box_min.xyz) + uvec3(o);
    uint h = weatherHash(cell.x, cell.y, cell.z, uint(j));
    vec3 r = vec3(weatherRandom(h, 0u), weatherRandom(h, 1u), weatherRandom(h, 2u));
    vec3 p = (vec3(o - u_layout.x) + r - u_frac.xyz) * u_frac.w;
    float keep = weatherRandom(h, 3u);
    float size = 0.6 + 0.8 * weatherRandom(h, 4u);
    vec3 v = u_motion.xyz;
#ifdef SNOW
    float phase = u_sway.y + 6.28318530718 * weatherRandom(h, 5u);
    p += u_sway.x * vec3(sin(phase), 0.0, cos(phase));
    v += u_sway.x * u_sway.z * vec3(cos(phase), 0.0, -sin(phase));
#endif
    float d = length(p);
    float near = u_shape.y, radius = u_shape.x;
    float fade = (near > 0.0 ? smoothstep(near, 2.0 * near, d) : 1.0) * (1.0 - smoothstep(0.75 * radius, radius, d));
    if (float(j) + keep >= u_shape.w || fade <= 0.0 || d < 1e-4) {
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0);  // outside the clip volume: nothing drawn
        v_local = vec2(0.0);
        v_streak = vec4(0.0);
        v_radiance = vec3(0.0);
#ifdef RAIN_VELOCITY
        v_prev_clip = vec4(0.0);
#endif
        return;
    }
    if (u_layout.z != 0 && gl_VertexID == 0 && (u_view * vec4(p, 0.0)).z < 0.0)
        ADD_COUNTER64(u_count_lo, u_count_hi, 1u);

    vec3 view = p / d;
    float px_m = 2.0 * d / (u_proj[1][1] * u_viewport.y);  // one pixel at this distance (m)
    float width = u_shape.z * size;
    float w = max(width, 1.5 * px_m);
    float coverage = sqrt(width / w);  // thinner than 1.5 px: fainter (less than linearly: a streak stays visible)
    vec3 axis = v * u_motion.w;  // tail to head
    float len = length(axis);
    vec3 side = cross(axis, view);
    if (length(side) < 1e-3 * max(len, 1e-6)) side = cross(view, abs(view.y) < 0.9 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0));
    side = safeNormalize(side);
    vec3 dir = len > 1e-6 ? axis / len : safeNormalize(cross(side, view));
    // Corners 0, 1 at the tail end, 2, 3 at the head end (a strip), half a width beyond the
    // cap centres so the ends are round.
    float along = gl_VertexID >= 2 ? 1.0 : 0.0, across = (gl_VertexID & 1) == 0 ? -1.0 : 1.0;
    vec3 tail = p - axis;
    vec3 corner = mix(tail - dir * (0.5 * w), p + dir * (0.5 * w), along) + side * (across * 0.5 * w);
    v_local = vec2(along * (len + w), across * 0.5 * w);
    v_streak = vec4(len, 0.5 * w, coverage * fade * u_ambient.w, 0.0);

    float mu = dot(view, u_sun_dir.xyz);
#ifdef SNOW
    v_radiance = u_ambient.rgb + u_sun.rgb * 0.5;  // a rough white flake: Lambert-like
#else
    // Water drops: some diffuse light, and the sun refracted forward through them.
    v_radiance = u_ambient.rgb + u_sun.rgb * (0.05 + 2.0 * pow(max(mu, 0.0), 12.0));
#endif
    gl_Position = u_view_proj * vec4(corner, 1.0);
#ifdef RAIN_VELOCITY
    // The drop's world velocity: its motion relative to the camera plus the camera's.
    v_prev_clip = u_prev_clip * vec4(corner - (v + u_camera_motion.xyz) * u_camera_motion.w, 1.0);
#endif
}
#endif

#ifdef FRAGMENT_SHADER
in vec2 v_local;
flat in vec4 v_streak;
flat in vec3 v_radiance;
#ifdef RAIN_VELOCITY
in vec4 v_prev_clip;
#include "../../../renderer/shaders/surface_velocity.glsl"
#endif
layout(location = 0) out vec4 o_color;

void main() {
    // Distance to the segment between the cap centres, in half widths: a capsule.
    float hw = max(v_streak.y, 1e-9);
    float s = v_local.x - hw;
    float q = clamp(s, 0.0, v_streak.x);
    float dist = length(vec2(s - q, v_local.y)) / hw;
    float shape = 1.0 - smoothstep(0.3, 1.0, dist);
#ifndef SNOW
    shape *= 0.35 + 0.65 * (v_streak.x > 0.0 ? q / v_streak.x : 1.0);  // brighter toward the head
#endif
    float a = clamp(shape * v_streak.z, 0.0, 1.0);
#ifdef RAIN_VELOCITY
    if (a < u_velocity_cover.z) discard;
    o_color = surfaceVelocity(v_prev_clip, u_velocity_cover.xy);
#else
    o_color = vec4(v_radiance * a, a);
#endif
}
#endif
