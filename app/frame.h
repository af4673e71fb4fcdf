// One frame of vista: builds the frame graph from the settings (each enabled feature adds
// its passes), compiles and executes it. Owns the long-lived renderer state: shaders,
// transient pool, timers and counter readback.
#pragma once

#include "config/settings.h"
#include "terrain/grass/grass.h"
#include "renderer/meshes/objects.h"
#include "renderer/frame_graph.h"
#include "renderer/gl_device.h"
#include "renderer/pass_timers.h"
#include "renderer/render_context.h"
#include "renderer/shader_library.h"
#include "renderer/transient_pool.h"
#include "renderer/lighting/local_lights.h"
#include "postfx/chain.h"
#include "postfx/taa.h"
#include "renderer/blue_noise.h"
#include "renderer/shadows/point_shadows.h"
#include "renderer/shadows/spot_shadows.h"
#include "renderer/shadows/sun_shadows.h"
#include "sky/atmosphere.h"
#include "sky/clouds/clouds.h"
#include "sky/sky_lighting.h"
#include "sky/weather/weather.h"
#include "terrain/terrain.h"
#include "terrain/water/water.h"

#include <cstdint>
#include <filesystem>
#include <utility>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace vista {

struct ProgramKey {
    std::string file;
    std::vector<std::string> defines;
};

// Every program variant the renderer can use: compiled up front and by the tests.
std::vector<ProgramKey> allPrograms();

// What the caller wants out of a frame besides rendering it.
struct FrameRequest {
    bool present = false;                          // blit to the default framebuffer (window)
    std::vector<unsigned char>* capture_ldr = nullptr;  // RGBA8 sRGB, top row first ("capture.readback")
    std::vector<std::uint16_t>* capture_hdr = nullptr;  // RGBA half floats (linear, the scene's HDR target before
                                                        // the post chain), top row first; with capture_ldr too
                                                        // it is read by "capture.readback_hdr")
    bool count_nonfinite = false;                  // NaN/Inf pixels of the HDR target
    bool count_lights = false;                     // lights.evaluations and lights.exact (GPU atomics)
    bool count_grass = false;                      // grass.blades (blades drawn, GPU counter)
    bool count_objects = false;                    // objects.instances, objects.triangles (drawn, GPU counters)
    bool count_weather = false;                    // weather.drops, weather.splashes (drawn, GPU counters)
    bool forward_lights = false;                   // light lists also for transparent (forward) surfaces
    std::vector<float>* light_heat = nullptr;      // local lights evaluated per pixel, RGBA floats (R used), top row
                                                   // first ("lights.heat_readback"); untouched without local lights
    std::vector<float>* depth = nullptr;           // reversed-Z depth (0: sky), one float a pixel, top row first
                                                   // ("capture.depth_readback"; bench lights classes pixels by it)
    std::vector<float>* velocity = nullptr;        // motion vectors (renderer/velocity.h), RGBA floats, top row first
                                                   // ("temporal.velocity_readback"; adds "temporal.velocity" without TAA)
    std::string* graph_dot = nullptr;              // receives the compiled graph (Graphviz)
    const ViewParams* shadow_fit_view = nullptr;   // fit the sun cascades to this camera, not the view's (bench shadows)
    // The frame's index in its sequence (capture: the path frame k, negative for settle frames
    // before the path's start): TAA's jitter and the blue noise's frame index come from it, so a
    // frame is the same whichever run renders it (docs/farm.md). Unset: frames since the last
    // resetHistory().
    std::optional<std::int64_t> sequence_frame;
};

struct FrameReport {
    std::vector<std::string> executed, culled;
    std::map<std::string, double> counters;  // CPU-side counters of this frame (terrain.nodes, ...)
};

class FrameRenderer {
public:
    // Needs a current GL context. root is where shaders are found.
    explicit FrameRenderer(std::filesystem::path root);

    // Compiles every program; false with the errors (file:line) on failure.
    bool compilePrograms(std::string& errors);

    // Loads (or drops) what the settings need: the terrain when [terrain] is enabled. Cheap
    // when nothing changed; call before rendering and after settings change. Returns the
    // problems (bad heightmap ...); the feature is then left out.
    InputErrors prepare(const Settings& settings);
    Terrain* terrain() { return terrain_.get(); }
    SkyAtmosphere* sky() { return sky_.get(); }  // null until a frame with [sky] enabled
    Clouds* clouds() { return clouds_.get(); }   // null unless the last frame drew clouds
    LocalLights* localLights() { return local_lights_.get(); }  // null without local lights
    SunShadows* sunShadows() { return sun_shadows_.get(); }     // null while the sun casts no shadows
    SpotShadows* spotShadows() { return spot_shadows_.get(); }  // null while no spot light is shadowed
    PointShadows* pointShadows() { return point_shadows_.get(); }  // null while no point light is shadowed
    Grass* grass() { return grass_.get(); }  // null while [grass] or [terrain] is off
    Weather* weather() { return weather_.get(); }  // null while [weather] is off
    Water* water() { return water_.get(); }  // null while [water] is off
    Objects* objects() { return objects_.get(); }  // null while [objects] places nothing (or no terrain)
    const PostChain& postfx() const { return postfx_; }
    // Uses a terrain made elsewhere (benchmarks): prepare() keeps it while the settings
    // name the same source.
    void adoptTerrain(std::unique_ptr<Terrain> terrain);
    std::unique_ptr<Terrain> releaseTerrain() { return std::move(terrain_); }  // benches swap terrains

    FrameReport render(const Settings& settings, const ViewParams& view, double time_s, const FrameRequest& request);
    // Forgets every temporal state, so the next frame renders as the first frame of a fresh
    // renderer would: the post chain's history (exposure, autofocus, motion blur, lens flare),
    // weather's previous camera, TAA's and the clouds' accumulation and the camera that cut
    // detection compares with. Captures call it before the settle frames of each run of written
    // frames (app/capture.cpp), which is what makes a frame the same whichever shard renders it;
    // every new kind of history must be reset here too (docs/temporal.md, docs/farm.md).
    void resetHistory();
    const TemporalAA* taa() const { return taa_.get(); }  // null while [postfx.taa] is off

    ShaderLibrary& shaders() { return shaders_; }
    PassTimers& timers() { return timers_; }
    CounterReadback& counters() { return counters_; }
    const TransientPool& pool() const { return pool_; }
    // Destroys the pool's unused transient objects now instead of after a few idle frames, so
    // the next frame's "gpu.memory_bytes" holds only what it needs (tests of leaving features out).
    void trimTransients() { pool_.clear(); }
    // GPU bytes the renderer holds: the transient pool, every feature's long-lived objects and
    // the frame's own buffers. Per feature in the frame's "FEATURE.memory_bytes" counters.
    std::size_t gpuMemoryBytes() const;
    // jitter_px: the TAA's sub-pixel shift of the projection this frame (none by default).
    RenderContext context(const ViewParams& view, const Settings& settings, double time_s, glm::dvec2 jitter_px = {});
    // GPU ms of one full-screen RGBA16F copy at this size (the stats' cost unit).
    double measureReferenceCopy(int width, int height);
    std::uint64_t frameIndex() const { return frame_; }

private:
    // Selects the terrain (widened for shadow casters when the sun casts shadows) and adds the
    // "shadows.cascadeN" passes (drawing `extra`, the grass, too); returns what lighting.sun
    // samples (invalid: no sun shadows).
    SunShadowInput addTerrainAndShadowPasses(FrameGraph& graph, const RenderContext& rc, const Settings& s,
                                             const ViewParams* fit_view, FrameReport& report, const ShadowCaster& extra);
    // Loads and places [objects] on the terrain (drops the Objects when nothing is placed).
    void prepareObjects(const Settings& s, InputErrors& errors);
    // This frame's local lights (false: none can light a visible point, add no light pass).
    bool prepareLocalLights(const RenderContext& rc, const Settings& s, FrameReport& report);
    // The shadowed spot lights among them (false: none; then spot_shadows_ is reset).
    bool prepareSpotShadows(const RenderContext& rc, const Settings& s);
    // "shadows.spot_atlas" (terrain and `extra`), the lights' tiles and the shadows.spot_* counters.
    SpotShadowInput addSpotShadowPass(FrameGraph& graph, const RenderContext& rc, const Settings& s,
                                      const ShadowCaster& extra, FrameReport& report);
    // The shadowed point lights (false: none; then point_shadows_ is reset).
    bool preparePointShadows(const RenderContext& rc, const Settings& s);
    // "shadows.point_cubes" (terrain and `extra`), the lights' cubes and the shadows.point_* counters.
    PointShadowInput addPointShadowPass(FrameGraph& graph, const RenderContext& rc, const Settings& s,
                                        const ShadowCaster& extra, FrameReport& report);

    ShaderLibrary shaders_;
    GlDevice device_;
    TransientPool pool_{device_};
    PassTimers timers_;
    CounterReadback counters_;
    gl::VertexArray empty_vao_;
    gl::Buffer frame_uniforms_;
    std::uint64_t frame_ = 0;
    std::unique_ptr<Terrain> terrain_;
    std::unique_ptr<SkyAtmosphere> sky_;  // LUTs kept across frames
    std::unique_ptr<Clouds> clouds_;      // null while [clouds] draws nothing
    std::unique_ptr<LocalLights> local_lights_;  // null while the scene has no local lights
    std::pair<bool, float> light_water_{false, 0.0f};
    double pre_exposure_ = 1.0;  // this frame's (sky/night_light.h), set by render()  // [water] enabled, level_m the lights were placed over
    std::unique_ptr<SunShadows> sun_shadows_;    // null while the sun casts no shadows
    std::unique_ptr<SpotShadows> spot_shadows_;  // null while no spot light is shadowed
    std::unique_ptr<PointShadows> point_shadows_;  // null while no point light is shadowed
    std::vector<Frustum> light_shadow_frusta_;   // this frame's spot and point shadow views (the terrain selection covers them)
    std::unique_ptr<Grass> grass_;        // null while grass is off (no buffers)
    std::unique_ptr<Weather> weather_;    // null while [weather] is off (keeps the last camera for streaks)
    std::unique_ptr<Water> water_;        // null while [water] is off (no buffers)
    std::unique_ptr<Objects> objects_;    // null while [objects] places nothing (no buffers)
    PostChain postfx_;                    // post chain state (adapted exposure)
    BlueNoiseTexture blue_noise_;         // made once; bound to binding::kBlueNoise every frame
    std::unique_ptr<TemporalAA> taa_;     // null while [postfx.taa] is off
    ViewParams last_view_;                // the previous frame's camera, for camera-cut detection
    double last_time_s_ = 0.0;
    bool has_last_view_ = false;
    std::uint64_t temporal_index_ = 0;    // frames since resetHistory(): the jitter's index without a sequence_frame
    std::uint64_t sequence_index_ = 0;    // this frame's jitter and blue-noise index (render(), FrameRequest::sequence_frame)
    SkyLightingCache sky_lighting_;       // sun and sky light for the lighting passes (CPU)
    TerrainSettings terrain_source_;  // as given, to notice changes
    bool terrain_failed_ = false;     // do not retry a bad heightmap every frame
};

}  // namespace vista
