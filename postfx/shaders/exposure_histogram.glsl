// "postfx.exposure.histogram": counts 2x2 pixel blocks per log2-luminance bin. Bin 0 holds black (below
// 2^EXPOSURE_LOG_MIN); bins 1..EXPOSURE_BINS-1 split [EXPOSURE_LOG_MIN, EXPOSURE_LOG_MAX]
// evenly. NaN and Inf pixels are not counted. Each workgroup counts in shared memory first.
#ifdef COMPUTE_SHADER
#include "../../renderer/shaders/bindings.glsl"
#include "postfx_bindings.glsl"
layout(local_size_x = EXPOSURE_GROUP, local_size_y = EXPOSURE_GROUP) in;
layout(binding = BINDING_TEX_0) uniform sampler2D u_image;
layout(std430, binding = POSTFX_BINDING_HISTOGRAM) buffer Histogram {
    uint bins[EXPOSURE_BINS];
};
shared uint s_bins[EXPOSURE_BINS];

void main() {
    // EXPOSURE_GROUP^2 == EXPOSURE_BINS: one bin per invocation to clear and flush.
    uint i = gl_LocalInvocationIndex;
    s_bins[i] = 0u;
    barrier();
    // One invocation per 2x2 block: a bilinear tap at its centre meters a quarter of the
    // fetches (an odd last row or column is clamped into the image).
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = textureSize(u_image, 0);
    if (all(lessThan(p, (size + 1) / 2))) {
        vec2 centre = min(vec2(p * 2 + 1), vec2(size) - 0.5);
        vec3 c = textureLod(u_image, centre / vec2(size), 0.0).rgb;
        float l = dot(max(c, vec3(0.0)), vec3(0.2126, 0.7152, 0.0722));
        if (!isnan(l) && !isinf(l)) {
            float t = (log2(max(l, 1e-38)) - EXPOSURE_LOG_MIN) / (EXPOSURE_LOG_MAX - EXPOSURE_LOG_MIN);
            uint bin = t < 0.0 ? 0u : 1u + uint(min(t, 1.0) * float(EXPOSURE_BINS - 2) + 0.5);
            atomicAdd(s_bins[min(bin, uint(EXPOSURE_BINS - 1))], 1u);
        }
    }
    barrier();
    if (s_bins[i] != 0u) atomicAdd(bins[i], s_bins[i]);
}
#endif
