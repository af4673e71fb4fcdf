// Lens flare from the sun: "postfx.lens_flare.visibility" (compute: the share of 16 depth samples
// on a 4x4 grid around the sun's screen position that see the sky, followed exponentially in
// time into a persistent state) and "postfx.lens_flare" (adds ghosts along the sun-to-centre
// axis, a halo, chromatic aberration and a starburst, times that visibility, to the image).
// The CPU decides whether the sun can flare at all: no pass while it is off screen, behind the
// camera or below the horizon.
#pragma once

#include "postfx/lens_flare_settings.h"
#include "postfx/postfx_bindings.h"
#include "renderer/gl/objects.h"
#include "renderer/render_context.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace vista {

namespace postfx {
// std430 mirror of FlareVisibility in postfx/shaders/lens_flare_visibility.glsl.
struct FlareVisibility {
    float visibility = 0.0f;  // smoothed share of sky samples, 0..1
    float target = 0.0f;      // this frame's share
    float valid = 0.0f;       // 0 until the first measurement
    float pad = 0.0f;
};
}  // namespace postfx

// The sun's position on screen in [0, 1]^2 (GL: y up), or none when it is behind the camera,
// outside the image or below the horizon (sun_dir: unit vector towards the sun, world space).
std::optional<glm::vec2> sunScreenPosition(const ViewParams& view, const glm::dvec3& sun_dir);

// The 16 sample offsets around the sun in units of the sampling radius (also in the shader).
glm::vec2 flareSampleOffset(int i);

class LensFlare {
public:
    LensFlare();
    TextureHandle addPasses(FrameGraph& graph, const RenderContext& rc, TextureHandle image, TextureHandle depth,
                            const LensFlareSettings& s, const glm::dvec3& sun_dir, float sun_illuminance, double dt_s,
                            bool reset);
    postfx::FlareVisibility read() const;  // tests, panel (stalls)
    std::size_t memoryBytes() const { return std::size_t(state_.size()); }  // GPU bytes held across frames

private:
    gl::Buffer state_;
    bool had_sun_ = false;  // last frame measured: smoothing continues; otherwise take it at once
};

ProgramList lensFlarePrograms();

}  // namespace vista
