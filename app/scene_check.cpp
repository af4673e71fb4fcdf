// The GL-free half of FrameRenderer::prepare, for `vista check`.
#include "app/scene_check.h"

#include "app/scene.h"
#include "postfx/lut.h"
#include "terrain/terrain.h"

namespace vista {

InputErrors validateSceneInputs(const Settings& s, CheckedTerrain* terrain) {
    InputErrors errors;
    if (s.terrain.enabled) {
        TerrainSettings wanted = s.terrain;
        wanted.heightmap = resolveInput(s.terrain.heightmap).string();
        wanted.dem = resolveInput(s.terrain.dem).string();
        wanted = resolveMaterialPaths(std::move(wanted), resolveInput);
        TerrainMapping mapping;
        Heightmap checked = Terrain::loadChecked(wanted, errors, &mapping);  // the same function Terrain::load runs
        if (terrain && !checked.samples.empty()) *terrain = {std::move(checked), mapping};
    }
    if (s.grade.enabled && !s.grade.lut.empty()) loadCube(resolveInput(s.grade.lut), errors);  // as PostChain::prepare
    return errors;
}

}  // namespace vista
