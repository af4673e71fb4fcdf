// Lens flare: the sun's screen position and the decision to draw are CPU work (one projected
// direction); the visibility and the flare itself are GPU passes.
#include "postfx/lens_flare.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

namespace vista {

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
    const float dt = float(std::clamp(dt_s, 0.0, 1e6)), rate = s.visibility_rate;
    const glm::vec2 sun_uv = *sun;
    struct VisibilityData {
        TextureHandle depth;
        BufferHandle state;
    };
    // Written, not declared read: the last frame's visibility is this pass's own business.
    BufferHandle state = graph.importBuffer("lens_flare.visibility", BufferDesc{sizeof(postfx::FlareVisibility)}, state_.id());
    const BufferHandle visibility = graph.addPass<VisibilityData>("postfx.lens_flare.visibility",
        [&](PassBuilder& b, VisibilityData& d) {
            d.depth = b.read(depth);
            d.state = b.write(state);
        },
        [&rc, sun_uv, radius_px, dt, rate, continues](const VisibilityData& d, PassContext& ctx) {
            GLuint program = rc.shaders.id("postfx/shaders/lens_flare_visibility.glsl");
            glUseProgram(program);
            glProgramUniform4f(program, 0, sun_uv.x, sun_uv.y, radius_px, 0.0f);
            glProgramUniform3f(program, 1, dt, rate, continues ? 0.0f : 1.0f);
            glBindTextureUnit(0, ctx.texture(d.depth));
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, postfx::kFlareVisibilityBinding, ctx.buffer(d.state));
            glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
            glDispatchCompute(1, 1, 1);
            glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
        }).state;

    struct FlareData {
        TextureHandle image, out;
        BufferHandle visibility;
    };
    const glm::vec4 shape{float(s.ghosts), s.ghost_spacing, s.halo_radius, s.chromatic};
    const glm::vec2 strength{s.intensity * sun_illuminance, s.starburst};
    return graph.addPass<FlareData>("postfx.lens_flare",
        [&](PassBuilder& b, FlareData& d) {
            d.image = b.read(image);
            d.visibility = b.read(visibility);
            TextureDesc desc = b.desc(image);
            desc.levels = 1;
            d.out = b.write(b.create("lens_flare.out", desc));
        },
        [&rc, sun_uv, shape, strength](const FlareData& d, PassContext& ctx) {
            const TextureDesc& desc = ctx.desc(d.out);
            bindTarget(rc.device.framebuffer({ctx.texture(d.out)}), desc.width, desc.height);
            GLuint program = rc.shaders.id("postfx/shaders/lens_flare.glsl");
            glUseProgram(program);
            glProgramUniform4f(program, 0, sun_uv.x, sun_uv.y, strength.x, strength.y);
            glProgramUniform4f(program, 1, shape.x, shape.y, shape.z, shape.w);
            glBindTextureUnit(0, ctx.texture(d.image));
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, postfx::kFlareVisibilityBinding, ctx.buffer(d.visibility));
            drawFullscreen(rc);
        }).out;
}

ProgramList lensFlarePrograms() {
    return {{"postfx/shaders/lens_flare_visibility.glsl", {}}, {"postfx/shaders/lens_flare.glsl", {}}};
}

}  // namespace vista
