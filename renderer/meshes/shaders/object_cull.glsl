// "objects.cull": one thread per instance. An instance whose bounding sphere is inside the view
// frustum and within max distance goes into its model's list for the LOD its distance picks; one
// within the shadow distance also into the model's shadow list (no frustum test: casters off
// screen still shade it). FIXUP_DRAWS: a second dispatch, one thread per indirect command, copies
// its group's count into the command's instance count (the group is in its baseInstance field,
// which the draws do not use).
#ifdef COMPUTE_SHADER
#include "../../../renderer/shaders/common.glsl"
#include "../../../renderer/shaders/counters.glsl"
#include "object_common.glsl"

layout(local_size_x = 64) in;

layout(std430, binding = BINDING_OBJECT_COUNTS) buffer Counts { uint u_counts[]; };

#ifdef FIXUP_DRAWS
struct DrawCommand {
    uint count, instance_count, first_index;
    int base_vertex;
    uint base_instance;
};
layout(std430, binding = BINDING_OBJECT_DRAWS) buffer Draws { DrawCommand u_draws[]; };
layout(location = 0) uniform uint u_draw_count;
void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= u_draw_count) return;
    u_draws[i].instance_count = u_counts[u_draws[i].base_instance];
}
#else
layout(std430, binding = BINDING_OBJECT_INSTANCES) readonly buffer Instances { ObjectInstance u_instances[]; };
layout(std430, binding = BINDING_OBJECT_MODELS) readonly buffer Models { ObjectModel u_models[]; };
layout(std430, binding = BINDING_OBJECT_VISIBLE) writeonly buffer Visible { uint u_visible[]; };
layout(std430, binding = BINDING_COUNTERS) buffer Counters { uint u_instance_counter[]; };  // objects.instances (low, high)
layout(std430, binding = BINDING_AUX) buffer Triangles { uint u_triangle_counter[]; };     // objects.triangles (low, high)

layout(location = 0) uniform uint u_count;          // instances
layout(location = 1) uniform vec3 u_camera;         // camera relative to the anchor (m)
layout(location = 2) uniform vec4 u_distances;      // lod1, lod2, max, shadow distance (m; shadow < 0: no casters)
layout(location = 3) uniform uint u_count_enabled;  // add to the objects.instances / objects.triangles counters
layout(location = 4) uniform vec4 u_planes[5];      // frustum planes, camera-relative (inside: dot >= 0)

void main() {
    uint i = gl_GlobalInvocationID.x + gl_GlobalInvocationID.y * gl_NumWorkGroups.x * gl_WorkGroupSize.x;
    if (i >= u_count) return;
    ObjectInstance inst = u_instances[i];
    uint model = uint(inst.params.y);
    ObjectModel m = u_models[model];
    vec3 centre = inst.position_yaw.xyz + objectTransform(inst, m.sphere.xyz) - u_camera;
    float r = inst.params.z;
    float d = length(centre);
    if (u_distances.w >= 0.0 && d - r <= u_distances.w) {
        uint slot = atomicAdd(u_counts[model * 4u + 3u], 1u);
        u_visible[m.region.w + slot] = i;
    }
    if (d - r > u_distances.z) return;
    for (int p = 0; p < 5; ++p)
        if (dot(u_planes[p].xyz, centre) + u_planes[p].w < -r) return;
    uint lod = d < u_distances.x ? 0u : (d < u_distances.y ? 1u : 2u);
    uint slot = atomicAdd(u_counts[model * 4u + lod], 1u);
    u_visible[m.region[lod] + slot] = i;
    if (u_count_enabled != 0u) {
        ADD_COUNTER64(u_instance_counter[0], u_instance_counter[1], 1u);
        ADD_COUNTER64(u_triangle_counter[0], u_triangle_counter[1], m.triangles[lod]);
    }
}
#endif
#endif
