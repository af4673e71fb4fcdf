// "sky.aerial": aerial perspective on every pixel at finite depth. The pixel's distance comes
// from the depth buffer; the froxel volume (aerial_volume.glsl) is read with trilinear
// interpolation (bilinear across the screen inside a slice, linear in distance between slice
// ends, from (0, 1) at the camera) and applied by dual-source blending:
// hdr = hdr * transmittance + in-scattering. Pixels at infinite depth (the sky) are left alone.
// A camera above the atmosphere has no volume: each pixel marches its own ray through the air.
#include "../../renderer/shaders/fullscreen.glsl"

#ifdef FRAGMENT_SHADER
#include "../../renderer/shaders/common.glsl"
#include "../../renderer/shaders/gbuffer.glsl"
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

// Bilinear inside slice k's tile, never across tiles: the filtered coordinate stays between the
// tile's first and last texel centres.
void fetchSlice(int k, vec2 uv, out vec3 inscatter, out vec3 transmittance) {
    float size = a_aerial.y;
    vec2 f = clamp(uv * (size - 1.0), vec2(0.0), vec2(size - 1.0)) + 0.5;
    vec2 atlas_uv = vec2((float(k) * size + f.x) / (size * a_aerial.z), f.y / size);
    inscatter = texture(u_inscatter, atlas_uv).rgb;
    transmittance = texture(u_aerial_transmittance, atlas_uv).rgb;
}

void main() {
    float depth = texelFetch(u_depth, ivec2(gl_FragCoord.xy), 0).r;
    if (!(depth > 0.0)) discard;
    vec3 position = positionFromDepth(v_uv, depth);
    float t = length(position) * 1e-3;  // km
    vec3 dir = position * (1e-3 / max(t, 1e-9));
    if (a_radii.z > topR()) {
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
        return;
    }
    int slices = int(a_aerial.z);
    // Slice k ends at range ((k + 1) / slices)^2; "slice -1" is the camera itself.
    float s = clamp(sqrt(max(t / a_aerial.x, 0.0)) * float(slices) - 1.0, -1.0, float(slices - 1));
    int k1 = clamp(int(ceil(s)), 0, slices - 1), k0 = k1 - 1;
    float x0 = float(k0 + 1) / float(slices), x1 = float(k1 + 1) / float(slices);
    float t0 = a_aerial.x * x0 * x0, t1 = a_aerial.x * x1 * x1;
    float w = clamp((t - t0) / max(t1 - t0, 1e-9), 0.0, 1.0);
    vec3 s0 = vec3(0.0), tr0 = vec3(1.0), s1, tr1;
    if (k0 >= 0) fetchSlice(k0, v_uv, s0, tr0);
    fetchSlice(k1, v_uv, s1, tr1);
    vec3 inscatter = skyRgb(mix(s0, s1, w));
    vec3 transmittance = mix(tr0, tr1, w);
    o_inscatter = vec4(clamp(inscatter, vec3(0.0), vec3(60000.0)), 0.0);
    o_transmittance = vec4(clamp(transmittance, vec3(0.0), vec3(1.0)), 1.0);
}
#endif
