// Local (point and spot) lights of a scene on the GPU: the long-lived light buffers and culling
// structures, and the passes that light the G-buffer with them.
//
// Per frame (prepare): the [lights] entries are collected when they change, animated, and
// uploaded camera-relative; the hashed method's world-space octree (renderer/lighting/light_hash.h) is
// updated incrementally. Passes (addPasses):
//   lights.cull   (tiled, clustered) compute: per-tile / per-cluster light lists on the GPU, no
//                 readback (renderer/lighting/shaders/light_cull.glsl);
//   lights.shade  full screen: each lit pixel shades its candidate lights, added to the HDR target
//                 (renderer/lighting/shaders/light_shade.glsl). After lights.cull it is an indirect draw
//                 with no instance unless some tile's list is non-empty: a frame whose lights
//                 light no pixel shades nothing.
// A scene with no local lights (or [lights] enabled = false) makes no LocalLights at all: no
// passes, no buffers.
//
// GPU layouts (std430, renderer/lighting/shaders/lights.glsl):
//   lights    (tiled, clustered: only the lights whose bounding sphere meets the view frustum,
//             in light order; naive, hashed: all) 4 vec4 per light: camera-relative position + radius; colour * intensity + spot cone
//             scale; unit spot axis + cone offset (renderer/lights.h SpotCone; point: 0, 1); spot shadow tile, point shadow cube (-1: none), 0, 0.
//   spheres   vec4 per light: view-space bounding-sphere centre + radius (culling only).
//   cells     uvec2 (offset, count) per tile (tiled) or per cluster (clustered: index tile.x +
//             tiles_x (tile.y + tiles_y slice)); count 0xFFFFFFFF = overflow, shade every light.
//   indices   tiled, clustered: a pool of lists filled by an atomic counter, sized from the
//             demand read back (64 entries per tile to start); hashed: LightHash::indices().
//   hash      for each level l in 0..20, 16 words: node table l (values base, offsets base, mbar,
//             rbar^3, Q, 0, 0, 0) and data table l (the same); then the tables: node values one
//             word per slot, data values two words (offset, count), offsets one word per entry.
#pragma once

#include "renderer/gl/objects.h"
#include "renderer/lighting/cluster_grid.h"
#include "renderer/lighting/light_hash.h"
#include "renderer/lighting/light_settings.h"
#include "renderer/lights.h"
#include "renderer/pass_timers.h"
#include "renderer/render_context.h"
#include "renderer/scene_targets.h"
#include "renderer/shadows/point_shadows.h"
#include "renderer/shadows/spot_shadows.h"

#include <glm/vec4.hpp>

#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace vista {

using GroundHeight = std::function<double(double x_m, double z_m)>;

// The lights of [lights]: explicit entries, then each volume's; volumes with `ground` put their
// lights that high above ground(x, z) (above the box's lower y without a ground function), and
// so do explicit lights with `ground` (they keep their y without a ground function). Every light
// comes out in HDR units with its radius resolved: resolveUnits(light, lux_per_hdr_unit,
// s.cutoff_lux) (lights.h; lux_per_hdr_unit is sky/night_light.h luxPerHdrUnit(sun_illuminance)).
std::vector<Light> collectSceneLights(const LightsSettings& s, const GroundHeight& ground, double lux_per_hdr_unit);

// Longest list a tile or cluster keeps (the culling pass's shared-memory list).
inline constexpr int kMaxLightsPerCell = 4096;
// Lights one draw shades of a range (lights.glsl chunkOf): "every light" (naive, overflowed
// cells) or a list; longer ranges take more draws (LocalLights::chunks()), deferred and forward.
// Below llvmpipe's 65,535 loop iterations per shader invocation, with room for the other loops
// of the shader (spot shadow filter taps, the sea's waves and reflection march).
inline constexpr std::uint32_t kLightChunk = 32768;

// Lights the settings describe (explicit entries, then volumes), before animation. 0 when
// [lights] is disabled.
std::uint64_t sceneLightCount(const LightsSettings& s);

// Whether a sphere (camera-relative centre, radius in m) meets the view frustum (no far plane),
// padded by 1e-4 of the radius and of the distance so that rounding never drops a light.
bool sphereMeetsView(const glm::dvec3& center_rel, double radius, const ViewParams& view, const ViewMatrices& m);

// Every variant of "lights.cull" and "lights.shade" (light_variants.h, for FrameRenderer::allPrograms()).
ProgramList localLightPrograms();

struct LocalLightStats {
    std::uint64_t count = 0;        // lights this frame
    double max_radius_m = 0.0;      // largest radius of them (after resolveUnits: auto radii resolved)
    std::uint64_t visible = 0;      // of them, on the GPU: tiled and clustered keep those whose sphere meets the view frustum
    std::uint64_t skipped = 0;      // tiled, clustered: in the frustum but below min_screen_px on screen (not on the GPU)
    double build_ms = 0.0;          // CPU: collect, animate, hash update, upload
    std::size_t memory_bytes = 0;   // GPU buffers held
    LightCulling method = LightCulling::Clustered;  // the method used (hashed falls back to clustered when it cannot build)
    int tiles_x = 0, tiles_y = 0, slices = 0;
    std::uint64_t overflow = 0;     // overflowed cells, as last read back (a few frames late)
    std::uint64_t longest_range = 0;  // most lights one pixel's range can hold: the lights on the GPU (hashed: the longest list)
    std::uint32_t chunks = 1;       // draws of kLightChunk lights that cover longest_range (each lit pass draws this many)
    LightHashStats hash;            // hashed only
    std::size_t hash_upload_bytes = 0;  // hashed: bytes of tables and index list uploaded this frame
};

struct LightPassOptions {
    bool count = false;  // lights.evaluations and lights.exact counters
    bool heat = false;   // targets.light_heat for the lights debug view
    bool forward = false;  // lists also cover transparent depths (a forward pass follows)
    const SpotShadowInput* spot_shadows = nullptr;  // this frame's spot shadow atlas (see setShadowSlots())
    const PointShadowInput* point_shadows = nullptr;  // this frame's point shadow cubes (see setPointShadowSlots())
};

class LocalLights {
public:
    LocalLights();
    ~LocalLights();
    LocalLights(const LocalLights&) = delete;
    LocalLights& operator=(const LocalLights&) = delete;

    // The CPU side of a frame: lights at time_s, buffers for the view. False when no light can
    // reach a visible point (none at all, or, for tiled and clustered, none whose bounding
    // sphere meets the view frustum): then add no passes.
    // ground (may be empty) gives the terrain height (m) at world x, z for volumes with `ground`.
    // lux_per_hdr_unit converts candela and lumens (sky/night_light.h luxPerHdrUnit of the
    // scene's sun_illuminance; collectSceneLights). radiance_scale multiplies every light's
    // colour * intensity (the frame's pre-exposure).
    bool prepare(const LightsSettings& s, const ViewParams& view, const ViewMatrices& matrices, double time_s,
                 const GroundHeight& ground, double lux_per_hdr_unit, float radiance_scale = 1.0f);
    // Needs targets.depth, .albedo, .normal; adds to targets.hdr (and makes targets.light_heat).
    void addPasses(FrameGraph& graph, const RenderContext& rc, SceneTargets& targets, CounterReadback& counters,
                   const LightPassOptions& options);
    // After prepare(): gives lights() [pick.light] the atlas tile slotOf(k) of each pick k (-1:
    // unshadowed); every other light stays unshadowed this frame.
    void setShadowSlots(const SpotShadows& shadows);
    // The same for the shadowed point lights' cubes (renderer/shadows/point_shadows.h).
    void setPointShadowSlots(const PointShadows& shadows);
    const LocalLightStats& stats() const { return stats_; }
    std::size_t memoryBytes() const { return stats_.memory_bytes; }  // GPU buffers held
    // Forward passes (transparent surfaces) drawn after this frame's lights.cull: compile with
    // the define (LIGHTS_NAIVE, _TILED, _CLUSTERED or _HASHED), include
    // renderer/lighting/shaders/lights.glsl and call forwardLocalLights(); bind the buffers first. With
    // tiled or clustered culling the frame must have asked for LightPassOptions::forward.
    // A forward surface is shaded in chunks() draws: the first with chunk (0, kLightChunk), then
    // for k = 1 .. chunks() - 1 (k kLightChunk, kLightChunk), added where its depth is equal.
    const char* define() const;
    void bindForForward() const;
    std::uint32_t chunks() const { return stats_.chunks; }
    std::span<const Light> lights() const { return animated_; }  // this frame's, world space

private:
    struct GpuBuffer {
        gl::Buffer buffer;
        void upload(const void* data, std::size_t bytes, std::string_view name);  // grows, never shrinks
        void reserve(std::size_t bytes, std::string_view name);
    };
    void uploadHash();
    // Writes slot_of(k) into component `component` of the shadow vec4 of each pick's light.
    void writeShadowSlots(std::span<const SpotShadowPick> picks, const std::function<int(std::size_t)>& slot_of,
                          int component);
    void readOverflow();

    std::vector<NamedLight> lights_;            // the entries the lights were collected from
    std::vector<NamedLightVolume> volumes_;
    bool had_ground_ = false, collected_ = false;
    double lux_per_hdr_unit_ = 0.0;
    float cutoff_lux_ = 0.0f;
    std::vector<Light> base_, animated_;
    LightAnimation animation_;
    std::vector<Sphere> world_spheres_;
    std::vector<glm::vec4> spheres_scratch_, light_scratch_;  // per-frame upload data, memory kept
    std::vector<std::uint32_t> order_scratch_;
    LightHash hash_;
    LightHashSettings hash_settings_;
    std::vector<std::uint32_t> hash_words_;  // the tables as uploaded (header + tables)
    int hash_levels_uploaded_ = -1;
    bool hash_built_ = false, hash_uploaded_ = false;
    std::string hash_message_;
    ClusterGrid grid_;
    int max_lights_per_cell_ = 0;  // for the overflow warning
    GpuBuffer lights_buf_, spheres_buf_, cells_buf_, indices_buf_, hash_buf_, grid_ubo_, pool_buf_;
    gl::Buffer shade_draw_;  // tiled, clustered: lights.shade's indirect draw; the cull pass sets its instance count
    std::array<gl::Buffer, 3> overflow_ring_;
    std::array<GLsync, 3> overflow_fence_{};
    std::size_t pool_entries_ = 0;    // list pool capacity (tiled, clustered)
    std::uint32_t pool_demand_ = 0;   // entries the pool was asked for, as last read back
    std::size_t write_slot_ = 0;  // overflow ring slot the next cull pass writes
    bool overflow_warned_ = false;
    bool chunks_warned_ = false;
    LocalLightStats stats_;
};

}  // namespace vista
