// objects.cull's uniforms (object_cull.glsl, its three variants): renderer/meshes/objects.cpp
// fills them, each variant reads its own.
#include "../../shaders/pass_block.glsl"
PASS_BLOCK(ObjectCullBlock)
    vec4 u_planes[5];              // frustum planes, camera-relative (inside: dot >= 0)
    vec4 u_distances;              // lod1, lod2, max, shadow distance (m; shadow < 0: no casters)
    vec3 u_camera; uint u_count;   // camera relative to the anchor (m); instances
    vec2 u_impostor; uint u_count_enabled; uint u_cull_unused;  // impostor distance, fade band (m); add to the
                                   // objects.instances / objects.triangles counters
    uint u_model_count; uint u_draw_count; uint u_cull_unused0; uint u_cull_unused1;  // COUNT_SHADOW: models; FIXUP_DRAWS: draw commands
PASS_BLOCK_END
