// "water.surface": the sea, drawn over the lit opaque scene before the aerial perspective (which
// then fogs it like the terrain) and the sky. The vertex stage displaces a camera-centred ring
// grid (ring j at radius c (e^(a j) - 1), a = 2 pi / segments: cells about square and growing
// with distance) by the waves its cells can carry; the fragment stage takes the normal from
// every wave its pixel footprint allows (the rest widens the sun's highlight) and composes
//   Fresnel * reflection + (1 - Fresnel) * (refracted scene * e^(-sigma L) + in-scattering)
// + sun glitter + local lights, with foam over it. Reflection: a screen-space ray march through
// the opaque copy, the sky-view LUT where it leaves the screen or finds nothing; refraction: the
// opaque copy offset by the normal; L = the water the view ray crosses (from the opaque depth).
// Seen from below (camera under water), the surface shows the sky (or the scene) refracted
// through it, or the water by total internal reflection. Variants: the local-light method
// (LIGHTS_NAIVE, _TILED, _CLUSTERED, _HASHED) or none; HAS_SUN_SHADOW (the sun's cascades).
// WATER_VIEW 1 normals, 2 foam, 3 water depth: debug views (no lights or shadows).
// WATER_LIGHT_CHUNK (with a method): a further chunk of the local lights only (lights.glsl
// chunkOf), drawn additively over the shaded surface with depth test EQUAL, as much of the
// colour as the lights reach through the foam ((1 - foam) x light: the shaded surface mixes the
// foam over its lit colour); u_light_chunk says which (the shaded surface draws the first).
// gl_Position is invariant so the chunks' depths equal the surface's.
// WATER_VELOCITY ("water.velocity", with none of the others): the surface's own motion into the
// frame's motion vectors (renderer/velocity.h): each vertex also at its previous-frame
// displacement (waves.glsl previousDisplacement) through u_prev_clip (the previous camera's clip
// from this camera's relative space); rg = this pixel's unjittered UV minus that UV, b its previous
// depth, a = 1; drawn with depth test EQUAL, so only where the surface is seen.
// Both stages: included once per file (the shader library expands each file once).
#include "../../../renderer/shaders/common.glsl"
#include "waves.glsl"
#include "water_surface_block.glsl"

#ifdef VERTEX_SHADER
invariant gl_Position;
out vec3 v_position;  // camera-relative, displaced
out vec2 v_rest;      // camera-relative rest position (x, z)
#ifdef WATER_VELOCITY
out vec4 v_prev_clip;
#endif
void main() {
    int segments = int(w_grid.z);
    int ring = gl_VertexID / segments, segment = gl_VertexID - ring * segments;
    float r = w_grid.x * (exp(w_grid.y * float(ring)) - 1.0);
    float angle = w_grid.y * float(segment);
    vec2 rest = r * vec2(cos(angle), sin(angle));
    float cell = (r + w_grid.x) * w_grid.y;  // radial step at this ring
    WaveSample ws = evaluateWaves(rest, cell);
    vec3 p = vec3(rest.x, w_surface.x, rest.y) + ws.displacement;
    v_position = p;
    v_rest = rest;
    gl_Position = u_view_proj * vec4(p, 1.0);
#ifdef WATER_VELOCITY
    v_prev_clip = u_prev_clip * vec4(vec3(rest.x, w_surface.x, rest.y) + previousDisplacement(rest, cell), 1.0);
#endif
}
#endif

#if defined(FRAGMENT_SHADER) && defined(WATER_VELOCITY)
in vec4 v_prev_clip;
layout(location = 0) out vec4 o_velocity;
#include "../../../renderer/shaders/surface_velocity.glsl"
void main() { o_velocity = surfaceVelocity(v_prev_clip, u_jitter.xy); }
#endif

#if defined(FRAGMENT_SHADER) && !defined(WATER_VELOCITY)
#include "../../../renderer/shaders/gbuffer.glsl"
#include "../../../renderer/lighting/shaders/brdf.glsl"
// Shared by lights.glsl and shadows.glsl below; included first and unconditionally because each
// file is expanded once, before the GLSL preprocessor sees the #ifs around them.
#include "../../../renderer/shadows/shaders/shadow_filter.glsl"
#if defined(LIGHTS_NAIVE) || defined(LIGHTS_TILED) || defined(LIGHTS_CLUSTERED) || defined(LIGHTS_HASHED)
#define WATER_LOCAL_LIGHTS
#include "../../../renderer/lighting/shaders/lights.glsl"
#endif
#ifdef HAS_SUN_SHADOW
#include "../../../renderer/shadows/shaders/shadows.glsl"
#endif
#include "../../../sky/weather/shaders/rain_ripples.glsl"
#define SKY_ATMOSPHERE_BLOCK WATER_BINDING_ATMOSPHERE
#include "../../../sky/shaders/atmosphere.glsl"
layout(binding = BINDING_TEX_0) uniform sampler2D u_scene_color;  // water.copy
layout(binding = BINDING_TEX_1) uniform sampler2D u_scene_depth;  // water.copy (R32F, reversed-Z)
layout(binding = BINDING_TEX_2) uniform sampler2D u_sky_view;     // sky-view LUT (w_sun.w = 1)
in vec3 v_position;
in vec2 v_rest;
layout(location = 0) out vec4 o_color;

const float kWaterF0 = 0.02;   // reflectance at normal incidence (n = 1.333)
const float kWaterIor = 1.333;

// Sky radiance along a direction: the sky-view LUT (as sky.glsl reads it) kept above the horizon;
// without a sky, the hemisphere's mean radiance.
vec3 skyRadiance(vec3 dir) {
    if (w_sun.w < 0.5) return w_sky_up.rgb / PI;
    float above = max(aboveHorizon(clamp(dir.y, -1.0, 1.0)), 0.0);
    vec2 h = dir.xz, s = a_sun.xz;
    float hl = dot(h, h), sl = dot(s, s);
    float cos_az = hl > 1e-12 && sl > 1e-12 ? dot(h, s) * inversesqrt(hl * sl) : 1.0;
    return skyRgb(texture(u_sky_view, skyViewUv(above, cos_az)).rgb);
}

ivec2 texelOf(vec2 uv) {
    return clamp(ivec2(uv * u_viewport.xy), ivec2(0), ivec2(u_viewport.xy) - 1);
}

// Screen-space reflection: marches the ray from origin along dir in geometrically growing steps
// through the opaque depth, refines a crossing by bisection and returns the opaque colour there;
// weight (0..1) fades hits near the screen's edges and the ray's end (0: nothing found). Clip
// coordinates are linear along the ray: clip(t) = clip0 + t clip_dir.
vec4 clipAt(vec4 clip0, vec4 clip_dir, float t) { return clip0 + clip_dir * t; }

vec3 traceReflection(vec3 origin, vec3 dir, out float weight) {
    weight = 0.0;
    int steps = int(w_sky_up.w);
    float t_max = w_ground_up.w;
    float t0 = max(0.25, 0.01 * length(origin));
    if (steps <= 0 || t0 >= t_max) return vec3(0.0);
    vec4 clip0 = u_view_proj * vec4(origin, 1.0), clip_dir = u_view_proj * vec4(dir, 0.0);
    float ratio = pow(t_max / t0, 1.0 / float(steps));
    float t_prev = 0.0, t = t0;
    bool crossed = false;
    // The march only finds the step that crosses the depth; the bisection runs once after it
    // (inside the loop a shader core would run it, masked, on every step).
    for (int i = 0; i < steps; ++i) {
        vec4 clip = clipAt(clip0, clip_dir, t);
        if (clip.w <= u_near.x) break;
        vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
        if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) break;
        float d = texelFetch(u_scene_depth, texelOf(uv), 0).r;
        float behind = d > 0.0 ? clip.w - linearDepth(d) : -1.0;
        if (behind > 0.0 && behind < 2.0 * (t - t_prev) + 1.0) {
            crossed = true;
            break;
        }
        t_prev = t;
        t *= ratio;
    }
    if (!crossed) return vec3(0.0);
    float lo = t_prev, hi = t;
    for (int j = 0; j < 5; ++j) {
        float m = 0.5 * (lo + hi);
        vec4 c = clipAt(clip0, clip_dir, m);
        float d2 = texelFetch(u_scene_depth, texelOf(c.xy / max(c.w, 1e-6) * 0.5 + 0.5), 0).r;
        if (d2 > 0.0 && c.w > linearDepth(d2)) hi = m; else lo = m;
    }
    vec4 c = clipAt(clip0, clip_dir, hi);
    vec2 hit = clamp(c.xy / max(c.w, 1e-6) * 0.5 + 0.5, vec2(0.0), vec2(1.0));
    vec2 edge = min(hit, 1.0 - hit);
    weight = smoothstep(0.0, 0.06, min(edge.x, edge.y)) * (1.0 - smoothstep(0.8, 1.0, hi / t_max));
    return texelFetch(u_scene_color, texelOf(hit), 0).rgb;
}

// The shading normal: the waves' (ws), with rain rings near the eye only (their 6 cm wavelength
// is gone within a few tens of metres).
vec3 surfaceNormal(WaveSample ws, float dist) {
    vec3 n = ws.normal;
    float ripples = w_rain.w * (1.0 - smoothstep(15.0, 40.0, dist));
    if (ripples > 0.0) {
        vec3 r = rainRippleNormal(mod(w_rain.xy + v_rest, RAIN_RIPPLE_WRAP_M), w_rain.z, ripples);
        n = normalize(n + vec3(r.x, 0.0, r.z));
    }
    return n;
}

// Seen from above: the shading normal kept facing the eye (grazing back slopes).
vec3 facingEye(vec3 n, vec3 v) {
    float nv = dot(n, v);
    return nv < 0.02 ? normalize(n + v * (0.02 - nv)) : n;
}

// Sun glitter's roughness: GGX widened by the slopes the footprint removed (no aliasing far away).
float glitterRoughness(WaveSample ws) {
    float r0 = w_surface.y;
    return min(sqrt(sqrt(r0 * r0 * r0 * r0 + 2.0 * ws.lost_slope_variance)), 1.0);
}

// Foam cover: bands running up the shore where the water (column metres deep) is shallow, and
// squeezed crests.
float foamCover(WaveSample ws, float column) {
    float foam = 0.0;
    if (w_surface.w > 0.0 && column < w_surface.w) {
        float shore = 1.0 - column / w_surface.w;
        float bands = 0.5 + 0.5 * sin(column / w_surface.w * 9.0 + w_foam.w + 3.0 * ws.displacement.y);
        foam = shore * shore * (0.4 + 0.6 * smoothstep(0.35, 0.75, bands));
    }
    return clamp(foam + w_scatter.w * (1.0 - smoothstep(0.2, 0.5, ws.jacobian)), 0.0, 1.0);
}

#ifdef WATER_LIGHT_CHUNK
// A further chunk of the local lights on the surface seen from above (see the top).
void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    float footprint = max(length(dFdx(v_rest)), length(dFdy(v_rest)));  // before any discard
    vec3 pos = v_position;
    LightRange range = forwardRange(pos, pixel, u_light_chunk);
    if (range.count == 0u || pos.y > 0.0) discard;  // nothing in this chunk, or seen from below (no local lights)
    WaveSample ws = evaluateWaves(v_rest, footprint);
    float dist = max(length(pos), 1e-4);
    vec3 v = -pos / dist;
    float scene_depth = texelFetch(u_scene_depth, pixel, 0).r;
    vec3 scene_pos = positionFromDepth((vec2(pixel) + 0.5) * u_viewport.zw, max(scene_depth, 1e-30));
    float foam = foamCover(ws, scene_depth > 0.0 ? max(pos.y - scene_pos.y, 0.0) : 1e6);
    Surface s;
    s.albedo = w_foam.rgb * foam;
    s.roughness = glitterRoughness(ws);
    s.normal = facingEye(surfaceNormal(ws, dist), v);
    s.f0 = kWaterF0;
    s.lit = true;
    uint exact;
    o_color = vec4((1.0 - foam) * shadeRange(range, s, pos, v, exact), 0.0);
}
#else
void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec2 uv = (vec2(pixel) + 0.5) * u_viewport.zw;
    float footprint = max(length(dFdx(v_rest)), length(dFdy(v_rest)));
    WaveSample ws = evaluateWaves(v_rest, footprint);
    vec3 pos = v_position;
    float dist = max(length(pos), 1e-4);
    vec3 n = surfaceNormal(ws, dist);
    vec3 v = -pos / dist;
    vec3 l = u_sun_dir.xyz;
    // The sun's visibility through the terrain's cascaded shadows (taken on the still surface's
    // normal: wave normals would only add acne), on the direct sun terms.
    float sun_visible = 1.0;
#ifdef HAS_SUN_SHADOW
    if (l.y > 0.0) sun_visible = sunShadow(pos, vec3(0.0, 1.0, 0.0), l.y, max(-(mat3(u_view) * pos).z, 0.0), gl_FragCoord.xy);
#endif
    vec3 sun = w_sun.rgb * sun_visible;
    vec3 e_down = sun * max(l.y, 0.0) + w_sky_up.rgb;  // irradiance on the still surface
    vec3 sigma = w_absorption.rgb;
    vec3 scatter = w_scatter.rgb * e_down / PI;  // radiance of a deep water column
    bool below = pos.y > 0.0;  // the surface is above the eye: seen from under water

    // The opaque scene behind the surface.
    float scene_depth = texelFetch(u_scene_depth, pixel, 0).r;
    vec3 scene_pos = positionFromDepth(uv, max(scene_depth, 1e-30));
    float thickness = scene_depth > 0.0 ? max(length(scene_pos) - dist, 0.0) : 1e6;
    float column = scene_depth > 0.0 ? max(pos.y - scene_pos.y, 0.0) : 1e6;  // water depth below the surface

    vec3 color;
    float foam = 0.0;
    if (!below) {
        n = facingEye(n, v);
        float nv = clamp(dot(n, v), 0.0, 1.0);
        float fresnel = kWaterF0 + (1.0 - kWaterF0) * pow(1.0 - nv, 5.0);

        // Reflection: screen-space where it finds the scene, the sky elsewhere.
        vec3 r = reflect(-v, n);
        r.y = abs(r.y);  // a ray reflected into the water would meet the surface again
        vec3 reflection = skyRadiance(r);
        // Where the Fresnel factor is near its minimum (looking steeply down) the reflection
        // hardly shows: no ray march there, faded in over a small range (no seam).
        float march = smoothstep(0.03, 0.045, fresnel);
        if (march > 0.0) {
            float hit;
            vec3 traced = traceReflection(pos, r, hit);
            reflection = mix(reflection, traced, hit * march);
        }

        // Refraction: the opaque copy offset by the normal's tilt, more through deeper water;
        // an offset onto something in front of the surface falls back to the pixel itself.
        vec2 shift = n.xz * (w_surface.z * min(thickness, 8.0) / dist) * 0.5 * vec2(u_proj[0][0], u_proj[1][1]);
        vec2 uv_r = clamp(uv + shift, vec2(0.0), vec2(1.0));
        float depth_r = texelFetch(u_scene_depth, texelOf(uv_r), 0).r;
        if (depth_r > gl_FragCoord.z) {
            uv_r = uv;
            depth_r = scene_depth;
        }
        vec3 refr_pos = positionFromDepth(uv_r, max(depth_r, 1e-30));
        float l_view = depth_r > 0.0 ? max(length(refr_pos) - dist, 0.0) : 1e6;
        float l_down = depth_r > 0.0 ? max(pos.y - refr_pos.y, 0.0) : 1e6;
        vec3 t_view = exp(-sigma * min(l_view, 1e4));
        vec3 t_down = exp(-sigma * min(l_down, 1e4));  // light reaching the bottom through the column
        vec3 refracted = texelFetch(u_scene_color, texelOf(uv_r), 0).rgb * t_down * t_view + scatter * (1.0 - t_view);

        color = fresnel * reflection + (1.0 - fresnel) * refracted;

        // Sun glitter.
        float roughness = glitterRoughness(ws);
        color += evalBrdf(vec3(0.0), roughness, kWaterF0, n, l, v) * sun * max(dot(n, l), 0.0);

        foam = foamCover(ws, column);

#ifdef WATER_LOCAL_LIGHTS
        Surface s;
        s.albedo = w_foam.rgb * foam;
        s.roughness = roughness;
        s.normal = n;
        s.f0 = kWaterF0;
        s.lit = true;
        uint evaluated, exact;
        color += forwardLocalLights(s, pos, pixel, u_light_chunk, evaluated, exact);  // the first chunk
#endif
        vec3 foam_light = w_foam.rgb / PI * (sun * max(dot(n, l), 0.0) + mix(w_ground_up.rgb, w_sky_up.rgb, n.y * 0.5 + 0.5));
        color = mix(color, foam_light, foam);
    } else {
        // From below: n faces down towards the eye; Snell's window above, total internal
        // reflection of the water outside it.
        vec3 nb = -n;
        vec3 t = refract(-v, nb, kWaterIor);
        vec3 water = scatter * exp(-sigma * min(pos.y, 1e4));
        if (dot(t, t) < 1e-6) {
            color = water;
        } else {
            float cos_t = clamp(dot(t, n), 0.0, 1.0);
            float fresnel = kWaterF0 + (1.0 - kWaterF0) * pow(1.0 - cos_t, 5.0);
            vec3 behind = scene_depth > 0.0 && scene_pos.y > pos.y ? texelFetch(u_scene_color, pixel, 0).rgb : skyRadiance(t);
            color = (1.0 - fresnel) * behind + fresnel * water;
        }
    }

#if WATER_VIEW == 1
    color = n * 0.5 + 0.5;
#elif WATER_VIEW == 2
    color = vec3(foam);
#elif WATER_VIEW == 3
    color = vec3(clamp(column / 10.0, 0.0, 1.0), clamp(thickness / 10.0, 0.0, 1.0), below ? 1.0 : 0.0);
#endif
    o_color = vec4(clamp(color, vec3(0.0), vec3(60000.0)), 0.0);
}
#endif
#endif
