// "lighting.sun": deferred sun and ambient light over the G-buffer (renderer/scene_targets.h),
// added to the HDR target. Local lights come after it (renderer/lighting/local_lights.h).
#pragma once

#include "renderer/debug_settings.h"
#include "renderer/lighting/sun_variant.h"
#include "renderer/render_context.h"
#include "renderer/scene_targets.h"
#include "renderer/shadows/sun_shadows.h"
#include "sky/sky_lighting.h"
#include "sky/sky_settings.h"

#include <glm/vec3.hpp>

#include <string>
#include <vector>

namespace vista {

// The light the sky gives: the key light's (sun's or moon's, SkyLighting::keyDirection())
// irradiance at normal incidence and hemisphere ambient, RGB in the HDR units of [sky]
// sun_illuminance (times the frame's pre-exposure). Direction: FrameUniforms::sun_dir.
struct SunAndSky {
    glm::vec3 sun_irradiance{0.0f};  // the sun's irradiance on a surface facing it
    glm::vec3 sky_up{0.0f};          // sky irradiance on an upward-facing surface
    glm::vec3 ground_up{0.0f};       // irradiance from the ground on a downward-facing surface
    //! With targets.cloud_shadow: where its map lies (sky/clouds/clouds.h Clouds::addShadowPass()).
    glm::vec4 cloud_shadow_map{0.0f};
};

// From the atmosphere (sky/sky_lighting.h): the sun's irradiance after transmittance, the sky's
// irradiance on an up-facing surface, and the ground (albedo [sky] ground_albedo) lit by both as
// the light from below.
SunAndSky sunAndSky(const SkyLighting& sky, const SkySettings& settings);

// Every variant of "lighting.sun" (SunVariant::all(), for FrameRenderer::allPrograms()).
ProgramList lightingPrograms();

// Needs targets.albedo, .normal and .depth; multiplies the ambient by targets.ao when valid (SSAO)
// and the sun's direct light by targets.cloud_shadow when valid (HAS_CLOUD_SHADOW) and by the
// cascaded shadows when `shadows` is valid (debug: [debug] view = cascades tints each pixel by its
// cascade, shadow writes the cascades' visibility alone); writes (adds to) targets.hdr.
void addSunLightingPass(FrameGraph& graph, const RenderContext& rc, const SunAndSky& light, SceneTargets& targets,
                        const SunShadowInput& shadows = {}, DebugView debug = DebugView::Final);

}  // namespace vista
