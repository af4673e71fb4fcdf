// Shadowed spot lights (000's street lights): the frame's visible spot lights with `shadow on`
// are ranked by their size on screen, the largest [shadows] spot_max_lights each get a square
// tile of one Depth32F atlas, and "shadows.spot_atlas" draws the terrain's casters into them
// from the view's own LOD selection. lights.shade reads the tiles through the light's slot
// (renderer/lighting/shaders/lights.glsl, renderer/shadows/shaders/spot_shadows.glsl). Made only while some spot
// light is shadowed; lights beyond the atlas's tiles go unshadowed and are counted.
//
// A tile holds a reversed-Z perspective view from the light along its axis, with a square
// frustum of full angle 2 * outer (the cone fits inside it) from near n to far f = radius:
//     clip = P * V * (p - light),   depth = n (f - z) / (z (f - n)),  z = distance along the axis
// so depth is 1 at the near plane and 0 at the light's radius; back to distance:
//     z = n f / (n + depth (f - n))                                    (spotLinearDepth)
// A texel of a tile covers 2 z tan(outer) / tile metres at distance z (texelPerMetre).
//
// Priority: the radius in pixels of the light's bounding sphere (renderer/lights.h) seen from
// the camera, r_px = r / sqrt(d^2 - r^2) * (height / 2) / tan(fov_y / 2) (infinite when the
// camera is inside the sphere); ties by light order. Lights whose sphere misses the view
// frustum, smaller than spot_min_screen_px, with radius 0, or cones of 85 deg or wider (no
// single perspective view holds them) are not candidates.
#pragma once

#include "renderer/camera.h"
#include "renderer/frustum.h"
#include "renderer/gl/objects.h"
#include "renderer/lights.h"
#include "renderer/render_context.h"
#include "renderer/shadows/shadow_binding.h"
#include "renderer/shadows/shadow_caster.h"
#include "renderer/shadows/shadow_settings.h"
#include "renderer/shadows/terrain_caster.h"

#include <glm/mat4x4.hpp>

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace vista {


inline constexpr int kMaxSpotShadows = 64;          // SPOT_SHADOW_MAX in spot_shadows.glsl
inline constexpr float kMaxShadowedSpotDeg = 85.0f;  // outer half-angles from here on cast no shadow

struct SpotShadowPick {
    std::uint32_t light = 0;  // index into the lights given to pickShadowedSpots
    double screen_px = 0.0;   // priority: bounding-sphere radius on screen
};

// The lights of `type` with `shadow on` that get a shadow, highest priority first, at most
// max_lights; `candidates` receives how many qualified (so candidates - result.size() went
// unshadowed for want of tiles). The spot atlas and the point-light cubes
// (renderer/shadows/point_shadows.h) share this ranking; spots also need a cone under 85 deg.
std::vector<SpotShadowPick> pickShadowedLights(std::span<const Light> lights, LightType type, const ViewParams& view,
                                               const ViewMatrices& m, int max_lights, float min_screen_px,
                                               std::uint64_t& candidates);
// pickShadowedLights for the spot lights.
std::vector<SpotShadowPick> pickShadowedSpots(std::span<const Light> lights, const ViewParams& view,
                                              const ViewMatrices& m, int max_lights, float min_screen_px,
                                              std::uint64_t& candidates);

// The light's view-projection for its tile, relative to `camera` (world): camera-relative
// positions in, clip out (reversed-Z, near `near_m`, far = radius). Also gives near and far.
struct SpotShadowView {
    glm::dmat4 view_proj{1.0};
    double near_m = 0.0, far_m = 0.0;
    double tan_half = 0.0;  // tan(outer), half the frustum's side at distance 1
};
SpotShadowView spotShadowView(const Light& light, const glm::dvec3& camera);
double spotLinearDepth(double depth, double near_m, double far_m);

// Tiles per atlas side for max_lights tiles: ceil(sqrt(max_lights)).
int spotAtlasTilesPerSide(int max_lights);

// What lights.shade needs to read the atlas.
struct SpotShadowInput {
    TextureHandle atlas;         // written by this frame's shadows.spot_atlas
    GLuint uniforms = 0;         // SpotShadowUniforms
    GLuint compare_sampler = 0;  // depth compare (GEQUAL, reversed-Z), bilinear
    GLuint depth_sampler = 0;    // raw depth, nearest (PCSS blocker search)
    bool valid() const { return atlas.valid(); }
    // Binds the uniforms and the atlas (this pass's texture of `atlas`) with both samplers at the
    // kSpotShadow* bindings lights.glsl reads (HAS_SPOT_SHADOWS); unbind() takes the samplers off again.
    void bind(GLuint texture) const {
        bindShadowInput(kSpotShadowBindings, uniforms, texture, compare_sampler, depth_sampler);
    }
    static void unbind() { unbindShadowInput(kSpotShadowBindings); }
};

struct SpotShadowStats {
    std::uint64_t candidates = 0;   // visible spot lights that may cast a shadow
    std::uint64_t shadowed = 0;     // of them, with a tile drawn this frame (a light with no caster in view needs none)
    std::uint64_t unshadowed = 0;   // candidates left without a tile (the atlas is full)
    std::int64_t caster_instances = 0;  // terrain quadrants drawn over all tiles
    std::size_t memory_bytes = 0;   // atlas + uniforms
};

class SpotShadows {
public:
    // Picks this frame's shadowed lights (lights: world space, this frame's positions) and
    // their views relative to the camera. False when none is shadowed: add no pass.
    bool prepare(const ShadowSettings& s, std::span<const Light> lights, const ViewParams& view,
                 const ViewMatrices& m);
    // The picked lights' frusta (camera-relative): the terrain selection must cover them.
    const std::vector<Frustum>& frusta() const { return frusta_; }
    // The lights picked this frame, highest priority first; pick k draws into tile k.
    const std::vector<SpotShadowPick>& picks() const { return picks_; }

    // "shadows.spot_atlas": every picked light's tile (terrain casters from the current
    // selection, then `extra`, e.g. grass, when valid). Lights with no terrain in their frustum
    // keep slot -1 (see slotOf()).
    SpotShadowInput addPass(FrameGraph& graph, const RenderContext& rc, TerrainCaster* terrain,
                            const ShadowCaster& extra = {});
    // After addPass: the tile of pick k, or -1 when nothing casts into it (read as lit).
    int slotOf(std::size_t pick) const { return pick < slots_.size() ? slots_[pick] : -1; }
    const SpotShadowStats& stats() const { return stats_; }
    // GPU bytes held across frames: the atlas (kept once drawn) and the uniforms.
    std::size_t memoryBytes() const { return atlas_.bytes() + objects_.bytes(); }
    GLuint atlasTexture() const { return atlas_.id(); }
    int tilesPerSide() const { return tiles_per_side_; }

private:
    void allocate(int resolution);

    ShadowSettings settings_;
    glm::dvec3 camera_{0.0};
    std::vector<SpotShadowPick> picks_;
    std::vector<SpotShadowView> views_;
    std::vector<Frustum> frusta_;
    std::vector<int> slots_;
    std::vector<std::vector<TerrainInstance>> instances_;  // per pick, reused
    std::vector<std::size_t> tess_;  // per pick: its first instances drawn tessellated (Terrain::shadowInstances)
    SpotShadowStats stats_;
    int tiles_per_side_ = 1;

    gl::Texture atlas_;
    int atlas_resolution_ = 0;
    gl::Framebuffer atlas_fb_;
    ShadowReadObjects objects_;
};

// "shadows.spot_view": the atlas's tiles as grey levels (near the light bright), for
// [debug] view = spot_atlas; returns the RGBA8 display image.
TextureHandle addSpotAtlasViewPass(FrameGraph& graph, const RenderContext& rc, const SpotShadowInput& shadows,
                                   int tiles_per_side);

}  // namespace vista
