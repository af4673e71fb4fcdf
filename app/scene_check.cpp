// The GL-free half of FrameRenderer::prepare, for `vista check`.
#include "app/scene_check.h"

#include "app/scene.h"
#include "postfx/lut.h"
#include "terrain/scatter/scatter.h"
#include "terrain/terrain.h"
#include "terrain/tile_cache.h"

#include <memory>
#include <optional>

namespace vista {

InputErrors validateSceneInputs(const Settings& s, CheckedTerrain* terrain) {
    InputErrors errors;
    if (s.terrain.enabled) {
        TerrainSettings wanted = s.terrain;
        wanted.heightmap = resolveInput(s.terrain.heightmap).string();
        wanted.dem = resolveInput(s.terrain.dem).string();
        wanted = resolveMaterialPaths(std::move(wanted), resolveInput);
        const glm::dvec3 origin = s.terrain.origin;
        std::optional<TerrainMapping> extent;  // where the scatter rules would place
        // The same functions Terrain::load runs.
        if (wanted.stream.enabled) {
            std::shared_ptr<TileCache> cache = openStreamCache(wanted, StreamCacheUse::Check, errors);
            if (cache) extent = cache->mapping();
            if (terrain && cache) {
                auto sampler = std::make_shared<TileCacheSampler>(*cache);
                terrain->ground = [cache, sampler, origin](double x, double z) {
                    return placedHeightAt(cache->mapping(), origin, x, z,
                                          [&](double tx, double tz) { return sampler->sample(tx, tz); });
                };
            }
        } else {
            TerrainMapping mapping;
            Heightmap checked = Terrain::loadChecked(wanted, errors, &mapping);
            if (!checked.samples.empty()) extent = mapping;
            if (terrain && !checked.samples.empty()) {
                terrain->map = std::move(checked);
                terrain->mapping = mapping;
                terrain->ground = [terrain, origin](double x, double z) {
                    return terrainHeightAt(terrain->map, terrain->mapping, origin, x, z);
                };
            }
        }
        // As FrameRenderer::prepareObjects: over the terrain's extent, or around the camera when
        // the rules are too dense for it.
        if (extent && objectsWanted(s.objects)) {
            const ScatterArea area = terrainScatterArea(origin, extent->size_m);
            const ScatterArea local = localScatterArea({s.camera.position.x, s.camera.position.z}, s.objects.max_distance_m);
            if (!scatterBudgetProblem(s.objects, area).empty())
                if (std::string why = scatterBudgetProblem(s.objects, local, "the camera-local"); !why.empty())
                    errors.push_back({"[objects]", 0, why});
        }
    }
    if (s.grade.enabled && !s.grade.lut.empty()) loadCube(resolveInput(s.grade.lut), errors);  // as PostChain::prepare
    return errors;
}

}  // namespace vista
