// Objects on the GPU (renderer/meshes/objects.h): instances, per-model data and the groups of
// the culled lists. Group g = model * 4 + k: k = 0..2 the view's LODs, 3 the shadow casters.
struct ObjectInstance {
    vec4 position_yaw;  // xyz: world position relative to the objects' anchor (m), w: yaw (rad)
    vec4 params;        // x: scale, y: model index, z: bounding radius x scale (m), w: unused
};
struct ObjectModel {
    vec4 sphere;        // model-space bounding sphere: centre xyz, radius w (m)
    uvec4 region;       // first slot of each group's list in the visible buffer (LOD 0..2, shadow)
    uvec4 triangles;    // triangles of LOD 0..2 and of the shadow LOD
};

// World offset (relative to the instance's position) of model-space point p.
vec3 objectTransform(ObjectInstance inst, vec3 p) {
    float c = cos(inst.position_yaw.w), s = sin(inst.position_yaw.w);
    p *= inst.params.x;
    return vec3(c * p.x + s * p.z, p.y, -s * p.x + c * p.z);
}
