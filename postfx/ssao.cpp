// SSAO: the raw pass stores view distance beside the visibility so that the blur needs one
// fetch per tap for both; with full size and no blur the raw target is the result.
#include "postfx/ssao.h"

#include "renderer/pass_kit.h"

namespace vista {
namespace {
#include "postfx/shaders/ssao_block.glsl"
#include "postfx/shaders/ssao_blur_block.glsl"
}  // namespace

TextureHandle addSsaoPasses(FrameGraph& graph, const RenderContext& rc, const SceneTargets& scene, const SsaoSettings& s) {
    const int scale = s.half_resolution ? 2 : 1;
    SsaoBlock block{};
    block.u_params = {s.radius_m, s.intensity, s.bias, float(scale)};
    block.u_counts = {s.directions, s.steps, 0, 0};
    FullscreenPass raw("postfx.ssao", {"postfx/shaders/ssao.glsl", {}}, {scene.depth, scene.normal}, "ssao.raw");
    raw.format = PixelFormat::RG16F;
    raw.divisor = scale;
    raw.divide_up = true;
    const TextureHandle ao = addFullscreenPass(graph, rc, std::move(raw), block);
    if (scale == 1 && !s.blur) return ao;

    SsaoBlurBlock blur{};
    blur.u_blur = {s.blur_depth_tolerance, s.blur ? 1.0f : 0.0f, float(scale), 0.0f};
    FullscreenPass pass("postfx.ssao.blur", {"postfx/shaders/ssao_blur.glsl", {}}, {ao, scene.depth}, "scene.ao");
    pass.size_from = scene.depth;
    pass.format = PixelFormat::R16F;
    return addFullscreenPass(graph, rc, std::move(pass), blur);
}

ProgramList ssaoPrograms() {
    return {{"postfx/shaders/ssao.glsl", {}}, {"postfx/shaders/ssao_blur.glsl", {}}};
}

}  // namespace vista
