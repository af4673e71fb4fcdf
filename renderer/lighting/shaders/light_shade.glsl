// "lights.shade": every lit G-buffer pixel shades the local lights its culling method gives it
// (LIGHTS_NAIVE: all; LIGHTS_TILED / LIGHTS_CLUSTERED: its tile's or cluster's list; LIGHTS_HASHED:
// the hashed octree's list for its world position), added to the HDR target.
// Ranges are shaded in chunks, one additive draw per chunk (u_light_chunk, lights.glsl chunkOf,
// LocalLights::chunks()): llvmpipe ends a shader invocation's loops after 65,535 iterations in
// all (gallivm's LP_MAX_TGSI_LOOP_ITERATIONS), which silently dropped every light past the
// 65,535th (issue 19, defect 6). Tiled and clustered lists (at most 4,096) fit the first draw.
// COUNT_LIGHTS adds the counters lights.evaluations (lights shaded) and lights.exact (of them,
// those that reach the pixel); LIGHT_HEAT writes the evaluations per pixel for the debug view.
#include "../../shaders/fullscreen.glsl"

#ifdef FRAGMENT_SHADER
#include "../../shaders/common.glsl"
#include "../../shaders/counters.glsl"
#include "../../shaders/gbuffer.glsl"
#include "brdf.glsl"
#include "lights.glsl"

layout(binding = BINDING_TEX_0) uniform sampler2D u_depth;
layout(binding = BINDING_TEX_1) uniform sampler2D u_albedo;
layout(binding = BINDING_TEX_2) uniform sampler2D u_normal;
#ifdef COUNT_LIGHTS
layout(std430, binding = BINDING_COUNTERS) buffer Evaluations { uint u_eval_lo, u_eval_hi; };
layout(std430, binding = BINDING_AUX) buffer Exact { uint u_exact_lo, u_exact_hi; };
#endif
layout(location = 0) out vec4 o_color;
#include "light_shade_block.glsl"
#ifdef LIGHT_HEAT
layout(location = 1) out float o_heat;
#endif

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
#ifdef LIGHT_HEAT
    o_heat = 0.0;
#endif
    float depth = texelFetch(u_depth, p, 0).r;
    Surface s = decodeSurface(texelFetch(u_albedo, p, 0), texelFetch(u_normal, p, 0));
    if (depth <= 0.0 || !s.lit) {
        o_color = vec4(0.0);
        return;
    }
    vec3 position = positionFromDepth((vec2(p) + 0.5) * u_viewport.zw, depth);
    vec3 v = safeNormalize(-position);
    LightRange range = methodRange(p, position, linearDepth(depth));
#ifdef LIGHT_HEAT
    o_heat = float(range.count);
#endif
    range = chunkOf(range, u_light_chunk);
    if (range.count == 0u) {  // nothing in this draw's chunk
        o_color = vec4(0.0);
        return;
    }
    uint exact;
    vec3 color = shadeRange(range, s, position, v, exact);
#ifdef COUNT_LIGHTS
    ADD_COUNTER64(u_eval_lo, u_eval_hi, range.count);
    ADD_COUNTER64(u_exact_lo, u_exact_hi, exact);
#endif
    o_color = vec4(color, 0.0);
}
#endif
