// What passes need from the renderer while they execute: shaders, the GL device (targets),
// the per-frame uniforms and a vertex array for full-screen triangles. Passed explicitly;
// there is no global renderer state.
#pragma once

#include "renderer/camera.h"
#include "renderer/gl_device.h"
#include "renderer/shader_library.h"

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include <cstdint>

namespace vista {

// std140 mirror of FrameUniforms in renderer/shaders/common.glsl.
struct FrameUniforms {
    glm::mat4 view;
    glm::mat4 proj;
    glm::mat4 view_proj;
    glm::mat4 inv_view_proj;
    glm::vec4 camera_world;
    glm::vec4 sun_dir;   // xyz towards the key light (the sun, or the moon at night), w [sky] sun_illuminance
    glm::vec4 viewport;  // w, h, 1/w, 1/h
    glm::vec4 time;      // x scene time (s), y frame index, z temporal index (frames since FrameRenderer::resetHistory)
    glm::vec4 near;      // x near plane (m)
    glm::vec4 exposure;  // x pre-exposure (sky/night_light.h): every light's radiance is times this
};
static_assert(sizeof(FrameUniforms) == 4 * 64 + 6 * 16, "FrameUniforms must match the std140 block");

struct RenderContext {
    ShaderLibrary& shaders;
    GlDevice& device;
    GLuint empty_vao;  // bound for attribute-less draws
    ViewParams view;
    ViewMatrices matrices;
    std::uint64_t frame = 0;
    double time_s = 0.0;
    double pre_exposure = 1.0;  // FrameUniforms::exposure.x (sky/night_light.h)
    // The frame's sun (as in FrameUniforms::sun_dir by day; at night that holds the moon), for
    // passes that work with it on the CPU (the lens flare): they read it here rather than from
    // the sky's settings.
    glm::dvec3 sun_direction{0.0, 1.0, 0.0};  // unit vector towards the sun
    float sun_illuminance = 0.0f;             // [sky] sun_illuminance times the pre-exposure
    float sun_visibility = 1.0f;              // share of the sun reaching the camera through the air and clouds, 0..1
    // cd/m^2 per unit of the HDR image as rendered (pre-exposure included; sky/night_light.h
    // luxPerHdrUnit), for the passes that work in physical units (exposure, scotopic vision).
    double cd_per_value = 1.0;
    // The TAA's sub-pixel shift of this frame's projection in NDC (already in `matrices` and the
    // frame uniforms; `view` is unjittered). Temporal passes take it out when they reproject.
    glm::vec2 jitter_ndc{0.0f};
};

// Draws a full-screen triangle with the bound program.
void drawFullscreen(const RenderContext& rc);

}  // namespace vista
