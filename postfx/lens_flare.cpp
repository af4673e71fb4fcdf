// Lens flare: the sun's screen position and the decision to draw are CPU work (one projected
// direction); the visibility and the flare itself are GPU passes.
#include "postfx/lens_flare.h"

#include "renderer/pass_kit.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

namespace vista {
namespace {
#include "postfx/shaders/lens_flare_block.glsl"
}  // namespace

std::optional<glm::vec2> sunScreenPosition(const ViewParams& view, const glm::dvec3& sun_dir) {
    if (!(sun_dir.y > 0.0)) return std::nullopt;  // below the horizon
    const glm::dvec4 clip = glm::dmat4(viewMatrices(view).view_proj) * glm::dvec4(sun_dir, 0.0);
    if (!(clip.w > 1e-9)) return std::nullopt;  // behind the camera
    const glm::dvec2 ndc = glm::dvec2(clip) / clip.w;
    if (std::abs(ndc.x) > 1.0 || std::abs(ndc.y) > 1.0) return std::nullopt;
    return glm::vec2(ndc * 0.5 + 0.5);
}

glm::vec2 flareSampleOffset(int i) {
    return glm::vec2(float(i % 4) - 1.5f, float(i / 4) - 1.5f) / 1.5f;
}

LensFlare::LensFlare() {
    postfx::FlareVisibility initial;
    state_ = gl::Buffer::create(sizeof initial, &initial, GL_DYNAMIC_STORAGE_BIT, "postfx.lens_flare visibility");
}

postfx::FlareVisibility LensFlare::read() const {
    postfx::FlareVisibility v;
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glGetNamedBufferSubData(state_.id(), 0, sizeof v, &v);
    return v;
}

TextureHandle LensFlare::addPasses(FrameGraph& graph, const RenderContext& rc, TextureHandle image,
                                   TextureHandle depth, const LensFlareSettings& s, const glm::dvec3& sun_dir,
                                   float sun_illuminance, double dt_s, bool reset) {
    const std::optional<glm::vec2> sun = sunScreenPosition(rc.view, sun_dir);
    const bool continues = had_sun_ && !reset;
    had_sun_ = sun.has_value();
    if (!sun || s.intensity <= 0.0f || sun_illuminance <= 0.0f) return image;

    // Pixels per radian at the centre of the image, for the sampling radius.
    const double px_per_rad = 0.5 * double(rc.view.height) / std::tan(0.5 * glm::radians(rc.view.fov_deg));
    const float radius_px = float(std::max(1.0, px_per_rad * std::tan(glm::radians(double(s.visibility_radius_deg)))));
    LensFlareBlock block{};
    block.u_sun_uv = *sun;
    block.u_radius_px = radius_px;
    block.u_strength = s.intensity * sun_illuminance;
    block.u_dt = float(std::clamp(dt_s, 0.0, 1e6));
    block.u_rate = s.visibility_rate;
    block.u_reset = continues ? 0.0f : 1.0f;
    block.u_starburst = s.starburst;
    block.u_ghosts = float(s.ghosts);
    block.u_ghost_spacing = s.ghost_spacing;
    block.u_halo_radius = s.halo_radius;
    block.u_chromatic = s.chromatic;
    // Written, not declared read: the last frame's visibility is this pass's own business.
    const BufferHandle state = graph.importBuffer("lens_flare.visibility", BufferDesc{sizeof(postfx::FlareVisibility)}, state_.id());
    ComputePass measure("postfx.lens_flare.visibility", {"postfx/shaders/lens_flare_visibility.glsl", {}});
    measure.inputs = {depth};
    measure.writes = {{postfx::kFlareVisibilityBinding, state}};
    const BufferHandle visibility = addComputePass(graph, rc, std::move(measure), block)[0];
    FullscreenPass flare("postfx.lens_flare", {"postfx/shaders/lens_flare.glsl", {}}, {image}, "lens_flare.out");
    flare.buffers = {{postfx::kFlareVisibilityBinding, visibility}};
    return addFullscreenPass(graph, rc, std::move(flare), block);
}

ProgramList lensFlarePrograms() {
    return {{"postfx/shaders/lens_flare_visibility.glsl", {}}, {"postfx/shaders/lens_flare.glsl", {}}};
}

}  // namespace vista
