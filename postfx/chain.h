// The post-processing chain ([postfx] order): each enabled effect adds its passes in the
// listed order, on a handle to the current image (Filament's PostProcessManager style),
// starting from the scene's linear HDR image and ending with the display image (RGBA8,
// sRGB-encoded). A disabled effect adds no pass and no target; a chain without an enabled
// tone map still ends with "postfx.encode" (clamp and sRGB).
#pragma once

#include "config/input_error.h"
#include "postfx/dof.h"
#include "postfx/exposure.h"
#include "postfx/grade.h"
#include "postfx/lens_flare.h"
#include "postfx/motion_blur.h"
#include "postfx/postfx_settings.h"
#include "renderer/feature_slot.h"
#include "renderer/render_context.h"

#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace vista {

class PostChain {
public:
    // Adds the chain's passes for hdr; returns the display image. rc.time_s drives the
    // exposure adaptation: its change since the last call is the frame time (the first call,
    // or time going backwards, takes the metered exposure at once).
    // depth: the scene's depth (reversed-Z) for the effects that need it (depth of field);
    // without one those effects add no pass. shown: something reads the returned image this
    // frame; when nothing does (an HDR-only capture) the graph culls the chain, and its clock
    // stays put so the adapting states (exposure, focus) catch up on the next shown frame.
    // velocity: the frame's motion vectors ("temporal.velocity") for motion blur; invalid: motion
    // blur makes its own from its previous camera.
    TextureHandle addPasses(FrameGraph& graph, const RenderContext& rc, TextureHandle hdr, const PostChainSettings& s,
                            TextureHandle depth = {}, bool shown = true, TextureHandle velocity = {});
    // Auto exposure's state, while auto exposure is in use (null otherwise).
    const AutoExposure* autoExposure() const { return auto_exposure_.get(); }
    // Depth of field's autofocus state, while depth of field is in use (null otherwise).
    const DepthOfField* dof() const { return dof_.get(); }
    // The lens flare's sun visibility, while the lens flare is in use (null otherwise).
    const LensFlare* lensFlare() const { return lens_flare_.get(); }
    // Loads the files the settings name ([postfx.grade] lut, found at lut_file) when they
    // changed; the problems (file:line) are returned and the LUT is then left out.
    InputErrors prepare(const PostChainSettings& s, const std::filesystem::path& lut_file);
    // Forgets every state kept across frames (adapted exposure, autofocus, motion blur's previous
    // camera, the flare's smoothed visibility, the clock): the next frame starts as the first.
    void resetHistory();
    // GPU bytes the chain holds across frames (effect states, the grading LUT); 0 when no effect
    // keeps state.
    std::size_t memoryBytes() const;

private:
    // Effects with state across frames, kept while they run (their bytes are postfx.memory_bytes).
    FeatureSlot<AutoExposure> auto_exposure_{nullptr};  // the adapted exposure
    FeatureSlot<DepthOfField> dof_{nullptr};            // the autofocus state
    FeatureSlot<MotionBlur> motion_blur_{nullptr};      // the previous frame's camera
    FeatureSlot<LensFlare> lens_flare_{nullptr};        // the smoothed sun visibility
    gl::Texture lut_texture_;                      // [postfx.grade] lut, while grading uses one
    GradeLut lut_;
    std::string lut_path_;                         // as given, to notice changes
    double last_time_s_ = 0.0;
    bool has_time_ = false;
};

// Every program variant the chain can use.
ProgramList postfxPrograms();

// The camera's EV100 for [postfx.exposure] mode = camera: the lens's [postfx.dof] f_stop, the
// shutter time [postfx.motion_blur] shutter_deg / 360 / frame_rate and [postfx.exposure] iso.
double cameraEv100(const PostChainSettings& s);

}  // namespace vista
