// Counts NaN and Inf pixels of an HDR image into a counter (robustness check: must be 0).
#ifdef COMPUTE_SHADER
#include "bindings.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = BINDING_TEX_0) uniform sampler2D u_image;
layout(std430, binding = BINDING_COUNTERS) buffer Counters { uint u_nonfinite; };
void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, textureSize(u_image, 0)))) return;
    vec4 c = texelFetch(u_image, p, 0);
    if (any(isnan(c)) || any(isinf(c))) atomicAdd(u_nonfinite, 1u);
}
#endif
