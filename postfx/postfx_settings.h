// [postfx]: the post chain's order (postfx/chain.h).
// describe() is the one description of the keys; config/settings.h gathers them into Settings.
#pragma once

#include "config/visitor.h"
#include "postfx/bloom_settings.h"
#include "postfx/dof_settings.h"
#include "postfx/exposure_settings.h"
#include "postfx/fxaa_settings.h"
#include "postfx/grade_settings.h"
#include "postfx/lens_flare_settings.h"
#include "postfx/motion_blur_settings.h"
#include "postfx/night_vision_settings.h"
#include "postfx/scotopic_settings.h"
#include "postfx/tonemap_settings.h"

#include <vector>

namespace vista {

//! The post-processing effects that [postfx] order can list; each has a [postfx.NAME] section.
enum class PostEffect : int { Bloom, Exposure, Tonemap, Fxaa, Grade, Dof, MotionBlur, LensFlare, NightVision, Scotopic };

struct PostfxSettings {
    bool enabled = true;  //!< off: the HDR image is only clamped and sRGB-encoded
    //! Effects in the order they run on the image. Effects before `tonemap` see linear HDR,
    //! effects after it the display (sRGB) image. Without `tonemap` (or with it disabled) the
    //! chain still ends with a clamp and the sRGB encoding.
    std::vector<PostEffect> order{PostEffect::MotionBlur, PostEffect::Dof,      PostEffect::Bloom,
                                  PostEffect::LensFlare,  PostEffect::Scotopic, PostEffect::Exposure, PostEffect::Tonemap,
                                  PostEffect::Grade,      PostEffect::NightVision, PostEffect::Fxaa};
};

// What the post chain (postfx/chain.h) reads: [postfx] and the sections of the effects it can run.
// The scene's Settings (config/settings.h) derives from it.
struct PostChainSettings {
    PostfxSettings postfx;
    ExposureSettings exposure;          // [postfx.exposure]
    TonemapSettings tonemap;            // [postfx.tonemap]
    BloomSettings bloom;                // [postfx.bloom]
    FxaaSettings fxaa;                  // [postfx.fxaa]
    GradeSettings grade;                // [postfx.grade]
    DofSettings dof;                    // [postfx.dof]
    MotionBlurSettings motion_blur;     // [postfx.motion_blur]
    LensFlareSettings lens_flare;       // [postfx.lens_flare]
    NightVisionSettings night_vision;   // [postfx.night_vision]
    ScotopicSettings scotopic;          // [postfx.scotopic]
};

// Lists the keys of PostfxSettings to v, in file order.
void describe(SettingsVisitor& v, PostfxSettings& s);

}  // namespace vista
