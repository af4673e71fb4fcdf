// Auto exposure after the usual histogram approach (e.g. Unreal's): metering in log2
// luminance, the average between two percentiles so that a few very dark or bright pixels do
// not swing it, and exponential adaptation whose rate is per second, not per frame.
#include "postfx/exposure.h"

#include "renderer/pass_kit.h"

#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>

namespace vista {
namespace {
#include "postfx/shaders/exposure_block.glsl"
}  // namespace

AutoExposure::AutoExposure() {
    postfx::ExposureState initial;
    state_ = gl::Buffer::create(sizeof initial, &initial, GL_DYNAMIC_STORAGE_BIT, "postfx.exposure state");
}

postfx::ExposureState AutoExposure::read() const {
    postfx::ExposureState s;
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glGetNamedBufferSubData(state_.id(), 0, sizeof s, &s);
    return s;
}

ExposureInput manualExposure(const ExposureSettings& s) { return {true, std::exp2(s.ev), {}}; }

double ev100(double f_stop, double shutter_s, double iso) {
    return std::log2(f_stop * f_stop / std::max(shutter_s, 1e-9) * 100.0 / std::max(iso, 1e-9));
}

ExposureInput cameraExposure(const ExposureSettings& s, double ev100_value, double cd_per_value) {
    return {true, float(std::exp2(double(s.ev)) * cd_per_value / (1.2 * std::exp2(ev100_value))), {}};
}

ExposureInput AutoExposure::addPasses(FrameGraph& graph, const RenderContext& rc, TextureHandle image,
                                      const ExposureSettings& s, double dt_s, bool reset, double cd_per_unit) {
    ComputePass count("postfx.exposure.histogram", {"postfx/shaders/exposure_histogram.glsl", {}});
    count.inputs = {image};
    count.creates = {{postfx::kHistogramBinding, "exposure.histogram", BufferDesc{sizeof(std::uint32_t) * postfx::kHistogramBins}}};
    count.clear_writes = true;
    count.groups = [](const TextureDesc& desc) {
        const unsigned g = postfx::kHistogramGroup;
        const unsigned w = (unsigned(desc.width) + 1) / 2, h = (unsigned(desc.height) + 1) / 2;  // 2x2 blocks
        return glm::uvec3((w + g - 1) / g, (h + g - 1) / g, 1);
    };
    const BufferHandle histogram = addComputePass(graph, rc, std::move(count))[0];

    ExposureBlock block{};
    block.u_percent = {std::min(s.low_percent, s.high_percent) / 100.0f, s.high_percent / 100.0f};
    block.u_ev_range = {std::min(s.min_ev, s.max_ev), s.max_ev};
    block.u_speed = {s.speed_up, s.speed_down};
    block.u_dt = float(std::clamp(dt_s, 0.0, 1e6));
    block.u_reset = reset ? 1.0f : 0.0f;
    block.u_units = glm::vec3(float(std::log2(std::max(rc.pre_exposure, 1e-30))),
                              float(std::log2(std::max(cd_per_unit, 1e-30))), s.night_ev);
    block.u_compensation = std::exp2(s.ev);
    // The state is written, not declared read: the previous frame's value is this pass's own
    // business, and a pass reading what it writes would keep itself alive.
    const BufferHandle state = graph.importBuffer("exposure.state", BufferDesc{sizeof(postfx::ExposureState)}, state_.id());
    ComputePass adapt("postfx.exposure.adapt", {"postfx/shaders/exposure_adapt.glsl", {}});
    adapt.reads = {{postfx::kHistogramBinding, histogram}};
    adapt.writes = {{postfx::kExposureBinding, state}};
    const BufferHandle adapted = addComputePass(graph, rc, std::move(adapt), block)[0];
    return {true, 1.0f, adapted};
}

TextureHandle addExposureApplyPass(FrameGraph& graph, const RenderContext& rc, TextureHandle image,
                                   const ExposureInput& exposure) {
    FullscreenPass pass("postfx.exposure.apply", {"postfx/shaders/exposure_apply.glsl", {}}, {image}, "exposed");
    if (exposure.state.valid()) {
        pass.program.defines.push_back("EXPOSURE_AUTO");
        pass.buffers.emplace_back(postfx::kExposureBinding, exposure.state);
    }
    ExposureBlock block{};
    block.u_exposure = exposure.manual;
    return addFullscreenPass(graph, rc, std::move(pass), block);
}

ProgramList exposurePrograms() {
    return {{"postfx/shaders/exposure_histogram.glsl", {}},
            {"postfx/shaders/exposure_adapt.glsl", {}},
            {"postfx/shaders/exposure_apply.glsl", {}},
            {"postfx/shaders/exposure_apply.glsl", {"EXPOSURE_AUTO"}}};
}

}  // namespace vista
