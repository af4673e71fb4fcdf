// "objects.gbuffer": instanced glTF meshes into the G-buffer. Instance k of a draw is
// u_instances[u_visible[u_region + k]] (objects.cull filled the region). Metallic-roughness
// materials map onto the G-buffer's dielectric encoding: albedo = base x (1 - metallic), F0 from
// 0.04 toward the encoding's 0.16 with metallic; occlusion darkens the albedo (the G-buffer has
// no AO channel; SSAO adds the rest). Emissive (x [objects] emissive_nits) goes into the HDR
// target, which the lighting adds to. Missing textures are 1 x 1 defaults (white, flat normal),
// so there is no branch per texture. ALPHA_MASK: alpha below the cutoff is discarded (foliage;
// BLEND materials too, at their cutoff, until the forward pass exists). SHADOW_PASS: depth only
// into a shadow view (with the alpha test when ALPHA_MASK). IMPOSTOR_FADE: the draws of LODs
// that reach into the fade band before the impostor distance drop the pixels the impostor draws
// (object_common.glsl impostorFade); a variant, so the other draws pay nothing. FORWARD: BLEND
// materials in "objects.transparent", sorted back to front on the CPU: lit here by the sun, the
// hemisphere ambient and the local lights' forward lists (LIGHTS_NAIVE, _TILED, _CLUSTERED or
// _HASHED, as the sea), written premultiplied (blend ONE, ONE_MINUS_SRC_ALPHA); u_light_chunk is
// the part of each light range it shades. FORWARD + LIGHT_CHUNK: a further chunk of the local
// lights only, alpha 0, drawn right after the item with depth test EQUAL (objects_forward.cpp);
// gl_Position is invariant in the FORWARD variants so the two draws' depths are equal. FORWARD
// writes gl_ClipDistance[0] = dot(u_clip, (p, 1)) (the pass enables it only with the sea: the
// water plane splits the glass drawn before and after the sea). FORWARD + HAS_SUN_SHADOW: the
// sun's cascades shadow the glass as they shadow the G-buffer; FORWARD + HAS_SPOT_SHADOWS /
// HAS_POINT_SHADOWS (with a lights method): the local lights' spot atlas and point cubes shadow it
// as they shadow lights.shade (lights.glsl). FORWARD + AERIAL_FOG: the pass comes after
// "sky.aerial", and the surface fogs itself at its own distance from the aerial-perspective volume
// (renderer/aerial_volume.h): out = (T C + a L, a) for its premultiplied light C and coverage a,
// T and L the volume's transmittance and in-scattering there; blended over the fogged scene this
// is T (C + (1 - a) B) + L, exact for one pane over a background B fogged to its own depth.
#include "../../../renderer/shaders/common.glsl"
#include "../../../renderer/shaders/gbuffer.glsl"
#include "object_common.glsl"

layout(std430, binding = BINDING_OBJECT_INSTANCES) readonly buffer Instances { ObjectInstance u_instances[]; };
layout(std430, binding = BINDING_OBJECT_VISIBLE) readonly buffer Visible { uint u_visible[]; };

#include "object_block.glsl"

#ifdef VERTEX_SHADER
#ifdef FORWARD
invariant gl_Position;
#endif
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec4 a_tangent;
layout(location = 3) in vec2 a_uv;
out vec2 v_uv;
#ifndef SHADOW_PASS
out vec3 v_normal;
out vec4 v_tangent;
out vec3 v_position;  // camera-relative
#endif
#ifdef IMPOSTOR_FADE
flat out float v_fade;
#endif

void main() {
    ObjectInstance inst = u_instances[u_visible[u_region + uint(gl_InstanceID)]];
    vec3 p = inst.position_yaw.xyz - u_camera + objectTransform(inst, a_position);
    v_uv = a_uv;
#ifndef SHADOW_PASS
    // Uniform scale: the rotation alone turns normals and tangents.
    ObjectInstance unit = inst;
    unit.params.x = 1.0;
    v_normal = objectTransform(unit, a_normal);
    v_tangent = vec4(objectTransform(unit, a_tangent.xyz), a_tangent.w);
    v_position = p;
#endif
#ifdef IMPOSTOR_FADE
    vec3 centre = inst.position_yaw.xyz - u_camera + objectTransform(inst, vec3(u_fade.zw, u_fade_centre_z));
    v_fade = impostorFade(length(centre), u_fade.xy);
#endif
    gl_Position = u_matrix * vec4(p, 1.0);
#ifdef FORWARD
    gl_ClipDistance[0] = dot(u_clip, vec4(p, 1.0));
#endif
}
#endif

#ifdef FRAGMENT_SHADER
#include "../../../renderer/lighting/shaders/brdf.glsl"
// Shared by lights.glsl; included first and unconditionally because each file is expanded once,
// before the GLSL preprocessor sees the #ifs around them (as water_surface.glsl does).
#include "../../../renderer/shadows/shaders/shadow_filter.glsl"
#if defined(FORWARD) && (defined(LIGHTS_NAIVE) || defined(LIGHTS_TILED) || defined(LIGHTS_CLUSTERED) || defined(LIGHTS_HASHED))
#define OBJECT_LOCAL_LIGHTS
#include "../../../renderer/lighting/shaders/lights.glsl"
#endif
#if defined(FORWARD) && defined(HAS_SUN_SHADOW)
#include "../../../renderer/shadows/shaders/shadows.glsl"
#endif
#include "../../../renderer/shaders/aerial_fetch.glsl"
#if defined(FORWARD) && defined(AERIAL_FOG)
layout(binding = BINDING_AERIAL_INSCATTER) uniform sampler2D t_aerial_inscatter;
layout(binding = BINDING_AERIAL_TRANSMITTANCE) uniform sampler2D t_aerial_transmittance;
// The air between the eye and this fragment: in-scattering (HDR) and transmittance.
void fragmentFog(vec3 position, out vec3 inscatter, out vec3 transmittance) {
    aerialFetch(t_aerial_inscatter, t_aerial_transmittance, u_aerial, gl_FragCoord.xy * u_viewport.zw,
                length(position) * 1e-3, inscatter, transmittance);
}
#endif
layout(binding = BINDING_TEX_0) uniform sampler2D t_base_color;
in vec2 v_uv;

#ifdef SHADOW_PASS
void main() {
#ifdef ALPHA_MASK
    if (u_base_color.a * texture(t_base_color, v_uv).a < u_emissive.w) discard;
#endif
}
#else
layout(binding = BINDING_TEX_1) uniform sampler2D t_metallic_roughness;
layout(binding = BINDING_TEX_2) uniform sampler2D t_normal;
layout(binding = BINDING_TEX_3) uniform sampler2D t_occlusion;
layout(binding = BINDING_TEX_4) uniform sampler2D t_emissive;
in vec3 v_normal;
in vec4 v_tangent;
in vec3 v_position;
#ifdef IMPOSTOR_FADE
flat in float v_fade;
#endif
#ifdef FORWARD
layout(location = 0) out vec4 o_color;  // premultiplied radiance, coverage
#else
layout(location = 0) out vec4 o_color;  // emissive radiance
layout(location = 1) out vec4 o_albedo;
layout(location = 2) out vec4 o_normal;
#endif

void main() {
#ifdef IMPOSTOR_FADE
    if (impostorFadeNoise(gl_FragCoord.xy) < v_fade) discard;
#endif
#ifdef LIGHT_CHUNK
    // Screen derivatives (the tangent frame below) are taken before any fragment is discarded.
    vec3 dp1 = dFdx(v_position), dp2 = dFdy(v_position);
    vec2 du1 = dFdx(v_uv), du2 = dFdy(v_uv);
    LightRange range = forwardRange(v_position, ivec2(gl_FragCoord.xy), u_light_chunk);
    if (range.count == 0u) discard;  // nothing in this chunk
#endif
    vec4 base = u_base_color * texture(t_base_color, v_uv);
#ifdef ALPHA_MASK
    if (base.a < u_emissive.w) discard;
#endif
    vec3 n = safeNormalize(gl_FrontFacing ? v_normal : -v_normal);
#if defined(FORWARD) && defined(HAS_SUN_SHADOW) && !defined(LIGHT_CHUNK)
    // The sun's visibility at the surface itself (its face normal offsets the lookup).
    float sun_visible = 1.0;
    if (dot(n, u_sun_dir.xyz) > 0.0)
        sun_visible = sunShadow(v_position, n, dot(n, u_sun_dir.xyz), max(-(mat3(u_view) * v_position).z, 0.0), gl_FragCoord.xy);
#else
    const float sun_visible = 1.0;
#endif
    // Tangent frame: the vertex tangent, or one from screen derivatives where the mesh has none.
    vec3 t = v_tangent.xyz;
    float handed = v_tangent.w;
    if (handed == 0.0) {
#ifndef LIGHT_CHUNK
        vec3 dp1 = dFdx(v_position), dp2 = dFdy(v_position);
        vec2 du1 = dFdx(v_uv), du2 = dFdy(v_uv);
#endif
        t = dp1 * du2.y - dp2 * du1.y;
        handed = (du1.x * du2.y - du2.x * du1.y) < 0.0 ? -1.0 : 1.0;
    }
    t = safeNormalize(t - n * dot(n, t));
    vec3 b = cross(n, t) * handed;
    vec3 tn = texture(t_normal, v_uv).xyz * 2.0 - 1.0;
    tn.xy *= u_material.z;
    n = safeNormalize(t * tn.x + b * tn.y + n * tn.z);

    vec4 mr = texture(t_metallic_roughness, v_uv);
    float metallic = clamp(u_material.x * mr.b, 0.0, 1.0);
    float roughness = clamp(u_material.y * mr.g, 0.04, 1.0);
    float occlusion = mix(1.0, texture(t_occlusion, v_uv).r, u_material.w);
    Surface s;
    s.albedo = base.rgb * (1.0 - metallic) * occlusion;
    s.roughness = roughness;
    s.normal = n;
    s.f0 = mix(0.04, 0.16, metallic);
    s.lit = true;
    vec3 emissive = u_emissive.rgb * texture(t_emissive, v_uv).rgb;
#ifdef FORWARD
    // Premultiplied: the diffuse part scales with coverage, reflections do not (glass).
    float alpha = clamp(base.a, 0.0, 1.0);
    s.albedo *= alpha;
    vec3 v = safeNormalize(-v_position);
#ifdef LIGHT_CHUNK
    uint exact;
    o_color = vec4(shadeRange(range, s, v_position, v, exact), 0.0);
#ifdef AERIAL_FOG
    vec3 fog_in, fog_t;
    fragmentFog(v_position, fog_in, fog_t);
    o_color.rgb *= fog_t;  // added light: dimmed by the air in front, no in-scattering of its own
#endif
#else
    vec3 l = u_sun_dir.xyz;
    vec3 color = evalBrdf(s.albedo, s.roughness, s.f0, n, l, v) * u_sun_irradiance * (sun_visible * max(dot(n, l), 0.0));
    float nv = clamp(dot(n, v), 0.0, 1.0);
    float fr = s.f0 + (1.0 - s.f0) * pow(1.0 - nv, 5.0) * (1.0 - s.roughness);
    vec3 r = reflect(-v, n);
    color += (1.0 - fr) * s.albedo / PI * mix(u_ground_up, u_sky_up, n.y * 0.5 + 0.5) +
             fr / PI * mix(u_ground_up, u_sky_up, r.y * 0.5 + 0.5);
#ifdef OBJECT_LOCAL_LIGHTS
    uint evaluated, exact;
    color += forwardLocalLights(s, v_position, ivec2(gl_FragCoord.xy), u_light_chunk, evaluated, exact);
#endif
    o_color = vec4(color + emissive, alpha);
#ifdef AERIAL_FOG
    vec3 fog_in, fog_t;
    fragmentFog(v_position, fog_in, fog_t);
    o_color.rgb = fog_t * o_color.rgb + alpha * fog_in;
#endif
#endif
#else
    encodeSurface(s, o_albedo, o_normal);
    o_color = vec4(emissive, 1.0);
#endif
}
#endif
#endif
