// Weather ([weather], sky/weather/weather_model.h for the maths): "weather.rain" draws the drops (rain
// streaks or snow flakes) of a box of field cells around the camera, evaluated in the vertex
// shader (no buffer), and "weather.splash" short-lived splashes on the terrain; both blend
// into scene.hdr after the sky and clouds, depth-tested against scene.depth. The terrain's
// wet darkening is a uniform of terrain.gbuffer (Terrain::setWetness). A frame with [weather]
// off creates no Weather object and adds no pass (app/frame.cpp).
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

#include <glm/vec3.hpp>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace vista {

class Terrain;

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
    const WeatherStats& stats() const { return stats_; }
    std::size_t memoryBytes() const { return std::size_t(cell_buffer_.size()); }  // GPU bytes held across frames

private:
    // The camera's velocity (m/s) from the previous call: streaks follow the motion relative
    // to the camera. 0 on the first frame, when time did not advance or jumped by over 1 s.
    glm::dvec3 cameraVelocity(const glm::dvec3& position, double time_s);

    WeatherStats stats_;
    std::vector<std::uint32_t> cells_;  // this frame's visible drop cells (packed offsets)
    gl::Buffer cell_buffer_;            // the same on the GPU, grown as needed
    glm::dvec3 previous_position_{0.0};
    double previous_time_ = 0.0;
    bool has_previous_ = false;
};

}  // namespace vista
