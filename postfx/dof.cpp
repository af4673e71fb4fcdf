// Depth of field after the usual scatter-as-gather scheme (e.g. Jimenez 2014, Sousa 2013):
// each tap of a disk around the pixel contributes when its own CoC reaches the pixel, far
// taps no further than the pixel's own CoC (a sharp object is not covered by the blurred
// background behind it), near taps by their own CoC into a separate layer whose coverage is
// the share of the pixel the blurred foreground discs cover.
#include "postfx/dof.h"

#include "renderer/pass_kit.h"

#include <algorithm>
#include <cmath>

namespace vista {

namespace {

#include "postfx/shaders/dof_block.glsl"

// Every uniform the passes share: the lens, the focus range, the gather's taps.
DofBlock dofBlock(const RenderContext& rc, const DofSettings& s) {
    DofBlock b{};
    b.u_focal_m = s.focal_length_mm * 1e-3f;
    b.u_f_stop = s.f_stop;
    b.u_sensor_m = s.sensor_height_mm * 1e-3f;
    b.u_manual_diopters = dofClampDiopters(1.0f / s.focus_distance_m, s);
    b.u_near_m = float(rc.view.near_m);
    b.u_max_coc_px = s.max_coc_px;
    b.u_max_diopters = dofClampDiopters(1e30f, s);
    b.u_rate = s.autofocus_rate;
    b.u_taps = float(s.samples);
    return b;
}

}  // namespace

double dofCocRadiusPx(double distance_m, double focus_m, const DofSettings& s, int image_height) {
    const double f = double(s.focal_length_mm) * 1e-3, n = double(s.f_stop);
    const double p = 1.0 / focus_m, inv = std::isinf(distance_m) ? 0.0 : 1.0 / distance_m;
    const double diameter_m = f * f / n * (p - inv) / (1.0 - f * p);
    return 0.5 * diameter_m / (double(s.sensor_height_mm) * 1e-3) * double(image_height);
}

float dofClampDiopters(float diopters, const DofSettings& s) {
    return std::clamp(diopters, 0.0f, 0.5f / (s.focal_length_mm * 1e-3f));
}

DepthOfField::DepthOfField() {
    postfx::DofFocusState initial;
    state_ = gl::Buffer::create(sizeof initial, &initial, GL_DYNAMIC_STORAGE_BIT, "postfx.dof focus state");
}

postfx::DofFocusState DepthOfField::read() const {
    postfx::DofFocusState s;
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glGetNamedBufferSubData(state_.id(), 0, sizeof s, &s);
    return s;
}

TextureHandle addDofCocPass(FrameGraph& graph, const RenderContext& rc, TextureHandle image, TextureHandle depth,
                            const DofSettings& s, BufferHandle focus) {
    FullscreenPass pass("postfx.dof.coc", {"postfx/shaders/dof_coc.glsl", {}}, {image, depth}, "dof.coc");
    pass.format = PixelFormat::RGBA16F;
    if (focus.valid()) {
        pass.program.defines.push_back("DOF_AUTOFOCUS");
        pass.buffers.emplace_back(postfx::kDofFocusBinding, focus);
    }
    return addFullscreenPass(graph, rc, std::move(pass), [block = dofBlock(rc, s)](const TextureDesc& image_desc) {
        DofBlock b = block;
        b.u_height_px = float(image_desc.height);
        return b;
    });
}

TextureHandle DepthOfField::addPasses(FrameGraph& graph, const RenderContext& rc, TextureHandle image,
                                      TextureHandle depth, const DofSettings& s, double dt_s, bool reset) {
    DofBlock block = dofBlock(rc, s);
    BufferHandle focus;
    if (s.autofocus) {
        block.u_dt = float(std::clamp(dt_s, 0.0, 1e6));
        block.u_reset = reset ? 1.0f : 0.0f;
        // Written, not declared read: the last frame's focus is this pass's own business.
        const BufferHandle state = graph.importBuffer("dof.focus", BufferDesc{sizeof(postfx::DofFocusState)}, state_.id());
        ComputePass measure("postfx.dof.focus", {"postfx/shaders/dof_focus.glsl", {}});
        measure.inputs = {depth};
        measure.writes = {{postfx::kDofFocusBinding, state}};
        focus = addComputePass(graph, rc, std::move(measure), block)[0];
    }
    const TextureHandle coc = addDofCocPass(graph, rc, image, depth, s, focus);

    // Tiles of kDofTile pixels: the smallest CoC of each (mode 0), then dilated by the reach of
    // the largest CoC (mode 1).
    const auto tilePass = [&](const char* name, const char* target, TextureHandle in, int mode, int reach) {
        DofBlock b = block;
        b.u_tile_mode = mode;
        b.u_tile_reach = reach;
        FullscreenPass pass(name, {"postfx/shaders/dof_tiles.glsl", {}}, {in}, target);
        pass.format = PixelFormat::R16F;
        pass.divisor = postfx::kDofTile;
        pass.divide_up = true;
        pass.size_from = coc;
        return addFullscreenPass(graph, rc, std::move(pass), b);
    };
    const TextureHandle tiles = tilePass("postfx.dof.tiles", "dof.tiles", coc, 0, 0);
    const int reach = int(std::ceil(s.max_coc_px / float(postfx::kDofTile)));
    const TextureHandle near = tilePass("postfx.dof.dilate", "dof.near", tiles, 1, reach);

    std::vector<std::string> defines;
    if (s.debug) defines.push_back("DOF_DEBUG");
    FullscreenPass gather("postfx.dof.gather", {"postfx/shaders/dof_gather.glsl", defines}, {coc, near}, "dof.out");
    gather.size_from = image;
    return addFullscreenPass(graph, rc, std::move(gather), block);
}

ProgramList dofPrograms() {
    return {{"postfx/shaders/dof_focus.glsl", {}},
            {"postfx/shaders/dof_coc.glsl", {}},
            {"postfx/shaders/dof_coc.glsl", {"DOF_AUTOFOCUS"}},
            {"postfx/shaders/dof_tiles.glsl", {}},
            {"postfx/shaders/dof_gather.glsl", {}},
            {"postfx/shaders/dof_gather.glsl", {"DOF_DEBUG"}}};
}

}  // namespace vista
