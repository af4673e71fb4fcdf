// "temporal.velocity": each pixel's depth reprojected into the previous frame (u_reproject:
// this frame's unjittered clip -> the previous frame's clip, built in double on the CPU;
// renderer/velocity.h describes the target). The pixel's unjittered NDC is its centre less
// this frame's jitter, so TAA finds the (unjittered) history at uv - velocity.
#include "fullscreen.glsl"

#ifdef FRAGMENT_SHADER
#include "bindings.glsl"
layout(binding = BINDING_TEX_0) uniform sampler2D u_depth;
#include "velocity_block.glsl"
layout(location = 0) out vec4 o_velocity;

void main() {
    vec2 size = vec2(textureSize(u_depth, 0));
    float d = texelFetch(u_depth, ivec2(gl_FragCoord.xy), 0).r;
    d = (d > 0.0 && !isnan(d)) ? min(d, 1.0) : 0.0;
    vec2 ndc = gl_FragCoord.xy / size * 2.0 - 1.0 - u_jitter.xy;
    vec4 prev = u_reproject * vec4(ndc, d, 1.0);
    o_velocity = vec4(0.0);
    if (prev.w > 1e-6) {
        vec2 v = (ndc - prev.xy / prev.w) * 0.5;
        if (!any(isnan(v)) && !any(isinf(v))) o_velocity = vec4(v, prev.z / prev.w, 1.0);
    }
}
#endif
