// "postfx.lens_flare.visibility": the share of 16 depth samples (a 4x4 grid spanning +-radius
// around the sun, postfx/lens_flare.cpp flareSampleOffset) that see the sky (reversed-Z depth 0);
// samples off the image are left out. The visibility follows it by exp(-dt * rate), so the
// flare fades smoothly as the sun sinks behind a ridge.
#ifdef COMPUTE_SHADER
#include "postfx_bindings.glsl"
#include "../../renderer/shaders/bindings.glsl"
layout(local_size_x = 1) in;
layout(binding = BINDING_TEX_0) uniform sampler2D u_depth;
layout(std430, binding = POSTFX_BINDING_FLARE_VISIBILITY) buffer FlareVisibility {
    float visibility;
    float target;
    float valid;
    float pad;
};
#include "lens_flare_block.glsl"

void main() {
    ivec2 size = textureSize(u_depth, 0);
    vec2 centre = u_sun_uv * vec2(size);
    float sky = 0.0, counted = 0.0;
    for (int i = 0; i < 16; ++i) {
        vec2 offset = (vec2(float(i % 4), float(i / 4)) - 1.5) / 1.5;
        ivec2 p = ivec2(floor(centre + offset * u_radius_px));
        if (any(lessThan(p, ivec2(0))) || any(greaterThanEqual(p, size))) continue;
        float d = texelFetch(u_depth, p, 0).r;
        counted += 1.0;
        sky += d == 0.0 ? 1.0 : 0.0;
    }
    float measured = counted > 0.0 ? sky / counted : 0.0;
    bool first = u_reset > 0.5 || valid < 0.5 || isnan(visibility);
    visibility = first ? measured : measured + (visibility - measured) * exp(-max(u_dt, 0.0) * u_rate);
    target = measured;
    valid = 1.0;
}
#endif
