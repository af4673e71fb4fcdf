// One frame of vista: builds the frame graph from the settings (each enabled feature adds
// its passes), compiles and executes it. Owns the long-lived renderer state: shaders,
// transient pool, timers and counter readback.
#pragma once

#include "config/settings.h"
#include "terrain/grass/grass.h"
#include "renderer/meshes/objects.h"
#include "renderer/feature_slot.h"
#include "renderer/frame_graph.h"
#include "renderer/gl_device.h"
#include "renderer/pass_timers.h"
#include "renderer/render_context.h"
#include "renderer/shader_library.h"
#include "renderer/transient_pool.h"
#include "renderer/lighting/lamp_glow.h"
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
#include "terrain/terrain_caster.h"
#include "terrain/water/water.h"

#include <cstdint>
#include <filesystem>
#include <future>
#include <utility>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace vista {

// Every program variant the renderer can request: the concatenation of each feature's
// enumeration (its variant structs' all()). The shader library refuses anything else in the
// tests; the shader test compiles every entry.
ProgramList allPrograms();

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
    // The screen estimators' blue noise (SSAO, shadow kernels: u_time.w) follows the sequence
    // index even without TAA (a caller that averages frames itself: the converged reference);
    // otherwise it moves only while TAA averages it and stays still without (no flicker).
    bool animate_screen_noise = false;
};

struct FrameReport {
    std::vector<std::string> executed, culled;
    std::map<std::string, double> counters;  // CPU-side counters of this frame (terrain.nodes, ...)
};

class FrameRenderer {
public:
    // Needs a current GL context. root is where shaders are found.
    explicit FrameRenderer(std::filesystem::path root);

    // Compiles every listed program (allPrograms()); false with the errors (file:line) on
    // failure. Without it programs compile on first use: captures and tests compile only the
    // variants their scenes use; the window and the benches compile all up front, so no setting
    // changed later and no timed frame waits for a compile.
    bool compilePrograms(std::string& errors);
    // The errors of the programs compiled so far that failed, one program's per line ("": none).
    std::string programErrors() const;

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
    std::unique_ptr<Terrain> releaseTerrain() {  // benches swap terrains
        objects_next_ = {};
        ++terrain_generation_;
        return terrain_.take();
    }

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
    // screen_noise_frame: the blue-noise frame of the screen estimators (SSAO, shadow kernels;
    // u_time.w): the sequence index while TAA averages them, else 0 (a still pattern, no flicker).
    RenderContext context(const ViewParams& view, const Settings& settings, double time_s, glm::dvec2 jitter_px = {},
                          std::uint32_t screen_noise_frame = 0);
    // GPU ms of one full-screen RGBA16F copy at this size (the stats' cost unit).
    double measureReferenceCopy(int width, int height);
    std::uint64_t frameIndex() const { return frame_; }

private:
    struct Frame;  // this frame's settings, camera, context and light (frame.cpp)
    // The casters every shadow pass draws besides the terrain: the culled grass and objects.
    struct Casters {
        BufferHandle blades;        // grass.cull's lists (invalid: no grass this frame)
        BufferHandle object_lists;  // objects.cull's lists (invalid: no objects this frame)
        ShadowCaster caster;        // both, as the shadow passes draw them
    };
    // What the lighting passes sample of the shadow passes.
    struct Shadows {
        SunShadowInput sun;
        SpotShadowInput spot;
        PointShadowInput point;
    };

    // The phases of render(), in order.
    // The sky of this scene time ([sky] time_scale) with every light scaled by the pre-exposure
    // (sky/night_light.h); `at_time` holds the copy when either differs from the input.
    const Settings& settingsAt(const Settings& input, const ViewParams& view, double time_s, Settings& at_time);
    // Camera cut, jitter, the render context and the frame's sun and sky light.
    Frame beginFrame(const Settings& s, const ViewParams& view, double time_s, const FrameRequest& request);
    // Local lights and which of them get a spot tile or a point cube, and the clouds; drops what
    // is off. True: some local light can light a visible point.
    bool prepareFeatures(const Frame& f, FrameReport& report);
    // grass.cull and objects.cull: what the view and the shadow passes draw.
    Casters addCullPasses(FrameGraph& graph, const Frame& f, const FrameRequest& request, FrameReport& report);
    // The sun cascades, the spot atlas and the point cubes (the terrain's selection covers them all).
    Shadows addShadowPasses(FrameGraph& graph, const Frame& f, const Casters& casters, const FrameRequest& request,
                            FrameReport& report);
    // The G-buffer: terrain, grass, objects.
    void addGeometryPasses(FrameGraph& graph, const Frame& f, const Casters& casters, SceneTargets& scene,
                           FrameReport& report);
    // SSAO, cloud shadows, the sun (or moon) and the local lights into the HDR target.
    void addLightingPasses(FrameGraph& graph, const Frame& f, const Shadows& shadows, SceneTargets& scene,
                           const FrameRequest& request);
    // Over the lit scene, back to front: glass beyond the water plane, the sea, the sky and its
    // aerial perspective, the rest of the glass (fogging itself) and the clouds in the order that
    // keeps what is nearer on top, the view under water, rain or snow.
    void addSkyAndTransparentPasses(FrameGraph& graph, const Frame& f, const Casters& casters, const Shadows& shadows,
                                    SceneTargets& scene, const FrameRequest& request, FrameReport& report);
    // What glass is lit by: the sun and sky, the local lights' forward lists, the sun's cascades.
    ForwardLight forwardLight(const Frame& f, const Shadows& shadows);
    // "lights.glow" over the fogged scene, when some light glows (else the feature is released).
    void addLampGlowPass(FrameGraph& graph, const Frame& f, SceneTargets& scene, FrameReport& report);
    // Motion vectors (the camera's, then the sea's and the grass's own) and TAA (and the velocity
    // readback a test asks for).
    void addTemporalPasses(FrameGraph& graph, const Frame& f, const Casters& casters, SceneTargets& scene,
                           const FrameRequest& request, FrameReport& report);
    // What a test reads of the scene besides the image: non-finite pixels, light heat, depth.
    void addSceneReadbacks(FrameGraph& graph, const Frame& f, const SceneTargets& scene, const FrameRequest& request);
    // The post chain, or the debug view in its place: the image shown.
    TextureHandle addPostAndDebugPasses(FrameGraph& graph, const Frame& f, const SceneTargets& scene,
                                        const Shadows& shadows, const FrameRequest& request);
    // The captured images and the window's blit.
    void addOutputPasses(FrameGraph& graph, const RenderContext& rc, const SceneTargets& scene, TextureHandle display,
                         const FrameRequest& request);
    // Compiles and runs the graph; the frame's timers, counters and pool move on.
    void execute(FrameGraph& graph, const FrameRequest& request, FrameReport& report);
    // Memory per feature and the sky's counters, after the frame.
    void reportAfterFrame(const Frame& f, FrameReport& report) const;
    // Applies f to every feature slot (memory counters, the renderer's total).
    template <class F>
    void forEachFeature(F&& f) const;

    // Selects the terrain (widened for shadow casters when the sun casts shadows) and adds the
    // "shadows.cascadeN" passes (drawing `extra`, the grass, too); returns what lighting.sun
    // samples (invalid: no sun shadows).
    SunShadowInput addTerrainAndShadowPasses(FrameGraph& graph, const RenderContext& rc, const Settings& s,
                                             const ViewParams* fit_view, FrameReport& report, const ShadowCaster& extra);
    // Loads and places [objects] on the terrain (drops the Objects when nothing is placed).
    void prepareObjects(const Settings& s, InputErrors& errors);
    // A camera-local placement (rules too dense for the whole terrain) placed again around camera
    // once it has moved far enough from the last one's centre; true when it was.
    bool placeLocalObjects(const Settings& s, glm::dvec3 camera);
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
    FeatureSlot<Terrain> terrain_{"terrain.memory_bytes"};
    TerrainShadowCaster terrain_caster_;  // the terrain as the shadow passes draw it (bound each frame)
    FeatureSlot<SkyAtmosphere> sky_{"sky.memory_bytes"};  // LUTs kept across frames
    FeatureSlot<Clouds> clouds_{"clouds.memory_bytes"};  // empty while [clouds] draws nothing
    FeatureSlot<LocalLights> local_lights_{"lights.memory_bytes"};  // empty while the scene has no local lights
    FeatureSlot<LampGlow> lamp_glow_{"lights.glow_memory_bytes"};  // empty while no light glows (clear air, no lights)
    std::pair<bool, float> light_water_{false, 0.0f};  // [water] enabled, level_m the lights were placed over
    double pre_exposure_ = 1.0;  // this frame's (sky/night_light.h), set by render()
    FeatureSlot<SunShadows> sun_shadows_{"shadows.memory_bytes"};  // empty while the sun casts no shadows
    FeatureSlot<SpotShadows> spot_shadows_{"shadows.spot_memory_bytes"};  // empty while no spot light is shadowed
    FeatureSlot<PointShadows> point_shadows_{"shadows.point_memory_bytes"};  // empty while no point light is shadowed
    std::vector<Frustum> light_shadow_frusta_;   // this frame's spot and point shadow views (the terrain selection covers them)
    FeatureSlot<Grass> grass_{"grass.memory_bytes"};  // empty while grass is off (no buffers)
    FeatureSlot<Weather> weather_{"weather.memory_bytes"};  // empty while [weather] is off (keeps the last camera for streaks)
    FeatureSlot<Water> water_{"water.memory_bytes"};  // empty while [water] is off (no buffers)
    FeatureSlot<Objects> objects_{"objects.memory_bytes"};  // empty while [objects] places nothing (no buffers)
    ObjectsSettings objects_placed_for_;  // the lists objects_ was placed from (while it exists)
    bool objects_local_ = false;          // placed around the camera, not over the whole terrain
    glm::dvec2 objects_centre_{0.0};      // ... around this point (world x, z)
    double objects_reach_m_ = 0.0;        // ... for this [objects] max_distance_m
    // The next camera-local placement, computed on another thread once the camera is half way to
    // the margin (around objects_next_centre_ for objects_next_reach_m_). Declared after the
    // terrain it reads: destroyed (waited for) first; prepare() and a new terrain wait for it too.
    std::future<std::vector<ObjectPlacement>> objects_next_;
    glm::dvec2 objects_next_centre_{0.0};
    double objects_next_reach_m_ = 0.0;
    PostChain postfx_;                    // post chain state (adapted exposure)
    BlueNoiseTexture blue_noise_;         // made once; bound to binding::kBlueNoise every frame
    FeatureSlot<TemporalAA> taa_{nullptr};  // empty while [postfx.taa] is off (its bytes count as postfx's)
    ViewParams last_view_;                // the previous frame's camera, for camera-cut detection
    double last_time_s_ = 0.0;
    bool has_last_view_ = false;
    std::uint64_t temporal_index_ = 0;    // frames since resetHistory(): the jitter's index without a sequence_frame
    std::uint64_t sequence_index_ = 0;    // this frame's jitter and blue-noise index (render(), FrameRequest::sequence_frame)
    SkyLightingCache sky_lighting_;       // sun and sky light for the lighting passes (CPU)
    TerrainSettings terrain_source_;  // as given, to notice changes
    bool terrain_failed_ = false;     // do not retry a bad heightmap every frame
    std::uint64_t terrain_generation_ = 0;  // counts terrain swaps (kept sun cascades show the old one)
    std::string shadow_caster_key_;   // what the kept sun cascades were drawn from (casterKey in frame.cpp)
};

}  // namespace vista
