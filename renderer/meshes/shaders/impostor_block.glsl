// objects.gbuffer's impostor cards' uniforms: renderer/meshes/objects.cpp fills them (once per
// model), impostor.glsl reads them.
#include "../../shaders/pass_block.glsl"
PASS_BLOCK(ImpostorBlock)
    mat4 u_matrix;                 // camera-relative world -> clip
    vec3 u_camera; uint u_region;  // camera relative to the anchor (m); first slot of the model's impostor list
    vec4 u_sphere;                 // model-space bounding sphere: centre, radius (m)
    vec4 u_params;                 // fade band start (m), 1 / band width, frames per side, emissive nits
PASS_BLOCK_END
