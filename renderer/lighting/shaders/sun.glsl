// "lighting.sun": the sun and the sky's ambient light on every lit G-buffer pixel, added to
// the HDR target (which already holds emissive radiance). BRDF in brdf.glsl.
#include "../../shaders/fullscreen.glsl"

#ifdef FRAGMENT_SHADER
#include "../../shaders/common.glsl"
#include "../../shaders/gbuffer.glsl"
#include "brdf.glsl"
layout(binding = BINDING_TEX_0) uniform sampler2D u_depth;
layout(binding = BINDING_TEX_1) uniform sampler2D u_albedo;
layout(binding = BINDING_TEX_2) uniform sampler2D u_normal;
#include "sun_block.glsl"
#ifdef HAS_AO
layout(binding = BINDING_TEX_3) uniform sampler2D u_ao;  // ambient occlusion (r), 1 = open
#endif
#ifdef HAS_CLOUD_SHADOW
#include "../../../sky/shaders/sky_bindings.glsl"
layout(binding = SKY_TEX_CLOUD_SHADOW) uniform sampler2D u_cloud_shadow;  // sun transmittance through the clouds
// The map's texel for a point: its projection along the sun onto y = 0 (sky/clouds/shaders/cloud_shadow.glsl);
// towards the map's edge the shadow fades out (no streaks of edge texels beyond it).
float cloudShadow(vec3 pos) {
    vec2 ref = pos.xz - u_sun_dir.xz / u_cloud_shadow_map.w * (u_camera_world.y + pos.y);
    vec2 uv = (ref - u_cloud_shadow_map.xy) * u_cloud_shadow_map.z + 0.5;
    float edge = smoothstep(0.9, 1.0, 2.0 * max(abs(uv.x - 0.5), abs(uv.y - 0.5)));
    return mix(clamp(texture(u_cloud_shadow, uv).r, 0.0, 1.0), 1.0, edge);
}
#endif
#if defined(HAS_SUN_SHADOW) || defined(SHADOW_CASCADE_VIEW)
#include "../../shadows/shaders/shadows.glsl"
#endif
layout(location = 0) out vec4 o_color;

// Hemisphere ambient: irradiance on a surface facing n.
vec3 ambientIrradiance(vec3 n) {
    return mix(u_ground_up, u_sky_up, n.y * 0.5 + 0.5);
}

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    float depth = texelFetch(u_depth, p, 0).r;
    Surface s = decodeSurface(texelFetch(u_albedo, p, 0), texelFetch(u_normal, p, 0));
    if (depth <= 0.0 || !s.lit) discard;
    vec3 pos = positionFromDepth((vec2(p) + 0.5) * u_viewport.zw, depth);
    vec3 v = safeNormalize(-pos);
    vec3 l = u_sun_dir.xyz;
    float ndotl = dot(s.normal, l);
    vec3 color = vec3(0.0);
    if (ndotl > 0.0) {
        float shadow = 1.0;
#ifdef HAS_SUN_SHADOW
        shadow = sunShadow(pos, s.normal, ndotl, linearDepth(depth), gl_FragCoord.xy);
#endif
#ifdef HAS_CLOUD_SHADOW
        shadow *= cloudShadow(pos);
#endif
        color = evalBrdf(s.albedo, s.roughness, s.f0, s.normal, l, v) * u_sun_irradiance * (ndotl * shadow);
    }
    // Ambient: Lambert on the hemisphere irradiance, and a rough specular term from the
    // irradiance around the mirror direction (Fresnel at the view angle, damped by roughness).
    float nv = clamp(dot(s.normal, v), 0.0, 1.0);
    float fr = s.f0 + (1.0 - s.f0) * pow(1.0 - nv, 5.0) * (1.0 - s.roughness);
    vec3 r = reflect(-v, s.normal);
    float ao = 1.0;
#ifdef HAS_AO
    ao = texelFetch(u_ao, p, 0).r;
#endif
    color += ao * ((1.0 - fr) * s.albedo / PI * ambientIrradiance(s.normal) + fr / PI * ambientIrradiance(r));
#ifdef SHADOW_CASCADE_VIEW
    color *= cascadeColor(linearDepth(depth));  // [debug] view = cascades
#endif
#ifdef SHADOW_TERM_VIEW
    // [debug] view = shadow: the sun's visibility alone (0 where the surface faces away).
    float term = 0.0;
#ifdef HAS_SUN_SHADOW
    if (ndotl > 0.0) term = sunShadow(pos, s.normal, ndotl, linearDepth(depth), gl_FragCoord.xy);
#else
    term = ndotl > 0.0 ? 1.0 : 0.0;
#endif
    color = vec3(term);
#endif
    o_color = vec4(color, 0.0);
}
#endif
