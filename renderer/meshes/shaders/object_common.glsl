// Objects on the GPU (renderer/meshes/objects.h): instances, per-model data and the groups of
// the culled lists. Group g = model * 5 + k: k = 0..2 the view's LODs, 3 the shadow casters,
// 4 the impostors.
#define OBJECT_GROUPS 5u
struct ObjectInstance {
    vec4 position_yaw;  // xyz: world position relative to the objects' anchor (m), w: yaw (rad)
    vec4 params;        // x: scale, y: model index, z: bounding radius x scale (m), w: unused
};
struct ObjectModel {
    vec4 sphere;        // model-space bounding sphere: centre xyz, radius w (m)
    uvec4 region;       // first slot of each group's list in the visible buffer (LOD 0..2, shadow)
    uvec4 triangles;    // triangles of LOD 0..2 and of the shadow LOD
    uvec4 impostor;     // x: first slot of the impostor list, y: its triangles per instance (2)
};

// World offset (relative to the instance's position) of model-space point p.
vec3 objectTransform(ObjectInstance inst, vec3 p) {
    float c = cos(inst.position_yaw.w), s = sin(inst.position_yaw.w);
    p *= inst.params.x;
    return vec3(c * p.x + s * p.z, p.y, -s * p.x + c * p.z);
}

// Turns a world offset into the instance's model frame (the inverse of objectTransform's rotation).
vec3 objectInverseRotate(ObjectInstance inst, vec3 w) {
    float c = cos(inst.position_yaw.w), s = sin(inst.position_yaw.w);
    return vec3(c * w.x - s * w.z, w.y, s * w.x + c * w.z);
}

// Hemi-octahedral map of the upper hemisphere onto [-1, 1]^2 (the impostor's frame grid;
// renderer/meshes/impostor.h has the same maps on the CPU). Directions below the horizon are
// folded onto it.
vec2 hemiOctEncode(vec3 d) {
    d.y = max(d.y, 0.0);
    d /= max(abs(d.x) + abs(d.y) + abs(d.z), 1e-20);
    return vec2(d.x + d.z, d.x - d.z);
}
vec3 hemiOctDecode(vec2 e) {
    vec3 d = vec3(0.5 * (e.x + e.y), 0.0, 0.5 * (e.x - e.y));
    d.y = 1.0 - abs(d.x) - abs(d.z);
    return normalize(d);
}
// The card's right and up axes for a frame seen from direction d (unit, toward the viewer).
void impostorBasis(vec3 d, out vec3 right, out vec3 up) {
    right = abs(d.y) < 0.999 ? normalize(cross(vec3(0.0, 1.0, 0.0), d)) : vec3(1.0, 0.0, 0.0);
    up = cross(d, right);
}

// The mesh-to-impostor cross-fade: at fade t (0 mesh .. 1 impostor) the mesh keeps the pixels
// whose screen noise is >= t and the impostor the others, so each pixel shows exactly one.
float impostorFadeNoise(vec2 pixel) {  // interleaved gradient noise (Jimenez 2014)
    return fract(52.9829189 * fract(dot(floor(pixel), vec2(0.06711056, 0.00583715))));
}
// Fade of an instance whose bounding-sphere centre is dist from the camera: u_fade-style
// (band start, 1 / band width).
float impostorFade(float dist, vec2 fade) { return clamp((dist - fade.x) * fade.y, 0.0, 1.0); }
