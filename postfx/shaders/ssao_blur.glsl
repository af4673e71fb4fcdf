// "postfx.ssao.blur": full-size ambient visibility from the (half- or full-size) raw AO:
// a 3x3 (or, with the blur off, 1x1) gather weighted by a 1 2 1 tent and by depth similarity,
// exp(-|z_sample - z| / (z * tolerance)), so occlusion does not bleed across silhouettes and
// a half-size result upsamples along edges.
#include "../../renderer/shaders/fullscreen.glsl"

#ifdef FRAGMENT_SHADER
#include "../../renderer/shaders/common.glsl"
layout(binding = BINDING_TEX_0) uniform sampler2D u_ao;     // r visibility, g view distance
layout(binding = BINDING_TEX_1) uniform sampler2D u_depth;  // full size
#include "ssao_blur_block.glsl"
layout(location = 0) out vec4 o_ao;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    float depth = texelFetch(u_depth, p, 0).r;
    if (depth <= 0.0) {
        o_ao = vec4(1.0);
        return;
    }
    float z = linearDepth(depth);
    ivec2 size = textureSize(u_ao, 0);
    ivec2 q = min(p / int(u_blur.z), size - 1);
    int r = int(u_blur.y);
    float sum = 0.0, weight = 0.0;
    for (int dy = -r; dy <= r; ++dy) {
        for (int dx = -r; dx <= r; ++dx) {
            vec2 s = texelFetch(u_ao, clamp(q + ivec2(dx, dy), ivec2(0), size - 1), 0).rg;
            float w = (2.0 - float(abs(dx))) * (2.0 - float(abs(dy))) * exp(-abs(s.g - z) / (z * u_blur.x));
            sum += s.r * w;
            weight += w;
        }
    }
    float ao = weight > 1e-6 ? sum / weight : texelFetch(u_ao, q, 0).r;
    o_ao = vec4(ao, 0.0, 0.0, 1.0);
}
#endif
