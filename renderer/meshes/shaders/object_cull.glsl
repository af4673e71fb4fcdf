// "objects.cull": one thread per instance. An instance whose bounding sphere is inside the view
// frustum and within max distance goes into its model's list for the LOD its distance picks, or,
// beyond the impostor distance, into the model's impostor list; within the fade band before it
// into both (the two draws dither complementary pixels). One within the shadow distance also
// goes into the model's shadow list (no frustum test: casters off screen still shade it).
// FIXUP_DRAWS: a second dispatch, one thread per indirect command, copies its group's count into
// the command's instance count (the group is in its baseInstance field, which the draws do not
// use). COUNT_SHADOW: one thread per model adds its shadow list's triangles to the
// objects.shadow_triangles counter, once per shadow view drawn.
#ifdef COMPUTE_SHADER
#include "../../../renderer/shaders/common.glsl"
#include "../../../renderer/shaders/counters.glsl"
#include "object_common.glsl"
#include "object_cull_block.glsl"

layout(local_size_x = 64) in;

layout(std430, binding = BINDING_OBJECT_COUNTS) buffer Counts { uint u_counts[]; };

#if defined(COUNT_SHADOW)
layout(std430, binding = BINDING_OBJECT_MODELS) readonly buffer Models { ObjectModel u_models[]; };
layout(std430, binding = BINDING_COUNTERS) buffer Counters { uint u_shadow_counter[]; };  // objects.shadow_triangles
void main() {
    uint m = gl_GlobalInvocationID.x;
    if (m >= u_model_count) return;
    // casters x triangles can pass 2^32: the 64-bit product's high word goes to the high word.
    uint high, low;
    umulExtended(u_counts[m * OBJECT_GROUPS + 3u], u_models[m].triangles.w, high, low);
    ADD_COUNTER64(u_shadow_counter[0], u_shadow_counter[1], low);
    if (high != 0u) atomicAdd(u_shadow_counter[1], high);
}
#elif defined(FIXUP_DRAWS)
struct DrawCommand {
    uint count, instance_count, first_index;
    int base_vertex;
    uint base_instance;
};
layout(std430, binding = BINDING_OBJECT_DRAWS) buffer Draws { DrawCommand u_draws[]; };
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
layout(std430, binding = BINDING_AUX_2) buffer Impostors { uint u_impostor_counter[]; };   // objects.impostors (low, high)


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
        uint slot = atomicAdd(u_counts[model * OBJECT_GROUPS + 3u], 1u);
        u_visible[m.region.w + slot] = i;
    }
    if (d - r > u_distances.z) return;
    for (int p = 0; p < 5; ++p)
        if (dot(u_planes[p].xyz, centre) + u_planes[p].w < -r) return;
    uint triangles = 0u;
    if (d < u_impostor.x) {
        uint lod = d < u_distances.x ? 0u : (d < u_distances.y ? 1u : 2u);
        uint slot = atomicAdd(u_counts[model * OBJECT_GROUPS + lod], 1u);
        u_visible[m.region[lod] + slot] = i;
        triangles += m.triangles[lod];
    }
    bool impostor = d >= u_impostor.x - u_impostor.y;
    if (impostor) {
        uint slot = atomicAdd(u_counts[model * OBJECT_GROUPS + 4u], 1u);
        u_visible[m.impostor.x + slot] = i;
        triangles += m.impostor.y;
    }
    if (u_count_enabled != 0u) {
        ADD_COUNTER64(u_instance_counter[0], u_instance_counter[1], 1u);
        ADD_COUNTER64(u_triangle_counter[0], u_triangle_counter[1], triangles);
        if (impostor) ADD_COUNTER64(u_impostor_counter[0], u_impostor_counter[1], 1u);
    }
}
#endif
#endif
