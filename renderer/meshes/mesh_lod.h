// Coarser levels of detail for a Model by vertex clustering (Rossignac and Borrel 1993): the
// model's bounding box is cut into a grid of cells; every vertex of a cell moves to the cell's
// mean position (normal and UV averaged per cell and material), and triangles whose corners
// fall into fewer than three distinct cells disappear. Cheap, robust on any input, and good
// enough for distant objects, which is all a far LOD is drawn for.
#pragma once

#include "renderer/meshes/model.h"

namespace vista {

// Appends to model.lods one level per entry of cells (grid cells along the box's longest side,
// coarsest last), each over new vertices and indices appended to the model's arrays. A level
// that would keep no triangle keeps the previous level's triangles instead.
void buildLods(Model& model, const std::vector<int>& cells);

}  // namespace vista
