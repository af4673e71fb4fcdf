// Noise cloud layers ([clouds], sky/clouds/cloud_model.h for the maths): "clouds.shadow", a small map
// of the sun's transmittance through the layers around the camera for lighting.sun, and
// "clouds.shell", the layers drawn over the image after the sky. A frame with clouds off (or no
// active layer) creates no Clouds object and adds no pass (app/frame.cpp).
#pragma once

#include "renderer/gl/objects.h"
#include "renderer/render_context.h"
#include "renderer/scene_targets.h"
#include "sky/clouds/cloud_settings.h"
#include "sky/sky_settings.h"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <string>
#include <utility>
#include <vector>

namespace vista {

class SkyAtmosphere;

// The side of the pixel block of which a subset march ([clouds] march_subset: 1, 4 or 16, others
// rounded down) marches one pixel per frame: 1, 2 or 4.
int cloudSubsetStride(int march_subset);

// Every program the clouds use, with its defines (for FrameRenderer::allPrograms()).
ProgramList cloudPrograms();

class Clouds {
public:
    Clouds();
    // This frame's layers (wind, coverage and noise origins at rc.time_s, in double) into the
    // uniform block both passes read. sky_irradiance_up: the sky's irradiance on an up-facing
    // surface (sky/sky_lighting.h), the clouds' ambient light. Returns the active layers.
    int prepare(const RenderContext& rc, const CloudsSettings& clouds, const SkySettings& sky,
                const glm::dvec3& sky_irradiance_up);
    // GPU bytes held across frames (its uniform block; the maps are transient).
    std::size_t memoryBytes() const;
    // "clouds.shadow": an R16F shadow_size^2 map of the sun's transmittance (1 = clear);
    // map: what lighting.sun needs to sample it (xy its centre minus the camera, world x/z m,
    // z 1 / extent (1/m), w the sun's slant max(sun y, 0.05)).
    TextureHandle addShadowPass(FrameGraph& graph, const RenderContext& rc, glm::vec4& map);
    // "clouds.shell": the layers over targets.hdr (after "sky.atmosphere"), cut at targets.depth;
    // with half_resolution into a half-size "clouds.half" that "clouds.composite" upsamples.
    // With [clouds] temporal the march goes to a target of its own (half or full size) with its
    // distances, "clouds.temporal" accumulates it with the reprojected history (kept here, across
    // frames) and "clouds.composite" blends the result. cut: drop the history (a camera cut).
    // With a march subset (temporal only) the march covers one pixel per block in a target
    // 1/stride its size ("clouds.subset") and "clouds.temporal" builds the whole cloud target.
    void addShellPass(FrameGraph& graph, const RenderContext& rc, const SkyAtmosphere& sky, SceneTargets& targets,
                      bool cut = false);
    // Tells the device the history textures are going (it caches framebuffers by texture name)
    // and drops them; call before destroying this object.
    void release(GlDevice& device);
    // Drops the accumulated history (FrameRenderer::resetHistory).
    void resetHistory() { history_valid_ = false; }
    // Frames accumulated in the history at most (0: none yet), for the clouds.history_frames counter.
    int historyFrames() const { return history_valid_ ? history_frames_ : 0; }
    // Pixels of the cloud target the last shell pass marched (all of them, or one per block of a
    // subset march).
    long long marchedPixels() const { return marched_pixels_; }

private:
    struct Gpu;
    void bind() const;
    // "clouds.temporal": march (and its distances) blended with the reprojected history; returns
    // the accumulated clouds (this frame's history).
    TextureHandle addTemporalPass(FrameGraph& graph, const RenderContext& rc, TextureHandle march, TextureHandle distance,
                                  const TextureDesc& desc, bool cut);

    gl::Buffer uniforms_;
    int shadow_size_ = 256;
    bool half_resolution_ = true;
    glm::vec4 shadow_map_{0.0f};
    // Temporal accumulation: colour (RGBA16F) and distance (km) + frames (RG16F), ping-ponged.
    bool temporal_ = true;
    int subset_stride_ = 1;  // cloudSubsetStride([clouds] march_subset) with temporal, else 1
    long long marched_pixels_ = 0;
    int frame_stride_ = 1;   // this frame's: subset_stride_, or 1 on a frame without usable history
    float temporal_blend_ = 0.0625f;
    float temporal_parallax_decay_ = 3.0f;
    gl::Texture history_[2], history_distance_[2];
    int history_current_ = 0;
    int history_frames_ = 0;
    bool history_valid_ = false;
    ViewParams history_view_;
};

}  // namespace vista
