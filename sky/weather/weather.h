// Weather ([weather], sky/weather/weather_model.h for the maths): "weather.rain" draws the drops (rain
// streaks or snow flakes) of a box of field cells around the camera, evaluated in the vertex
// shader (no buffer), and "weather.splash" short-lived splashes on the terrain; both blend
// into scene.hdr after the sky and clouds, depth-tested against scene.depth. The terrain's
// wet darkening is a uniform of terrain.gbuffer (Terrain::setWetness). A frame with [weather]
// off creates no Weather object and adds no pass (app/frame.cpp). "weather.velocity" redraws
// the drops into the frame's motion vectors (addVelocityPass).
#pragma once

#include "renderer/frame_graph.h"
#include "renderer/gl/objects.h"
#include "renderer/lighting/deferred.h"
#include "renderer/pass_timers.h"
#include "renderer/render_context.h"
#include "renderer/scene_targets.h"
#include "sky/clouds/cloud_settings.h"
#include "sky/weather/weather_model.h"
#include "sky/weather/weather_settings.h"
#include "terrain/terrain_settings.h"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace vista {

class Terrain;
struct WeatherRainBlock;  // sky/weather/shaders/weather_rain_block.glsl

// weather.velocity: a drop takes over a pixel's motion vector where its opacity reaches this
// (fainter drops leave the background's, which TAA then follows under them).
inline constexpr float kRainVelocityOpacity = 0.15f;

ProgramList weatherPrograms();

struct WeatherStats {
    std::int64_t drop_cells = 0;         // box cells listed as visible
    std::int64_t drop_candidates = 0;    // quads the rain pass issues (listed cells x drops drawn per cell)
    std::int64_t splash_candidates = 0;  // quads the splash pass issues (0: no splash pass)
    glm::dvec3 camera_velocity{0.0};     // m/s, from the last frame's camera (0 on the first)
};

class Weather {
public:
    // Adds weather.rain (and weather.splash with terrain, rain and splashes on, and the ground
    // under the camera within splash_radius_m) over
    // targets.hdr. light: the sun and sky irradiance at the camera. count: GPU counters
    // "weather.drops" and "weather.splashes" (drawn, in front of the camera).
    void addPasses(FrameGraph& graph, const RenderContext& rc, const WeatherSettings& s, const CloudsSettings& clouds,
                   const SunAndSky& light, const Terrain* terrain, const TerrainSettings& ts, SceneTargets& targets,
                   CounterReadback& counters, bool count);
    // Adds weather.velocity: the drops weather.rain drew this frame (none: velocity unchanged)
    // write their own motion over `velocity` where they are opaque enough
    // (kRainVelocityOpacity). prev_clip_from_relative: renderer/temporal.h previousClipFromRelative.
    TextureHandle addVelocityPass(FrameGraph& graph, const RenderContext& rc, TextureHandle depth, TextureHandle velocity,
                                  const glm::dmat4& prev_clip_from_relative);
    const WeatherStats& stats() const { return stats_; }
    std::size_t memoryBytes() const { return std::size_t(cell_buffer_.size()); }  // GPU bytes held across frames

private:
    // The camera's velocity (m/s) from the previous call: streaks follow the motion relative
    // to the camera. 0 on the first frame, when time did not advance or jumped by over 1 s.
    glm::dvec3 cameraVelocity(const glm::dvec3& position, double time_s);
    void bindCells() const;  // this frame's cells (uploaded by addPasses) for the rain shader

    struct RainDraw {
        std::shared_ptr<const WeatherRainBlock> block;  // weather.rain's uniforms this frame
        GLsizei instances = 0;
        bool snow = false;
    };

    WeatherStats stats_;
    std::optional<RainDraw> rain_;  // this frame's drops, for addVelocityPass; none when no drop is drawn
    double frame_dt_s_ = 0.0;       // time since the previous frame (0: none, or a jump)
    std::vector<std::uint32_t> cells_;  // this frame's visible drop cells (packed offsets)
    gl::Buffer cell_buffer_;            // the same on the GPU, grown as needed
    glm::dvec3 previous_position_{0.0};
    double previous_time_ = 0.0;
    bool has_previous_ = false;
};

}  // namespace vista
