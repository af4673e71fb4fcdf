// Exposure: a manual scale (2^ev), or auto exposure metered from a log-luminance histogram
// ("postfx.exposure.histogram", a compute pass) and adapted over time
// ("postfx.exposure.adapt", into a persistent state buffer). The scale is applied by the next
// pass of the chain: the tone map, or "postfx.exposure.apply" when another effect comes first.
#pragma once

#include "postfx/exposure_settings.h"
#include "postfx/postfx_bindings.h"
#include "renderer/gl/objects.h"
#include "renderer/render_context.h"

#include <string>
#include <utility>
#include <vector>

namespace vista {

// An exposure the next pass multiplies its input by: state (auto) when valid, else manual.
struct ExposureInput {
    bool pending = false;
    float manual = 1.0f;
    BufferHandle state;
};

// The adapted exposure, kept across frames.
class AutoExposure {
public:
    AutoExposure();
    // Meters image and adapts: dt_s is the time since the last metered frame; reset takes the
    // metered value at once (first frame, time jumped back). image holds radiance times
    // rc.pre_exposure, cd_per_unit cd/m^2 per HDR unit before it (sky/night_light.h
    // luxPerHdrUnit); the state is kept in HDR units without the pre-exposure.
    ExposureInput addPasses(FrameGraph& graph, const RenderContext& rc, TextureHandle image, const ExposureSettings& s,
                            double dt_s, bool reset, double cd_per_unit);
    // Reads the state back from the GPU (tests, panel; stalls).
    postfx::ExposureState read() const;
    std::size_t memoryBytes() const { return std::size_t(state_.size()); }  // GPU bytes held across frames

private:
    gl::Buffer state_;
};

ExposureInput manualExposure(const ExposureSettings& s);
// A physical camera's exposure value at ISO 100: log2(N^2 / t * 100 / S), f-number N, shutter
// time t (s), sensitivity S (Lagarde & de Rousiers 2014, "Moving Frostbite to PBR", 4.5).
double ev100(double f_stop, double shutter_s, double iso);
// The camera's exposure (ExposureMode::Camera): the luminance 1.2 * 2^EV100 cd/m^2 maps to 1,
// times 2^ev; cd_per_value converts the image's values to cd/m^2 (RenderContext::cd_per_value).
ExposureInput cameraExposure(const ExposureSettings& s, double ev100_value, double cd_per_value);

// "postfx.exposure.apply": image times the pending exposure, same format.
TextureHandle addExposureApplyPass(FrameGraph& graph, const RenderContext& rc, TextureHandle image,
                                   const ExposureInput& exposure);

ProgramList exposurePrograms();

}  // namespace vista
