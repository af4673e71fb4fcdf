// "postfx.dof.focus": autofocus. The median of 5 depth samples (the centre and 4 at 5% of the
// image height around it) is the target, in diopters (1 / distance: with reversed-Z and an
// infinite far plane that is depth / near, so the sky is 0 and needs no special case). The
// focus moves towards it exponentially in time, exp(-dt * rate): frame-rate independent, and
// a median ignores a single odd sample, so the focus does not flicker.
#ifdef COMPUTE_SHADER
#include "postfx_bindings.glsl"
#include "../../renderer/shaders/bindings.glsl"
layout(local_size_x = 1) in;
layout(binding = BINDING_TEX_0) uniform sampler2D u_depth;
layout(std430, binding = POSTFX_BINDING_DOF_FOCUS) buffer DofFocus {
    float diopters;
    float target;
    float valid;
    float pad;
};
#include "dof_block.glsl"

float sampleDiopters(ivec2 p, ivec2 size) {
    float d = texelFetch(u_depth, clamp(p, ivec2(0), size - 1), 0).r;
    d = (d > 0.0 && !isnan(d)) ? min(d, 1.0) : 0.0;  // NaN and negative: infinitely far
    return clamp(d / u_near_m, 0.0, u_max_diopters);
}

void main() {
    ivec2 size = textureSize(u_depth, 0);
    ivec2 c = size / 2;
    int r = max(1, size.y / 20);
    float v[5] = float[5](sampleDiopters(c, size), sampleDiopters(c + ivec2(r, 0), size),
                          sampleDiopters(c - ivec2(r, 0), size), sampleDiopters(c + ivec2(0, r), size),
                          sampleDiopters(c - ivec2(0, r), size));
    for (int i = 1; i < 5; ++i)  // insertion sort: five values
        for (int j = i; j > 0 && v[j - 1] > v[j]; --j) {
            float t = v[j];
            v[j] = v[j - 1];
            v[j - 1] = t;
        }
    float measured = v[2];
    bool first = u_reset > 0.5 || valid < 0.5 || isnan(diopters) || isinf(diopters);
    float keep = exp(-max(u_dt, 0.0) * u_rate);
    diopters = first ? measured : measured + (diopters - measured) * keep;
    target = measured;
    valid = 1.0;
}
#endif
