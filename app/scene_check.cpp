// The GL-free half of FrameRenderer::prepare, for `vista check`.
#include "app/scene_check.h"

#include "app/scene.h"
#include "postfx/lut.h"
#include "terrain/terrain.h"

namespace vista {

InputErrors validateSceneInputs(const Settings& s) {
    InputErrors errors;
    if (s.terrain.enabled) {
        TerrainSettings wanted = s.terrain;
        wanted.heightmap = resolveInput(s.terrain.heightmap).string();
        wanted.dem = resolveInput(s.terrain.dem).string();
        Terrain::loadChecked(wanted, errors);  // the same function Terrain::load runs
    }
    if (s.grade.enabled && !s.grade.lut.empty()) loadCube(resolveInput(s.grade.lut), errors);  // as PostChain::prepare
    return errors;
}

}  // namespace vista
