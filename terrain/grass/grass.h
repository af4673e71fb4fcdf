// Grass: instanced, wind-bent blades around the camera, culled on the GPU into indirect draws.
// "grass.cull" (compute) places and culls the candidates of the placement box
// (terrain/grass/grass_placement.h) into a near and a far blade list; "grass.gbuffer" draws them into
// the G-buffer after "terrain.gbuffer", so the deferred lighting lights them. Only exists while
// [grass] and [terrain] are enabled (the frame drops it otherwise: no pass, no buffers).
#pragma once

#include "renderer/frame_graph.h"
#include "renderer/gl/objects.h"
#include "renderer/pass_timers.h"
#include "renderer/render_context.h"
#include "renderer/scene_targets.h"
#include "terrain/grass/grass_placement.h"
#include "terrain/grass/grass_settings.h"
#include "terrain/terrain_settings.h"

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace vista {

class Terrain;

struct GrassBlock;  // grass.glsl's uniforms (shaders/grass_block.glsl)

class Grass {
public:
    // "grass.cull": this frame's blades (before the shadow passes that draw them); returns the
    // blade list. count: add the blades drawn to the GPU counter "grass.blades" (CounterReadback).
    // motion_dt_s: the time since the previous frame (0: none, a cut); each blade also keeps how
    // the wind bent it then, for addVelocityPass.
    BufferHandle addCullPass(FrameGraph& graph, const RenderContext& rc, Terrain& terrain, const TerrainSettings& ts,
                             const GrassSettings& s, CounterReadback& counters, bool count, double motion_dt_s = 0.0);
    // "grass.gbuffer": the culled blades into targets' G-buffer.
    void addGbufferPass(FrameGraph& graph, const RenderContext& rc, const GrassSettings& s, BufferHandle blades,
                        SceneTargets& targets);
    // "grass.velocity": the blades' own motion in the wind written over the frame's motion vectors
    // (renderer/velocity.h) where a blade is what the pixel shows (depth EQUAL to the blade's):
    // each vertex also bent as motion_dt_s earlier (addCullPass) and projected by
    // prev_clip_from_relative (renderer/temporal.h previousClipFromRelative), so the vector holds
    // the wind's motion plus the camera's. Returns the new velocity handle.
    TextureHandle addVelocityPass(FrameGraph& graph, const RenderContext& rc, const GrassSettings& s, BufferHandle blades,
                                  TextureHandle depth, TextureHandle velocity, const glm::dmat4& prev_clip_from_relative);
    // The culled blades depth-only (grass.glsl SHADOW_PASS) through matrix (camera-relative world
    // -> clip), into the bound target; for shadow passes that read the blade list.
    void drawShadow(const RenderContext& rc, const GrassSettings& s, const glm::mat4& matrix) const;

    // How wet the blades are (0 dry .. 1 soaked: darker, glossier). Set by the weather feature.
    void setWetness(float wetness) { wetness_ = wetness; }

    const GrassLayout& layout() const { return layout_; }
    std::int64_t considered() const { return layout_.candidates(); }  // candidates per frame
    std::size_t memoryBytes() const { return std::size_t(blades_.size()) + std::size_t(draws_.size()); }
    // For tests: the blade list (GrassBlade, 48 bytes each: near ones from 0, far ones from
    // farStart()) and the two indirect commands {count, instances, first, base} (near, far).
    GLuint bladeBuffer() const { return blades_.id(); }
    GLuint drawBuffer() const { return draws_.id(); }
    std::uint32_t farStart() const { return near_capacity_; }

private:
    void allocate(const GrassSettings& s);
    void drawLists(const RenderContext& rc, GLuint program, const GrassSettings& s, GrassBlock block) const;  // both indirect draws with program

    GrassLayout layout_;
    GrassSettings sized_for_{};      // the settings the buffers were made for
    bool allocated_ = false;
    float wetness_ = 0.0f;
    std::uint32_t near_capacity_ = 0, far_capacity_ = 0;
    gl::Buffer blades_, draws_;
};

// False when the eye is more than radius_m above the highest terrain within radius_m of it
// (min/max quadtree): no blade can be in reach, so the frame adds no grass pass (the Grass
// object and its buffers stay).
bool grassInReach(const Terrain& terrain, const TerrainSettings& ts, const GrassSettings& s, const glm::dvec3& eye);

// Bytes of one culled blade on the GPU (GrassBlade in grass_common.glsl).
constexpr std::size_t kGrassBladeBytes = 48;

ProgramList grassPrograms();

}  // namespace vista
