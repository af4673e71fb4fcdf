// Debug view: the selected terrain nodes' bounding boxes as lines, coloured by LOD level.
#include "../../renderer/shaders/common.glsl"

struct Box {
    vec4 lo;  // camera-relative min corner (m), w: LOD level
    vec4 hi;  // camera-relative max corner (m)
};
layout(std430, binding = BINDING_TERRAIN_NODES) readonly buffer Boxes { Box u_boxes[]; };

#ifdef VERTEX_SHADER
flat out float v_level;
void main() {
    // 12 edges x 2 ends per box: edge e runs along axis e / 4 at corner (e % 4) of the other two.
    Box b = u_boxes[gl_VertexID / 24];
    int e = (gl_VertexID % 24) / 2, end = gl_VertexID % 2, axis = e / 4, corner = e % 4;
    vec3 t;
    t[axis] = float(end);
    t[(axis + 1) % 3] = float(corner & 1);
    t[(axis + 2) % 3] = float(corner >> 1);
    v_level = b.lo.w;
    gl_Position = u_view_proj * vec4(mix(b.lo.xyz, b.hi.xyz, t), 1.0);
}
#endif

#ifdef FRAGMENT_SHADER
flat in float v_level;
layout(location = 0) out vec4 o_color;
void main() {
    const vec3 colors[8] = vec3[](vec3(1, 0.2, 0.2), vec3(1, 0.6, 0.1), vec3(0.9, 0.9, 0.1), vec3(0.3, 0.9, 0.2),
                                  vec3(0.1, 0.8, 0.9), vec3(0.2, 0.4, 1), vec3(0.7, 0.3, 1), vec3(1, 0.4, 0.8));
    o_color = vec4(colors[int(v_level) % 8] * 4.0, 1.0);  // bright enough to read after tone mapping
}
#endif
