// The GPU atmosphere (Hillaire 2020, the model of sky/atmosphere_model.h): long-lived LUTs
// (transmittance, multiple scattering, sky view) rebuilt only when what they depend on
// changes; the aerial perspective (haze and optional height fog) over everything at finite
// depth; and the "sky.atmosphere" pass that draws the sky, the sun disk, the moon, the stars
// and the planet's ground behind everything at infinite depth. Also the sun's and the moon's
// directions and the celestial frame from the settings.
#pragma once

#include "renderer/aerial_volume.h"
#include "renderer/gl/objects.h"
#include "renderer/render_context.h"
#include "renderer/scene_targets.h"
#include "sky/atmosphere_model.h"
#include "sky/sky_settings.h"

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace vista {

// Unit vector towards the sun in vista's world (y up, -z north): from the angles or from
// latitude, day of year and solar time (sun_mode).
glm::dvec3 sunDirection(const SkySettings& sky);

// Unit vector towards the moon: from the angles, or (sun_mode = time) moon_age_days after new
// moon along the ecliptic from the sun (its 5 deg inclination ignored).
glm::dvec3 moonDirection(const SkySettings& sky);
// Rotation from vista's world to the celestial frame (z the celestial pole, x the vernal
// equinox) at the settings' latitude and, in sun_mode = time, local sidereal time (angles: 0).
glm::dmat3 celestialFromWorld(const SkySettings& sky);

// The model's parameters from the settings (metres, 1/m; solar_irradiance 1: radiances are
// transfer factors the renderer scales by sun_illuminance).
AtmosphereParams atmosphereParams(const SkySettings& sky);

// Every program the sky uses (for FrameRenderer::allPrograms()).
ProgramList skyPrograms();

// What of the sky pass's optional work a view can show (its program variants: a shader core runs
// a branch's body for every pixel). Conservative: a disc counts when any part of it, grown by a
// degree, may lie inside the cone around the view axis through the frustum's corners.
struct SkyShows {
    bool sun_disk = true;  // the sun's disk (SKY_SUN_DISK)
    bool moon = true;      // the moon's disk (SKY_MOON; [sky] moon on)
    bool stars = true;     // the star field (SKY_STARS; [sky] stars on and a sky dark enough somewhere)
};
// sun and moon are unit vectors; altitude_m is the camera's above sea level. The stars need a sky
// darker than a tenth of the brightest star, which a sky lit by a sun at or above the horizon never
// is below 20 km (higher up, and from space, the sky darkens), unless the moon eclipses the sun.
SkyShows skyShows(const ViewParams& view, const ViewMatrices& m, const SkySettings& sky, const glm::dvec3& sun,
                  const glm::dvec3& moon, double altitude_m);
// The sky pass's defines for a part of the screen (clip: 0 whole, 1 rays up, -1 rays down) and
// whether it draws the ground.
std::vector<std::string> skyDefines(const SkyShows& shows, bool ground, int clip);

// What the sky LUTs were last built for, and how often (tests and the bench look).
struct SkyLutStats {
    int transmittance_builds = 0, multiscatter_builds = 0, sky_view_builds = 0;
};

// Owns the LUT textures across frames. Create once (needs a GL context); cheap until used.
class SkyAtmosphere {
public:
    SkyAtmosphere();
    ~SkyAtmosphere();
    // Adds the passes this frame needs: the LUT passes whose inputs changed; with
    // aerial_perspective and a depth target, "sky.aerial_volume" (not from space) and
    // "sky.aerial" (haze and extinction over targets.hdr where targets.depth > 0, so after the
    // lighting); then
    // "sky.atmosphere" over targets.hdr where targets.depth (if valid) is still at infinity.
    // Same as addLutPasses() then addScenePasses().
    void addPasses(FrameGraph& graph, const RenderContext& rc, const SkySettings& sky, SceneTargets& targets);
    // The LUT passes of this frame (those whose inputs changed) and this frame's atmosphere block.
    // Passes that read the LUTs before the sky is drawn (water.surface) go between the two calls.
    void addLutPasses(FrameGraph& graph, const RenderContext& rc, const SkySettings& sky);
    // After addLutPasses() in the same graph: addSkyPass() then addAerialPerspective(). The two
    // touch disjoint pixels (depth at infinity, finite depth), so their order changes nothing.
    // The frame draws glass after both (frameAerialVolume(): it fogs itself).
    void addScenePasses(FrameGraph& graph, const RenderContext& rc, const SkySettings& sky, SceneTargets& targets);
    // "sky.atmosphere" over targets.hdr where targets.depth (if valid) is still at infinity.
    void addSkyPass(FrameGraph& graph, const RenderContext& rc, SceneTargets& targets);
    // With aerial_perspective and a depth target: "sky.aerial_volume" (not from space) and
    // "sky.aerial" where targets.depth > 0.
    void addAerialPerspective(FrameGraph& graph, const RenderContext& rc, const SkySettings& sky, SceneTargets& targets);
    // Forces every LUT to be rebuilt next frame (benchmarks).
    void invalidate();
    const SkyLutStats& stats() const { return stats_; }
    // GPU bytes held across frames: the LUTs and uniform blocks (the aerial volume is transient).
    std::size_t memoryBytes() const {
        return std::size_t(uniforms_.size()) + std::size_t(frame_uniforms_.size()) + transmittance_.bytes() +
               multiscatter_.bytes() + sky_view_.bytes();
    }
    GLuint transmittanceTexture() const { return transmittance_.id(); }
    GLuint multiscatterTexture() const { return multiscatter_.id(); }
    GLuint skyViewTexture() const { return sky_view_.id(); }
    // For passes added after addPasses() in the same graph (clouds.shell): this frame's
    // transmittance LUT, and its atmosphere block bound at SKY_BINDING_ATMOSPHERE.
    TextureHandle frameTransmittance() const { return frame_transmittance_; }
    void bindFrameUniforms() const;
    // This frame's sky-view LUT (after addLutPasses) and its atmosphere block's buffer, for
    // passes that bind the block elsewhere (sky/shaders/atmosphere.glsl SKY_ATMOSPHERE_BLOCK).
    TextureHandle frameSkyView() const { return frame_sky_view_; }
    GLuint frameUniformBuffer() const { return frame_uniforms_.id(); }
    // True when this frame's camera is above the atmosphere (the sky-view LUT is then not rebuilt).
    bool frameInSpace() const { return frame_in_space_; }
    // What this frame's sky pass draws of the optional (its variant; counters sky.shows_*).
    const SkyShows& frameShows() const { return frame_shows_; }
    // This frame's aerial-perspective volume, after addAerialPerspective(): for forward surfaces
    // drawn after "sky.aerial" that fog themselves at their own distance (the glass). Invalid
    // without aerial perspective, depth or volume (a camera in space marches per pixel instead).
    const AerialVolume& frameAerialVolume() const { return frame_aerial_; }

private:
    struct Uniforms;
    static void setCamera(Uniforms& u, const AtmosphereParams& p, double altitude_m);
    void addAerialPasses(FrameGraph& graph, const RenderContext& rc, const Uniforms& u, bool in_space,
                         TextureHandle transmittance, TextureHandle multiscatter, SceneTargets& targets);
    void upload(const Uniforms& u);

    gl::Buffer uniforms_;
    gl::Buffer frame_uniforms_;  // this frame's block, written while the graph is built
    TextureHandle frame_transmittance_, frame_multiscatter_, frame_sky_view_;
    std::unique_ptr<Uniforms> frame_u_;  // this frame's block (addLutPasses to addScenePasses)
    bool frame_in_space_ = false;
    bool frame_planet_ground_ = true;  // this frame's [sky] planet_ground (the sky pass's variant)
    SkyShows frame_shows_;             // this frame's sun disk, moon and stars in view (variants)
    AerialVolume frame_aerial_;  // this frame's volume (addAerialPasses)
    gl::Texture transmittance_, multiscatter_, sky_view_;
    std::vector<float> atmosphere_key_;  // settings the transmittance/multi-scattering LUTs were built for
    std::vector<float> view_key_;        // size and steps of the sky-view LUT
    double view_sun_elevation_ = 0.0;    // sun elevation (rad) and altitude the sky-view LUT was built for
    double view_altitude_m_ = -1.0;
    bool atmosphere_valid_ = false, view_valid_ = false;
    SkyLutStats stats_;
};

}  // namespace vista
