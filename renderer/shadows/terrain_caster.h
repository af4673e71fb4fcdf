// The terrain as the shadow passes see it: a heightfield whose caster quadrants each shadow view
// picks from the frame's one LOD selection, drawn depth-only and instanced. renderer/shadows may
// not include terrain/; terrain/terrain_caster.h implements this for the scene's Terrain, as
// ShadowCaster (shadow_caster.h) carries the grass and the objects.
#pragma once

#include "renderer/frustum.h"
#include "renderer/render_context.h"

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

namespace vista {

// One quadrant of a node at its LOD level: what the terrain's vertex stage draws per instance.
struct TerrainInstance {
    glm::vec4 a;  // camera-relative x, z of the min corner (m), grid step in x (m), level
    glm::vec4 b;  // morph constants of the level, grid step in z (m), k: drawn with every 2^k-th grid vertex
};

// Accepts a caster by its camera-relative box (lo, hi).
using CasterBoxFilter = std::function<bool(const glm::dvec3& lo, const glm::dvec3& hi)>;

class TerrainCaster {
public:
    virtual ~TerrainCaster() = default;

    // The lowest and highest ground (m, world; infinite when not known).
    virtual glm::dvec2 heightRange() const = 0;
    // Where the displacement has ended (m from the camera): views serving only ground beyond it
    // need no tessellated casters.
    virtual double tessReach() const = 0;
    // The selection's quadrants inside planes (camera-relative) into out; with `keep`, only those
    // it accepts (`skipped` gets how many inside the planes it left out). With `tessellate` the
    // quadrants the view draws displaced come first, and their count is returned. With
    // coarsest_step_m > 0 the others whose grid is finer may be drawn with every 2nd, 4th, ...
    // vertex, up to that step (a shadow map's texel needs no finer caster).
    virtual std::size_t pick(const Frustum& planes, std::vector<TerrainInstance>& out, bool tessellate,
                             const CasterBoxFilter& keep = {}, std::size_t* skipped = nullptr,
                             double coarsest_step_m = 0.0) = 0;
    // The depth-only program the draws below take (made current by the caller).
    virtual GLuint program(const RenderContext& rc) const = 0;
    // Draws one list through matrix (camera-relative world -> the shadow view's clip) into
    // instance slot 0..kSlots-1; its first `tess` as displaced patches.
    static constexpr int kSlots = 8;
    virtual void draw(const RenderContext& rc, GLuint program, const glm::mat4& matrix,
                      const std::vector<TerrainInstance>& list, std::size_t tess, int slot) = 0;
    // The triangles a list draws (its patches counted as grid triangles).
    virtual std::int64_t triangles(const std::vector<TerrainInstance>& list) const = 0;
    // Draws several lists (spot tiles, point cube faces): list i through the matrix before(i)
    // returns after setting its viewport; empty lists are skipped.
    virtual void drawLists(const RenderContext& rc, GLuint program, std::span<const std::vector<TerrainInstance>> lists,
                           std::span<const std::size_t> tess, const std::function<glm::mat4(std::size_t)>& before) = 0;
};

}  // namespace vista
