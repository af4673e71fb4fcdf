// The chain keeps one pending exposure: exposure only meters, and the next pass that reads
// the image applies it (the tone map does so for free; anything else gets an apply pass).
#include "postfx/chain.h"

#include "postfx/bloom.h"
#include "postfx/fxaa.h"
#include "postfx/grade.h"
#include "postfx/lut.h"
#include "postfx/scotopic.h"
#include "postfx/ssao.h"
#include "postfx/tonemap.h"

namespace vista {

void PostChain::resetHistory() {
    auto_exposure_.release();
    dof_.release();
    motion_blur_.release();
    lens_flare_.release();
    has_time_ = false;
    last_time_s_ = 0.0;
}

TextureHandle PostChain::addPasses(FrameGraph& graph, const RenderContext& rc, TextureHandle hdr, const PostChainSettings& s,
                                   TextureHandle depth, bool shown, TextureHandle velocity) {
    const double dt = has_time_ ? rc.time_s - last_time_s_ : 0.0;
    const bool reset = !has_time_ || dt < 0.0;
    if (shown) {
        last_time_s_ = rc.time_s;
        has_time_ = true;
    }

    TextureHandle image = hdr;
    bool display = false;  // after the tone map: RGBA8 sRGB-encoded
    ExposureInput exposure;
    TextureHandle debug_view;  // an effect's debug view replaces the display (later effects are culled)
    auto flush = [&] {
        if (exposure.pending) image = addExposureApplyPass(graph, rc, image, exposure);
        exposure = {};
    };
    const std::vector<PostEffect> none;
    for (PostEffect effect : s.postfx.enabled ? s.postfx.order : none) {
        switch (effect) {
            case PostEffect::Bloom:
                if (!s.bloom.enabled) break;
                flush();
                image = addBloomPasses(graph, rc, image, s.bloom);
                break;
            case PostEffect::Exposure:
                if (!s.exposure.enabled) break;
                flush();
                if (s.exposure.mode == ExposureMode::Auto) {
                    // cd/m^2 per HDR unit of the light itself (the image holds it times the pre-exposure).
                    exposure = auto_exposure_.use().addPasses(graph, rc, image, s.exposure, dt, reset,
                                                              rc.cd_per_value * rc.pre_exposure);
                } else if (s.exposure.mode == ExposureMode::Camera) {
                    exposure = cameraExposure(s.exposure, cameraEv100(s), rc.cd_per_value);  // cd/m^2 as rendered
                } else {
                    exposure = manualExposure(s.exposure);
                    exposure.manual /= float(rc.pre_exposure);  // a fixed exposure of the light itself
                }
                break;
            case PostEffect::Tonemap:
                if (!s.tonemap.enabled || display) break;
                image = addTonemapPass(graph, rc, image, s.tonemap.op, s.tonemap.white, exposure);
                exposure = {};
                display = true;
                break;
            case PostEffect::Grade:
                if (!s.grade.enabled) break;
                flush();
                image = addGradePass(graph, rc, image, s.grade, lut_.texture ? &lut_ : nullptr);
                break;
            case PostEffect::Dof:
                if (!s.dof.enabled || !depth.valid()) break;
                flush();
                image = dof_.use().addPasses(graph, rc, image, depth, s.dof, dt, reset);
                if (s.dof.debug) debug_view = image;
                break;
            case PostEffect::MotionBlur:
                if (!s.motion_blur.enabled || !depth.valid()) break;
                flush();
                image = motion_blur_.use().addPasses(graph, rc, image, depth, velocity, s.motion_blur, dt, reset);
                break;
            case PostEffect::LensFlare:
                if (!s.lens_flare.enabled || !depth.valid()) break;
                flush();
                image = lens_flare_.use().addPasses(graph, rc, image, depth, s.lens_flare, rc.sun_direction,
                                                    rc.sun_illuminance * rc.sun_visibility, dt, reset);
                break;
            case PostEffect::Scotopic:
                // Only on frames whose sky is dim enough to be pre-exposed (below 400 lx).
                if (!s.scotopic.enabled || display || !(rc.pre_exposure > 1.0)) break;
                flush();
                image = addScotopicPass(graph, rc, image, s.scotopic, rc.cd_per_value);
                break;
            case PostEffect::NightVision:
                if (!s.night_vision.enabled) break;
                flush();
                image = addNightVisionPass(graph, rc, image, s.night_vision);
                break;
            case PostEffect::Fxaa:
                if (!s.fxaa.enabled) break;
                flush();
                image = addFxaaPass(graph, rc, image, s.fxaa, !display);
                break;
        }
    }
    // An effect that is off keeps nothing.
    auto_exposure_.releaseUnused();
    dof_.releaseUnused();
    motion_blur_.releaseUnused();
    lens_flare_.releaseUnused();
    if (debug_view.valid()) return debug_view;
    if (!display) return addTonemapPass(graph, rc, image, Tonemapper::Clamp, 1.0f, exposure, "postfx.encode");
    flush();
    return image;
}

std::size_t PostChain::memoryBytes() const {
    return auto_exposure_.memoryBytes() + dof_.memoryBytes() + lens_flare_.memoryBytes() + lut_texture_.bytes();
}

InputErrors PostChain::prepare(const PostChainSettings& s, const std::filesystem::path& lut_file) {
    InputErrors errors;
    const std::string wanted = s.grade.enabled && !s.grade.lut.empty() ? lut_file.string() : std::string();
    if (wanted == lut_path_) return errors;
    lut_path_ = wanted;
    lut_texture_ = {};
    lut_ = {};
    if (wanted.empty()) return errors;
    if (std::optional<CubeLut> cube = loadCube(wanted, errors)) {
        lut_texture_ = uploadCube(*cube, "postfx.grade lut");
        lut_ = {lut_texture_.id(), cube->size, cube->domain_min, cube->domain_max};
    }
    return errors;
}

double cameraEv100(const PostChainSettings& s) {
    const double shutter_s = double(s.motion_blur.shutter_deg) / 360.0 / double(s.motion_blur.frame_rate);
    return ev100(double(s.dof.f_stop), shutter_s, double(s.exposure.iso));
}

ProgramList postfxPrograms() {
    ProgramList programs;
    for (auto list :
         {tonemapPrograms(), exposurePrograms(), bloomPrograms(), fxaaPrograms(), gradePrograms(), ssaoPrograms(), dofPrograms(),
          motionBlurPrograms(), lensFlarePrograms(), scotopicPrograms()})
        programs.insert(programs.end(), list.begin(), list.end());
    return programs;
}

}  // namespace vista
