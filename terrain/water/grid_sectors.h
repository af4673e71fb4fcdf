// Which segments (angular sectors) of the sea's camera-centred ring grid (terrain/water/water.h)
// can reach the screen: the grid's triangles behind and beside the view are never drawn. A
// segment is drawn when some point of it, displaced by any wave, can lie inside the view
// frustum; that test is conservative, so culling never changes the image.
#pragma once

#include "terrain/cdlod.h"

namespace vista {

struct WaterGrid;

// The drawn segments: first, first + 1, ..., first + count - 1, each modulo the grid's segments.
struct SectorRange {
    int first = 0, count = 0;
};

// The segments of `grid` (still surface `height_above_m` below the eye, rings out to their
// outer radius) whose displaced triangles can meet `frustum` (camera-relative, inward planes,
// terrain/cdlod.h): displacements reach `max_height_m` up or down and `max_chop_m` sideways.
// All segments when the eye's own x, z may be in view (looking down, or at the surface).
SectorRange visibleSectors(const WaterGrid& grid, double height_above_m, double max_height_m, double max_chop_m,
                           const Frustum& frustum);

}  // namespace vista
