// Per-frame constants and helpers shared by every program.
#include "bindings.glsl"

// Camera-relative: the camera sits at the origin, world positions arrive minus the camera
// position (subtracted on the CPU in double precision). Reversed-Z, infinite far plane:
// depth 1 at the near plane, 0 at infinity.
layout(std140, binding = BINDING_FRAME_UNIFORMS) uniform FrameUniforms {
    mat4 u_view;           // rotation only
    mat4 u_proj;
    mat4 u_view_proj;
    mat4 u_inv_view_proj;
    vec4 u_camera_world;   // camera position in world space (lossy float; for effects only)
    vec4 u_sun_dir;        // xyz: unit vector towards the key light (sun, or moon at night), w: sun illuminance
    vec4 u_viewport;       // width, height, 1/width, 1/height
    vec4 u_time;           // x: scene time (s), y: frame index, z: temporal index (since the last history reset),
                           // w: the screen estimators' blue-noise frame (SSAO, shadow kernels): z with TAA, else 0
    vec4 u_near;           // x: near plane (m)
    vec4 u_exposure;       // x: pre-exposure (sky/night_light.h), already in every light's radiance
};

// View ray (camera-relative world space) through a pixel centre in [0,1]^2 uv.
vec3 viewRay(vec2 uv) {
    vec4 p = u_inv_view_proj * vec4(uv * 2.0 - 1.0, 0.5, 1.0);
    return normalize(p.xyz / p.w);
}

// Distance along the view axis for a reversed-Z infinite-far depth value.
float linearDepth(float depth) {
    return u_near.x / max(depth, 1e-30);
}

vec3 safeNormalize(vec3 v) {
    float len2 = dot(v, v);
    return len2 > 1e-30 ? v * inversesqrt(len2) : vec3(0.0, 1.0, 0.0);
}
