// The terrain as a shadow caster (see terrain_caster.h).
#include "terrain/terrain_caster.h"

#include <limits>

namespace vista {

glm::dvec2 TerrainShadowCaster::heightRange() const {
    const MinMaxQuadtree& tree = terrain_->quadtree();
    if (tree.levels() == 0) return {-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
    const glm::vec2 span = tree.minMax(tree.levels() - 1, 0, 0);
    return {double(span.x), double(span.y)};
}

GLuint TerrainShadowCaster::program(const RenderContext& rc) const {
    return rc.shaders.id("terrain/shaders/terrain.glsl", terrain_->shadowDefines());
}

}  // namespace vista
