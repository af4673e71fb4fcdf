// Depth debug view: log2 of the view distance mapped to grey, infinity (sky) dark blue.
#include "fullscreen.glsl"

#ifdef FRAGMENT_SHADER
#include "common.glsl"
layout(binding = BINDING_TEX_0) uniform sampler2D u_depth;
layout(location = 0) out vec4 o_color;
void main() {
    float depth = texelFetch(u_depth, ivec2(gl_FragCoord.xy), 0).r;
    if (depth <= 0.0) {
        o_color = vec4(0.05, 0.07, 0.15, 1.0);
        return;
    }
    // 1 m .. 64 km spread over the grey ramp.
    float t = clamp(log2(max(linearDepth(depth), 1e-3)) / 16.0, 0.0, 1.0);
    o_color = vec4(vec3(1.0 - t), 1.0);
}
#endif
