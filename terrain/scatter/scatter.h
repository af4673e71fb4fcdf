// Scatter placement without GL: a rule of [objects] (terrain/scatter/object_settings.h) places
// instances per world cell of cell_m x cell_m, like the grass: cell (i, k) holds
// floor(density * cell^2 + u) candidates (u a hash of the cell: the fractional part on average),
// and candidate j takes its position, model, yaw and scale from a hash of (i, k, j, seed). A
// candidate stays where the ground allows it (height range, slope, grass weight). So a cell
// always holds the same instances, whichever cells are placed with it and in whatever order:
// moving away and back gives the same forest (tested). placeObjects() places every list entry of
// [objects]; renderer/meshes/objects.h draws what it gives (the app wires the two).
#pragma once

#include "renderer/meshes/placed_objects.h"
#include "terrain/scatter/object_settings.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace vista {

struct GroundSample {
    bool valid = false;  // false: outside the terrain (nothing stands there)
    double height_m = 0.0;
    double slope = 0.0;  // rise over run
    double grass = 1.0;  // terrain grass weight, 0..1
};
using GroundFunction = std::function<GroundSample(double x, double z)>;

// The world area scatter rules cover: [min, max] in x and z (the terrain's extent).
struct ScatterArea {
    glm::dvec2 min{0.0}, max{0.0};
};
// The extent of a terrain of side size_m centred at origin ([terrain] origin).
ScatterArea terrainScatterArea(const glm::dvec3& origin, double size_m);

// The world cell holding point xz for rule r.
glm::ivec2 scatterCellOf(const ScatterRule& r, glm::dvec2 xz);
// Candidates in a cell (before the ground decides), for tests and statistics.
int scatterCandidates(const ScatterRule& r, glm::ivec2 cell);
// Appends the instances of one cell to out.
void scatterCell(const ScatterRule& r, glm::ivec2 cell, const GroundFunction& ground, std::vector<PlacedObject>& out);
// Every cell in [min_cell, max_cell] (inclusive), row by row.
std::vector<PlacedObject> scatterRegion(const ScatterRule& r, glm::ivec2 min_cell, glm::ivec2 max_cell,
                                        const GroundFunction& ground);

// Candidates (ground samples; most become instances) that placeObjects() may test over an area,
// all scatter rules together: the default scene's island tests about 0.22 M. Beyond it the rules
// are placed around the camera instead of over the whole terrain (a 131 km map would test 57 M:
// minutes and gigabytes), and an area around the camera that still tests more is refused.
constexpr double kMaxScatterCandidates = 4.0e6;
// "" when s's scatter rules test at most kMaxScatterCandidates over area; else why, naming them.
// where: what the area is ("the terrain's", "the camera-local").
std::string scatterBudgetProblem(const ObjectsSettings& s, const ScatterArea& area, const std::string& where = "the terrain's");

// A camera-local placement covers a square of half side kLocalScatterReach * max_distance_m
// around its centre and is placed again once the camera is (kLocalScatterReach - 1) *
// max_distance_m from that centre: every instance nearer than max_distance_m (all that is
// drawn) is always placed, and a cell holds the same instances whichever placement holds it.
constexpr double kLocalScatterReach = 1.5;
ScatterArea localScatterArea(glm::dvec2 centre, double max_distance_m);
bool localScatterStale(glm::dvec2 centre, glm::dvec2 camera, double max_distance_m);
// How far camera is from centre along x or z, whichever is farther (m).
double localScatterDrift(glm::dvec2 centre, glm::dvec2 camera);

// What s's lists place, one ObjectPlacement per entry in file order: each object.NAME (on the
// ground when it asks, ground may be empty), then each scatter.NAME over area (its files, no
// instances without a ground or an area). PlacedObject::file indexes the entry's files.
std::vector<ObjectPlacement> placeObjects(const ObjectsSettings& s, const GroundFunction& ground, const ScatterArea& area);
// Whether a and b place the same (their lists are equal): placeObjects() need not run again.
bool samePlacement(const ObjectsSettings& a, const ObjectsSettings& b);

}  // namespace vista
