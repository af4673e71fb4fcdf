// Shadowed point lights (the seed's shadowed point lights, issue 28 part 6): the frame's visible
// point lights with `shadow on` are ranked like the spot atlas's lights (pickShadowedLights in
// renderer/shadows/spot_shadows.h: bounding-sphere radius on screen, largest first), the first
// [shadows] point_max_lights each get a depth cube (six faces) of one cube-map array, and
// "shadows.point_cubes" draws the terrain's casters (from the view's own LOD selection) and the
// `extra` casters (grass, objects: whatever the spot atlas draws) into them. lights.shade reads a
// light's cube through its slot (renderer/lighting/shaders/lights.glsl,
// renderer/shadows/shaders/point_shadows.glsl). Made only while some point light is shadowed; the
// lights beyond the cubes go unshadowed and are counted.
//
// Face f of a cube (GL's layer order +X -X +Y -Y +Z -Z) is a reversed-Z perspective view of
// 90 deg from the light along that axis, with GL's cube-map up vectors (so a direction looks up
// the texel the face was drawn into), near n to far f = radius:
//     depth = n (f - z) / (z (f - n)),  z = the largest |component| of (p - light)   (pointFaceDepth)
// so a lookup needs no matrix: the hardware picks the face by the same largest component. A
// texel of a face covers 2 z / resolution metres at that z.
#pragma once

// spot_shadows.h brings the light types and Frustum.
#include "renderer/camera.h"
#include "renderer/gl/objects.h"
#include "renderer/render_context.h"
#include "renderer/shadows/shadow_binding.h"
#include "renderer/shadows/shadow_caster.h"
#include "renderer/shadows/shadow_settings.h"
#include "renderer/shadows/terrain_caster.h"
#include "renderer/shadows/spot_shadows.h"

#include <glm/mat4x4.hpp>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace vista {


inline constexpr int kMaxPointShadows = 16;  // POINT_SHADOW_MAX in point_shadows.glsl
inline constexpr int kCubeFaces = 6;

// A light's six face views relative to `camera` (world): camera-relative positions in, clip out.
struct PointShadowView {
    std::array<glm::dmat4, kCubeFaces> view_proj{};
    glm::dvec3 position{0.0};  // the light, camera-relative
    double near_m = 0.0, far_m = 0.0;
};
PointShadowView pointShadowView(const Light& light, const glm::dvec3& camera);
// The depth face `d` (a point minus the light) holds for an unoccluded point: see the header.
double pointFaceDepth(const glm::dvec3& d, double near_m, double far_m);
// The cube face a direction falls on (0..5: +X -X +Y -Y +Z -Z), as GL picks it.
int pointCubeFace(const glm::dvec3& d);

// What lights.shade needs to read the cubes.
struct PointShadowInput {
    TextureHandle cubes;         // written by this frame's shadows.point_cubes
    GLuint uniforms = 0;         // PointShadowUniforms
    GLuint compare_sampler = 0;  // depth compare (GEQUAL, reversed-Z), bilinear
    GLuint depth_sampler = 0;    // raw depth, nearest (PCSS blocker search, debug view)
    bool valid() const { return cubes.valid(); }
    // Binds the uniforms and the cubes (this pass's texture of `cubes`) with both samplers at the
    // kPointShadow* bindings lights.glsl reads (HAS_POINT_SHADOWS); unbind() takes the samplers off again.
    void bind(GLuint texture) const {
        bindShadowInput(kPointShadowBindings, uniforms, texture, compare_sampler, depth_sampler);
    }
    static void unbind() { unbindShadowInput(kPointShadowBindings); }
};

struct PointShadowStats {
    std::uint64_t candidates = 0;   // visible point lights that may cast a shadow
    std::uint64_t shadowed = 0;     // of them, with a cube drawn this frame (a light with no caster near it needs none)
    std::uint64_t unshadowed = 0;   // candidates left without a cube (all point_max_lights taken)
    std::int64_t caster_instances = 0;  // terrain quadrants drawn over all faces
};

class PointShadows {
public:
    PointShadows();
    PointShadows(const PointShadows&) = delete;
    PointShadows& operator=(const PointShadows&) = delete;
    // Picks this frame's shadowed point lights and their face views relative to the camera.
    // False when none is shadowed: add no pass.
    bool prepare(const ShadowSettings& s, std::span<const Light> lights, const ViewParams& view,
                 const ViewMatrices& m);
    // Six frusta per picked light (camera-relative): the terrain selection must cover them.
    const std::vector<Frustum>& frusta() const { return frusta_; }
    const std::vector<SpotShadowPick>& picks() const { return picks_; }

    // "shadows.point_cubes": every picked light's six faces (terrain from the current selection,
    // then `extra` when valid). Lights with no terrain near them keep slot -1 (read as lit).
    PointShadowInput addPass(FrameGraph& graph, const RenderContext& rc, TerrainCaster* terrain,
                             const ShadowCaster& extra = {});
    // After addPass: the cube of pick k, or -1.
    int slotOf(std::size_t pick) const { return pick < slots_.size() ? slots_[pick] : -1; }
    const PointShadowStats& stats() const { return stats_; }
    // GPU bytes held across frames: the cubes (kept once drawn) and the uniforms.
    std::size_t memoryBytes() const { return cubes_.bytes() + objects_.bytes(); }
    int cubes() const { return cube_count_; }  // cubes allocated (point_max_lights)

private:
    void allocate(int resolution, int cubes);

    ShadowSettings settings_;
    glm::dvec3 camera_{0.0};
    std::vector<SpotShadowPick> picks_;
    std::vector<PointShadowView> views_;
    std::vector<Frustum> frusta_;
    std::vector<int> slots_;
    std::vector<std::vector<TerrainInstance>> instances_;  // per pick and face (6 k + f), reused
    std::vector<std::size_t> tess_;  // per pick and face: its first instances drawn tessellated (Terrain::shadowInstances)
    PointShadowStats stats_;

    gl::Texture cubes_;
    int resolution_ = 0, cube_count_ = 0;
    gl::Framebuffer fb_;
    ShadowReadObjects objects_;
};

// "shadows.point_view": each shadowed light's cube as a row of its six faces in grey levels (near
// the light bright), for [debug] view = point_shadows; returns the RGBA8 display image.
TextureHandle addPointShadowViewPass(FrameGraph& graph, const RenderContext& rc, const PointShadowInput& shadows,
                                     int cubes);

}  // namespace vista
