// Auto exposure after the usual histogram approach (e.g. Unreal's): metering in log2
// luminance, the average between two percentiles so that a few very dark or bright pixels do
// not swing it, and exponential adaptation whose rate is per second, not per frame.
#include "postfx/exposure.h"

#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>

namespace vista {

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
    struct HistogramData {
        TextureHandle image;
        BufferHandle histogram;
    };
    const HistogramData& h = graph.addPass<HistogramData>("postfx.exposure.histogram",
        [&](PassBuilder& b, HistogramData& d) {
            d.image = b.read(image);
            d.histogram = b.write(b.create("exposure.histogram", BufferDesc{sizeof(std::uint32_t) * postfx::kHistogramBins}));
        },
        [&rc](const HistogramData& d, PassContext& ctx) {
            const TextureDesc& desc = ctx.desc(d.image);
            glClearNamedBufferData(ctx.buffer(d.histogram), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, nullptr);
            glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
            glUseProgram(rc.shaders.id("postfx/shaders/exposure_histogram.glsl"));
            glBindTextureUnit(0, ctx.texture(d.image));
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, postfx::kHistogramBinding, ctx.buffer(d.histogram));
            const GLuint g = postfx::kHistogramGroup;
            const GLuint w = (GLuint(desc.width) + 1) / 2, h = (GLuint(desc.height) + 1) / 2;  // 2x2 blocks
            glDispatchCompute((w + g - 1) / g, (h + g - 1) / g, 1);
            glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
        });

    struct AdaptData {
        BufferHandle histogram, state;
    };
    // The state is written, not declared read: the previous frame's value is this pass's own
    // business, and a pass reading what it writes would keep itself alive.
    BufferHandle state = graph.importBuffer("exposure.state", BufferDesc{sizeof(postfx::ExposureState)}, state_.id());
    const float low = std::min(s.low_percent, s.high_percent) / 100.0f, high = s.high_percent / 100.0f;
    const float min_ev = std::min(s.min_ev, s.max_ev), max_ev = s.max_ev;
    const float up = s.speed_up, down = s.speed_down, compensation = std::exp2(s.ev);
    const float dt = float(std::clamp(dt_s, 0.0, 1e6));
    const glm::vec3 units(float(std::log2(std::max(rc.pre_exposure, 1e-30))), float(std::log2(std::max(cd_per_unit, 1e-30))),
                          s.night_ev);
    const AdaptData& a = graph.addPass<AdaptData>("postfx.exposure.adapt",
        [&](PassBuilder& b, AdaptData& d) {
            d.histogram = b.read(h.histogram);
            d.state = b.write(state);
        },
        [&rc, low, high, min_ev, max_ev, up, down, compensation, dt, reset, units](const AdaptData& d, PassContext& ctx) {
            GLuint program = rc.shaders.id("postfx/shaders/exposure_adapt.glsl");
            glUseProgram(program);
            glProgramUniform2f(program, 0, low, high);
            glProgramUniform2f(program, 1, min_ev, max_ev);
            glProgramUniform2f(program, 2, up, down);
            glProgramUniform1f(program, 3, dt);
            glProgramUniform1f(program, 4, reset ? 1.0f : 0.0f);
            glProgramUniform1f(program, 5, compensation);
            glProgramUniform3f(program, 6, units.x, units.y, units.z);
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, postfx::kHistogramBinding, ctx.buffer(d.histogram));
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, postfx::kExposureBinding, ctx.buffer(d.state));
            glDispatchCompute(1, 1, 1);
            glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
        });
    return {true, 1.0f, a.state};
}

TextureHandle addExposureApplyPass(FrameGraph& graph, const RenderContext& rc, TextureHandle image,
                                   const ExposureInput& exposure) {
    struct Data {
        TextureHandle in, out;
        BufferHandle state;
    };
    const bool automatic = exposure.state.valid();
    const float manual = exposure.manual;
    const Data& d = graph.addPass<Data>("postfx.exposure.apply",
        [&](PassBuilder& b, Data& data) {
            data.in = b.read(image);
            if (automatic) data.state = b.read(exposure.state);
            TextureDesc desc = b.desc(image);
            desc.levels = 1;
            data.out = b.write(b.create("exposed", desc));
        },
        [&rc, automatic, manual](const Data& data, PassContext& ctx) {
            const TextureDesc& desc = ctx.desc(data.out);
            bindTarget(rc.device.framebuffer({ctx.texture(data.out)}), desc.width, desc.height);
            std::vector<std::string> defines;
            if (automatic) defines.push_back("EXPOSURE_AUTO");
            GLuint program = rc.shaders.id("postfx/shaders/exposure_apply.glsl", defines);
            glUseProgram(program);
            glProgramUniform1f(program, 0, manual);
            glBindTextureUnit(0, ctx.texture(data.in));
            if (automatic) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, postfx::kExposureBinding, ctx.buffer(data.state));
            drawFullscreen(rc);
        });
    return d.out;
}

ProgramList exposurePrograms() {
    return {{"postfx/shaders/exposure_histogram.glsl", {}},
            {"postfx/shaders/exposure_adapt.glsl", {}},
            {"postfx/shaders/exposure_apply.glsl", {}},
            {"postfx/shaders/exposure_apply.glsl", {"EXPOSURE_AUTO"}}};
}

}  // namespace vista
