// The scene's Terrain as a shadow caster (renderer/shadows/terrain_caster.h): binds the terrain
// and the frame's terrain settings, and hands the shadow passes its selection's quadrants and
// depth-only draws. Rebound every frame; must outlive the frame graph's execution.
#pragma once

#include "renderer/shadows/terrain_caster.h"
#include "terrain/terrain.h"

namespace vista {

class TerrainShadowCaster final : public TerrainCaster {
public:
    void bind(Terrain& terrain, const TerrainSettings& settings) {
        terrain_ = &terrain;
        settings_ = &settings;
    }

    glm::dvec2 heightRange() const override;
    double tessReach() const override { return terrain_->tessReach(*settings_); }
    std::size_t pick(const Frustum& planes, std::vector<TerrainInstance>& out, bool tessellate,
                     const CasterBoxFilter& keep = {}, std::size_t* skipped = nullptr,
                     double coarsest_step_m = 0.0) override {
        return terrain_->shadowInstances(*settings_, planes, out, tessellate, keep, skipped, coarsest_step_m);
    }
    GLuint program(const RenderContext& rc) const override;
    void draw(const RenderContext& rc, GLuint program, const glm::mat4& matrix, const std::vector<TerrainInstance>& list,
              std::size_t tess, int slot) override {
        terrain_->drawShadow(rc, *settings_, program, matrix, list, tess, slot);
    }
    std::int64_t triangles(const std::vector<TerrainInstance>& list) const override { return terrain_->triangles(list); }
    void drawLists(const RenderContext& rc, GLuint program, std::span<const std::vector<TerrainInstance>> lists,
                   std::span<const std::size_t> tess, const std::function<glm::mat4(std::size_t)>& before) override {
        terrain_->drawShadowLists(rc, *settings_, program, lists, tess, before);
    }

private:
    Terrain* terrain_ = nullptr;
    const TerrainSettings* settings_ = nullptr;
};

}  // namespace vista
