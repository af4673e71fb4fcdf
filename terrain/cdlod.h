// CDLOD terrain level of detail (after Strugar 2009): a min/max quadtree over the
// heightmap and a per-frame selection of nodes whose grid meshes are drawn instanced; each
// vertex morphs toward the next coarser grid over the last part of its level's range, so
// neighbouring nodes meet without cracks and levels change without popping.
//
// Units: world metres, y up. The heightmap covers [-size/2, size/2] in x and z, centred on
// the origin; height = offset + scale * sample. Selection works in double precision with
// camera-relative outputs, so a terrain far from the origin is stable.
#pragma once

#include "renderer/frustum.h"  // Frustum, frustumFromViewProj
#include "terrain/heightmap.h"

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace vista {

struct TerrainMapping {
    double size_m = 4096.0;      // world extent in x (and z, unless size_z_m is set)
    double height_scale_m = 600; // height of sample value 1
    double height_offset_m = 0;  // height of sample value 0
    int width = 0, height = 0;   // heightmap samples
    // World extent in z when it differs from x (a DEM whose texels or raster are not square
    // in metres, terrain/dem.h); 0: size_m.
    double size_z_m = 0.0;

    double sizeX() const { return size_m; }
    double sizeZ() const { return size_z_m > 0.0 ? size_z_m : size_m; }
    // World x/z of texel (tx, tz): texel centres span the whole extent (edges included).
    double texelSizeX() const { return size_m / double(width - 1); }
    double texelSizeZ() const { return sizeZ() / double(height - 1); }
};

// Min/max heights (metres) of every quadtree node. Leaf nodes span leaf_texels texels.
class MinMaxQuadtree {
public:
    MinMaxQuadtree() = default;
    MinMaxQuadtree(const Heightmap& map, const TerrainMapping& mapping, int leaf_texels);
    // From the leaves' min/max heights (m; row-major, ceil((width - 1) / leaf_texels) x
    // ceil((height - 1) / leaf_texels) of them, as a tile cache's level 0 with tile = leaf_texels
    // keeps them), without the map: the parents are the unions of their children, as above.
    MinMaxQuadtree(const TerrainMapping& mapping, int leaf_texels, std::vector<glm::vec2> leaves_m);

    int levels() const { return int(levels_.size()); }  // level 0 = leaves
    int leafTexels() const { return leaf_texels_; }
    // Nodes in x and z at a level: ceil((width - 1) / n), ceil((height - 1) / n) with
    // n = leaf_texels << level. The top level is the first with one node; a node reaching
    // past the map's edge covers only the texels inside it (nodes wholly outside don't exist).
    glm::ivec2 nodesPerSide(int level) const;
    // Heights (m) of node (x, z) at level, covering texels [x*n, min((x+1)*n, size-1)]
    // inclusive in x and z, so neighbours share their edge samples. Rounded outward to float.
    glm::vec2 minMax(int level, int x, int z) const;
    // Largest max - min height (m) of a node at level: bounds box diagonals for selection.
    double heightSpan(int level) const { return span_[std::size_t(level)]; }
    std::size_t memoryBytes() const;

private:
    void buildParents();  // levels 1.. from level 0 (per_side_ set)
    int leaf_texels_ = 0;
    std::vector<glm::ivec2> per_side_;
    std::vector<double> span_;
    std::vector<std::vector<glm::vec2>> levels_;  // per level, row-major (z * nodes.x + x)
};


// Ranges and morph regions. A level-k node's box has x/z extents (e_x, e_z) = texel sizes *
// min(leaf_texels << k, map samples - 1) and height H_k = tree.heightSpan(k); its diagonal is
// D_k = sqrt(e_x^2 + e_z^2 + H_k^2) and its side bound E_k = sqrt(max(e_x, e_z)^2 + H_k^2).
// With s_k = range[k] - range[k-1], m = morph_start and n levels, selection raises base_range_m
// to the smallest value with, for every k in [1, n-1],
//     s_k >= D_{k-1} / max(m, 1/2)     and, if k <= n-2,     s_k >= E_k
// (s_k = base * ratio^(k-1) * (ratio - 1)), and starts level k's morph no earlier than
// range[k-1] + D_{k-1}. Then neighbouring selected nodes differ by at most one level, and on a
// fine/coarse edge the finer node is fully morphed (k = 1) while the coarser one has not
// started (k = 0), so both edges are the same vertex row (derivation in cdlod.cpp).
struct LodSettings {
    int levels = 0;               // LOD levels to use (0 or more than the tree has: all quadtree levels)
    double base_range_m = 64.0;   // range of LOD 0 (raised as above)
    double range_ratio = 2.0;     // range of level L = base * ratio^L (at least 1.01)
    double morph_start = 0.7;     // morph over the last (1 - morph_start) of each level's span ([0, 0.99];
                                  // below 1/2 the start may move out, as above)
    double bias_slope = 0.0;      // largest slope (m/m) of a distance bias field (terrain/lod_error.h) added
                                  // to distances; the bounds above then use (1 + bias_slope) D_k for D_k,
                                  // and also for E_k when bias_slope > 0
};

class DistanceBias;

// One rectangle drawn with level `level`'s grid and morph constants. Usually a whole node
// (node_level == level). When only some children of a level-L node are finer, each remaining
// quadrant is a separate entry (Strugar's partial node): level = L, node_level = L - 1, and
// x, z, bounds, origin and size are those of the child node that quadrant is; it is drawn
// with half of level L's grid (grid/2 x grid/2 quads of level L's spacing).
struct SelectedNode {
    int level = 0;                 // LOD level: grid spacing and morph constants
    int node_level = 0;            // quadtree level of the area: level (whole) or level - 1 (quadrant)
    int x = 0, z = 0;              // node index at node_level
    glm::dvec3 min_rel, max_rel;   // bounds, camera-relative (m); x/z clamped to the map
    glm::dvec2 origin_rel;         // camera-relative x/z of the area's min corner (m)
    glm::dvec2 size_m{0.0};        // area extent in x, z (m), not clamped: grid rectangle
};

struct Selection {
    std::vector<SelectedNode> nodes;
    // Per level: morph distances (metres) as Strugar's constants: morphK = 1 - clamp(c.x - d * c.y, 0, 1),
    // with c.x = end / (end - start), c.y = 1 / (end - start); the top level never morphs
    // (c = (1, 0)) and reaches the farthest corner of the map; end = ranges[L],
    // start = ranges[L-1] + max(morph_start * (ranges[L] - ranges[L-1]), D_{L-1}); for L = 0: morph_start * ranges[0].
    std::vector<glm::dvec2> morph_consts;
    std::vector<double> ranges;        // per level, after raising the base range
    std::vector<double> morph_starts;  // per level: where the morph starts (m; unused for the top level)
};

// Per-level range ends and morph starts (m) as above, before the top level is stretched to
// the map's far corner (selectNodes does that).
void lodRanges(const MinMaxQuadtree& tree, const TerrainMapping& mapping, const LodSettings& lod,
               std::vector<double>& ends, std::vector<double>& starts);

// Selects nodes for a camera at world position camera (double), visible in frustum
// (camera-relative). Each part of the map inside the frustum is covered by exactly one node.
// With a bias, a node's distance is its box distance plus the smallest bias over it (a lower
// bound of d_eff over the node). Allocation-free after the first call if `out` is reused.
void selectNodes(const MinMaxQuadtree& tree, const TerrainMapping& mapping, const LodSettings& lod,
                 const glm::dvec3& camera, const Frustum& frustum, Selection& out, const DistanceBias* bias = nullptr);
// The same for the union of several frusta: the parts of the map inside any of them.
void selectNodes(const MinMaxQuadtree& tree, const TerrainMapping& mapping, const LodSettings& lod,
                 const glm::dvec3& camera, std::span<const Frustum> frusta, Selection& out,
                 const DistanceBias* bias = nullptr);

// Keeps the nodes of `from` whose boxes are not wholly outside `frustum` (camera-relative to
// the same camera): the main camera's selection reused for a shadow pass, so casters and
// receivers agree and nothing is selected twice. Allocation-free when `out` is reused.
void cullSelection(const Selection& from, const Frustum& frustum, Selection& out);

// CPU replica of the vertex shader: the morphed world x/z of grid vertex (gx, gz) of node,
// for a camera at `camera` (world, as passed to selectNodes). `grid` is the quads per side of a
// whole node (a multiple of 4, so quadrants start on even vertices); the node's area has
// q = grid >> (level - node_level) quads per side, gx, gz in [0, q], spacing
// step = size_m * 2^(level - node_level) / grid. With g = (gx, gz) and rel = origin_rel + g * step:
//   h = height_offset + height_scale * bilinear(map, texel coords of rel) - camera.y
//   d = length(rel.x, h, rel.y) + g(rel);  k = 1 - clamp(c.x - d * c.y, 0, 1)  (c = morph_consts[level],
//   g the bias at the vertex, 0 without one)
//   g -= fract(g / 2) * 2 * k * (rel < map max);  rel = clamp(origin_rel + g * step, map min, map max)
//   (camera-relative; a vertex at or past the far map edge does not morph on that axis)
// Bilinear sampling matches GL_LINEAR with clamp-to-edge on texel centres.
glm::dvec2 morphVertex(const SelectedNode& node, const Selection& sel, const TerrainMapping& mapping,
                       const Heightmap& map, const glm::dvec3& camera, int grid, int gx, int gz,
                       double* morph_k = nullptr, const DistanceBias* bias = nullptr);

}  // namespace vista
