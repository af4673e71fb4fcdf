// The object programs' uniforms (object.glsl, every variant: G-buffer, shadow, impostor bake,
// forward glass and its light chunks): renderer/meshes/objects.cpp and objects_forward.cpp fill
// them once per draw. Guarded: both files may share a unity batch.
#ifndef OBJECT_BLOCK_GLSL
#define OBJECT_BLOCK_GLSL
#include "../../shaders/pass_block.glsl"
PASS_BLOCK(ObjectBlock)
    mat4 u_matrix;                     // camera-relative world -> clip (view, or a shadow view)
    vec3 u_camera; uint u_region;      // camera relative to the anchor (m); first slot of this draw's group
    vec4 u_base_color;                 // linear RGBA factor
    vec4 u_material;                   // metallic, roughness, normal scale, occlusion strength
    vec4 u_emissive;                   // rgb emissive factor x nits, w alpha cutoff
    vec4 u_fade;                       // IMPOSTOR_FADE: band start (m), 1 / band width (1/m), model-space sphere centre xy ...
    vec3 u_sun_irradiance; float u_fade_centre_z;  // FORWARD: the sun at normal incidence (HDR units); IMPOSTOR_FADE: ... and z
    vec3 u_sky_up; float u_object_unused0;         // FORWARD: sky irradiance on an up-facing surface
    vec3 u_ground_up; float u_object_unused1;      // FORWARD: ground bounce on a down-facing surface
    vec4 u_clip;                       // FORWARD: camera-relative plane, kept where dot(u_clip, (p, 1)) >= 0
    vec4 u_aerial;                     // AERIAL_FOG: the volume's layout (renderer/shaders/aerial_fetch.glsl)
    uvec2 u_light_chunk; uvec2 u_object_unused2;   // FORWARD with lights: this draw's chunk of each light range (lights.glsl chunkOf)
PASS_BLOCK_END
#endif
