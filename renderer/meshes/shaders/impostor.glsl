// "objects.gbuffer", impostors: one camera-facing card per instance beyond the impostor
// distance, showing the baked frame (renderer/meshes/impostor.h) nearest the direction the
// instance is seen from, turned with the instance's yaw. The atlas holds the G-buffer's own
// encodings over a cleared (zero) background, so a filtered texel divided by its coverage
// (the normal's w) is the covered texels' mean: no dark fringe at the mips. Within the fade band
// the card keeps the pixels the mesh drops (object_common.glsl impostorFade).
#include "../../../renderer/shaders/common.glsl"
#include "../../../renderer/shaders/gbuffer.glsl"
#include "object_common.glsl"

layout(std430, binding = BINDING_OBJECT_INSTANCES) readonly buffer Instances { ObjectInstance u_instances[]; };
layout(std430, binding = BINDING_OBJECT_VISIBLE) readonly buffer Visible { uint u_visible[]; };

#include "impostor_block.glsl"

#ifdef VERTEX_SHADER
layout(location = 0) in vec3 a_position;  // the card corner in (right, up), -1..1
layout(location = 3) in vec2 a_uv;        // 0..1 within the frame
out vec2 v_uv;
flat out float v_fade;
flat out vec2 v_yaw;  // cos, sin

void main() {
    ObjectInstance inst = u_instances[u_visible[u_region + uint(gl_InstanceID)]];
    vec3 centre = inst.position_yaw.xyz - u_camera + objectTransform(inst, u_sphere.xyz);
    // The frame nearest the view direction, in the model's own frame.
    float n1 = u_params.z - 1.0;
    vec2 cell = clamp(round((hemiOctEncode(objectInverseRotate(inst, -centre)) * 0.5 + 0.5) * n1), 0.0, n1);
    vec3 right, up;
    impostorBasis(hemiOctDecode(cell / n1 * 2.0 - 1.0), right, up);
    ObjectInstance unit = inst;
    unit.params.x = 1.0;
    float r = u_sphere.w * inst.params.x;
    vec3 p = centre + (objectTransform(unit, right) * a_position.x + objectTransform(unit, up) * a_position.y) * r;
    v_uv = (cell + a_uv) / u_params.z;
    v_fade = impostorFade(length(centre), u_params.xy);
    v_yaw = vec2(cos(inst.position_yaw.w), sin(inst.position_yaw.w));
    gl_Position = u_matrix * vec4(p, 1.0);
}
#endif

#ifdef FRAGMENT_SHADER
layout(binding = BINDING_TEX_0) uniform sampler2D t_emissive;
layout(binding = BINDING_TEX_1) uniform sampler2D t_albedo;
layout(binding = BINDING_TEX_2) uniform sampler2D t_normal;
in vec2 v_uv;
flat in float v_fade;
flat in vec2 v_yaw;
layout(location = 0) out vec4 o_color;  // emissive radiance
layout(location = 1) out vec4 o_albedo;
layout(location = 2) out vec4 o_normal;

void main() {
    vec4 n = texture(t_normal, v_uv);
    if (n.w < 0.5 || impostorFadeNoise(gl_FragCoord.xy) >= v_fade) discard;
    float inv = 1.0 / n.w;
    vec4 a = texture(t_albedo, v_uv) * inv;
    Surface s;
    s.albedo = a.rgb * a.rgb;
    s.roughness = a.a;
    vec3 m = decodeNormal(n.xy * inv);  // model space
    s.normal = vec3(v_yaw.x * m.x + v_yaw.y * m.z, m.y, -v_yaw.y * m.x + v_yaw.x * m.z);
    s.f0 = n.z * inv * 0.16;
    s.lit = true;
    encodeSurface(s, o_albedo, o_normal);
    o_color = vec4(texture(t_emissive, v_uv).rgb * inv * u_params.w, 1.0);
}
#endif
