// "grass.gbuffer": the blades grass.cull kept, one triangle strip each (2 vertices per
// segment level and one at the tip), drawn by two indirect draws: near blades with
// u_segments segments, far ones with fewer. Each segment is the rest segment rotated toward
// the bend direction by an angle growing along the blade, so bending keeps the blade's length
// (grass_placement.cpp grassBladePoint is the CPU mirror). Writes the G-buffer like the
// terrain; the shading normal is blended toward the terrain normal so a meadow seen from
// above shades like the ground it covers. SHADOW_PASS: the same blades depth-only into a shadow
// view (sun cascades, spot shadow atlas). GRASS_VELOCITY ("grass.velocity"): the blades' own
// motion into the frame's motion vectors (renderer/velocity.h), drawn again with depth test EQUAL
// (gl_Position is invariant) over the camera's vectors: each vertex also bent as one frame
// earlier (the cull's bend change, look.w) and projected by u_prev_clip (the previous camera's
// clip from this camera's relative space); rg = this pixel's unjittered UV minus that UV, b its
// previous depth, a = 1.
#include "../../../renderer/shaders/common.glsl"
#include "../../../renderer/shaders/gbuffer.glsl"
#include "grass_common.glsl"

layout(std430, binding = BINDING_GRASS_BLADES) readonly buffer Blades { GrassBlade u_blades[]; };
#include "grass_block.glsl"

#ifdef VERTEX_SHADER
invariant gl_Position;
#ifdef GRASS_VELOCITY
out vec4 v_prev_clip;
#endif
out vec3 v_normal;           // blade normal (world, one side)
flat out vec3 v_ground;      // terrain normal
out vec3 v_albedo;

// Root to level `level` of a blade of length len bent by bend (direction and tip angle, rad):
// the sum of rotated unit segments (length preserved).
vec3 bladeSpine(float len, vec2 bend, int n, int level) {
    float tip_angle = min(length(bend), 1.4);
    vec2 dir = length(bend) > 1e-6 ? bend / length(bend) : vec2(0.0, 1.0);
    vec3 bend_dir = vec3(dir.x, 0.0, dir.y);
    vec3 p = vec3(0.0);
    float seg = len / float(n);
    for (int j = 0; j < level; ++j) {
        float s = (float(j) + 0.5) / float(n);
        float theta = tip_angle * s * sqrt(s);
        p += seg * (vec3(0.0, cos(theta), 0.0) + sin(theta) * bend_dir);
    }
    return p;
}

void main() {
    GrassBlade b = u_blades[u_first + uint(gl_InstanceID)];
    int n = u_segments;
    int level = min(gl_VertexID / 2, n);
    bool tip = gl_VertexID >= 2 * n;
    float side = tip ? 0.0 : (gl_VertexID % 2 == 0 ? -1.0 : 1.0);
    float len = b.shape.x;
    float tip_angle = min(length(b.shape.zw), 1.4);
    vec2 dir = length(b.shape.zw) > 1e-6 ? b.shape.zw / length(b.shape.zw) : vec2(0.0, 1.0);
    vec3 bend_dir = vec3(dir.x, 0.0, dir.y);
    vec3 p = bladeSpine(len, b.shape.zw, n, level);
    float s_here = (float(min(level, n - 1)) + 0.5) / float(n);
    float theta_here = tip_angle * s_here * sqrt(s_here);
    vec3 tangent = vec3(0.0, cos(theta_here), 0.0) + sin(theta_here) * bend_dir;
    vec3 across = vec3(cos(b.shape.y), 0.0, sin(b.shape.y));
    float s = float(level) / float(n);
    float width = b.root_width.w * (1.0 - pow(s, 1.3));
    vec3 offset = across * (0.5 * side * width);
    p += offset;

    vec3 normal = safeNormalize(cross(across, tangent));
    // A little roundness across the blade.
    v_normal = safeNormalize(normal + across * (0.35 * side));
    v_ground = safeNormalize(unpackSnorm4x8(b.look.y).xyz);
    vec3 tip_albedo = unpackUnorm4x8(b.look.x).rgb;
    v_albedo = tip_albedo * tip_albedo * mix(1.0 - u_look.x, 1.0, s);
#ifdef SHADOW_PASS
    gl_Position = u_shadow_matrix * vec4(b.root_width.xyz + p, 1.0);
#else
    gl_Position = u_view_proj * vec4(b.root_width.xyz + p, 1.0);
#endif
#ifdef GRASS_VELOCITY
    vec3 before = bladeSpine(len, b.shape.zw + unpackHalf2x16(b.look.w), n, level) + offset;
    v_prev_clip = u_prev_clip * vec4(b.root_width.xyz + before, 1.0);
#endif
}
#endif

#if defined(FRAGMENT_SHADER) && defined(GRASS_VELOCITY)
in vec4 v_prev_clip;
layout(location = 0) out vec4 o_velocity;
#include "../../../renderer/shaders/surface_velocity.glsl"
void main() { o_velocity = surfaceVelocity(v_prev_clip, u_jitter.xy); }
#endif

#if defined(FRAGMENT_SHADER) && defined(SHADOW_PASS)
void main() {}  // depth only
#endif

#if defined(FRAGMENT_SHADER) && !defined(SHADOW_PASS) && !defined(GRASS_VELOCITY)
in vec3 v_normal;
flat in vec3 v_ground;
in vec3 v_albedo;
layout(location = 0) out vec4 o_color;   // emissive radiance: none
layout(location = 1) out vec4 o_albedo;
layout(location = 2) out vec4 o_normal;

void main() {
    vec3 n = safeNormalize(gl_FrontFacing ? v_normal : -v_normal);
    // Toward the terrain normal: from above a blade shades like the ground it covers, and the
    // back of a blade never turns fully away from the sky.
    n = safeNormalize(mix(n, v_ground, u_look.z));
    Surface surface;
    // Wet blades ([weather] rain): a water film darkens them a little and makes them glossy.
    surface.albedo = v_albedo * (1.0 - 0.3 * u_look.w);
    surface.roughness = mix(u_look.y, 0.2, u_look.w);
    surface.normal = n;
    surface.f0 = 0.04;
    surface.lit = true;
    encodeSurface(surface, o_albedo, o_normal);
    o_color = vec4(0.0, 0.0, 0.0, 1.0);
}
#endif
