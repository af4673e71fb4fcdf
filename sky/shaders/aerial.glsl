// "sky.aerial": aerial perspective on every pixel at finite depth. The pixel's distance comes
// from the depth buffer; the froxel volume (aerial_volume.glsl) is read with trilinear
// interpolation (renderer/shaders/aerial_fetch.glsl, as the glass drawn after this pass reads it)
// and applied by dual-source blending:
// hdr = hdr * transmittance + in-scattering. Pixels at infinite depth (the sky) are left alone.
// A camera above the atmosphere has no volume: each pixel marches its own ray through the air
// (variant AERIAL_FROM_SPACE: a shader core would run the march's branch for every pixel).
#include "../../renderer/shaders/fullscreen.glsl"

#ifdef FRAGMENT_SHADER
#include "../../renderer/shaders/common.glsl"
#include "../../renderer/shaders/gbuffer.glsl"
#include "../../renderer/shaders/aerial_fetch.glsl"
#define SKY_TEX_TRANSMITTANCE BINDING_TEX_3
#define SKY_TEX_MULTISCATTER BINDING_TEX_4
#define SKY_TRANSMITTANCE_LUT
#define SKY_MULTISCATTER_LUT
#define SKY_FOG
#include "atmosphere.glsl"
layout(binding = BINDING_TEX_0) uniform sampler2D u_depth;
layout(binding = BINDING_TEX_1) uniform sampler2D u_inscatter;
layout(binding = BINDING_TEX_2) uniform sampler2D u_aerial_transmittance;
in vec2 v_uv;
layout(location = 0, index = 0) out vec4 o_inscatter;
layout(location = 0, index = 1) out vec4 o_transmittance;

void main() {
    float depth = texelFetch(u_depth, ivec2(gl_FragCoord.xy), 0).r;
    if (!(depth > 0.0)) discard;
    vec3 position = positionFromDepth(v_uv, depth);
    float t = length(position) * 1e-3;  // km
    vec3 dir = position * (1e-3 / max(t, 1e-9));
#ifdef AERIAL_FROM_SPACE
    {
        // From space (no volume): march this pixel's ray from where it enters the atmosphere,
        // its samples gathered towards the lower end, where the air is.
        float r = a_radii.z, mu = clamp(dir.y, -1.0, 1.0);
        float t_start = atmosphereEntry(r, mu);
        if (t_start < 0.0 || t <= t_start) discard;
        vec3 entry = vec3(0.0, r, 0.0) + t_start * dir;
        float r0 = length(entry);
        RaySums sums = integrateRay(r0, clamp(dot(entry, dir) / r0, -1.0, 1.0), clamp(dot(entry, a_sun.xyz) / r0, -1.0, 1.0),
                                    clamp(dot(dir, a_sun.xyz), -1.0, 1.0), t - t_start, a_sizes2.w, 0);
        o_inscatter = vec4(clamp(skyRgb(sums.radiance), vec3(0.0), vec3(60000.0)), 0.0);
        o_transmittance = vec4(clamp(sums.transmittance, vec3(0.0), vec3(1.0)), 1.0);
    }
#else
    vec3 inscatter, transmittance;
    aerialFetch(u_inscatter, u_aerial_transmittance, a_aerial, v_uv, t, inscatter, transmittance);
    o_inscatter = vec4(inscatter, 0.0);
    o_transmittance = vec4(transmittance, 1.0);
#endif
}
#endif
