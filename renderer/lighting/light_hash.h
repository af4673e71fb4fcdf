// Hashed shading's light structure (002, chapter 7): a camera-independent, world-space octree
// of the lights stored as a linkless octree (Choi et al. 2009), each layer a perfect spatial
// hash (renderer/lighting/perfect_hash.h), with per filled leaf an (offset, count) into one light-index
// list. Beyond the thesis it takes moving, added and removed lights without a full rebuild,
// and keeps to a memory bound.
//
// Geometry. Leaf nodes are cubes of node size d (m). The root cube has side d * 2^L (L = levels()),
// its corner origin() is on the d grid, and it holds every light sphere plus a margin. Level l
// (0 = root, L = leaves) has nodes of side d * 2^(L - l); node coordinates are integers
// c = floor((p - origin) / (d * 2^(L - l))). A leaf cell (level L) is *filled* with the lights whose
// sphere, radius inflated by guard_m, touches the cell (closest point of the cube to the centre
// within the radius; exact in double). A light of radius <= 0 is in no cell. Eight sibling cells
// that are all filled with the same list merge into their parent, recursively; an absent cell is
// empty. So the list found for a point is exactly the list of the leaf cell (level L) holding it:
// a superset of the lights that reach the point, never missing one.
//
// Tables (what the GPU reads). For each level l in [0, L): nodeTable(l) holds the branch nodes of
// level l (the root is always a branch); its value's bits 0-7 say which of the 8 children (octant
// x + 2y + 4z of the child's coordinates' low bits) is a leaf, bits 8-15 which of those leaves is
// filled. For each level l in [1, L]: dataTable(l) holds the filled leaves of level l, value =
// offset | count << 32 into indices() (read as a uvec2 (offset, count) on the GPU).
// Lookup of point p (world):
//     q = uvec3(floor((p - origin) / d));  outside [0, 2^L) in any axis: no lights
//     for l = 0 .. L-1:
//         c = q >> (L - l);  k = q >> (L - l - 1);  bit = (k.x & 1) + 2 (k.y & 1) + 4 (k.z & 1)
//         v = nodeTable(l).values[nodeTable(l).slot(c)]
//         if (v >> bit) & 1:                                           // the child is a leaf
//             if (v >> (8 + bit)) & 1: (offset, count) = dataTable(l + 1).values[... slot(k)]
//             stop (an empty leaf: no lights)
// Two table reads per level at most; query() runs exactly this on the CPU.
//
// Updates. update() diffs the new spheres against the old: a light whose covered leaf cells did
// not change costs nothing but its light-buffer entry; otherwise its id leaves/joins those cells'
// lists, and only the changed cells' ancestors (and their children, whose leaf/branch role can
// flip) are re-derived. Table entries are then erased, inserted or rewritten one by one; a table
// is rebuilt only when an insert finds no place (or many keys arrive at once). Changed leaf lists
// are appended to the index list (old ranges become garbage, compacted when garbage exceeds the
// live part). A full rebuild happens when a light leaves the root cube, or the budget is exceeded.
//
// Costs (measured on this 2-core machine, under load, Release): 100,000 lights of radius 10 m at
// node size 10 m: 1.2 M filled leaf cells, 10 levels, build about 3 s, 28 MB of GPU tables and
// index list; moving 1,000 of them by 3 m: about 35-60 ms, no table rebuilt. A light covers about
// (2 r / d + 1)^3 * 0.52 leaf cells, so lights much larger than the node size are expensive (002's
// "memory grows cubically"); the memory bound then coarsens the nodes.
//
// Memory bound. gpuBytes() = sum over tables of (slots * value bytes (4 node, 8 data) + offset
// entries * 4) + indices * 4. When it would exceed memory_budget_bytes, the node size doubles
// (stats().degraded, with a message) until it fits; if it does not fit even after
// kMaxCoarsenings doublings the structure is left empty with stats().ok = false and a message, and
// the renderer should fall back to another culling method (each later update() tries a full
// build again).
#pragma once

#include "renderer/lighting/perfect_hash.h"
#include "renderer/lights.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <memory>
#include <span>
#include <string>

namespace vista {

struct LightHashSettings {
    double node_size_m = 0.0;           // m, leaf node size; <= 0: half the mean radius of the lights (radius > 0)
    std::size_t memory_budget_bytes = std::size_t(256) << 20;  // GPU bytes, as above
    double slack = 0.25;                // extra hash table room, fraction: fewer rebuilds on insert
    double offset_ratio = 1.0;          // offset entries per key (002: 1/6); with ~1 key per entry a
                                        // group can almost always move on insert (measured: 1000
                                        // inserts into 100k keys refused 0 times at 1.0 and slack 0.3,
                                        // 476 times at 1/6 and slack 0.1). Costs 4 bytes per key.
    double guard_m = 0.01;              // m added to every radius in cell tests (GPU float rounding)
    double margin_m = 0.0;              // m of room around the lights' bounds; <= 0: max(extent / 4, 4 d)
    glm::dvec3 bounds_min{0.0}, bounds_max{0.0};  // m, world; when max > min on every axis the root cube
                                                  // also covers this box (e.g. the terrain), so lights
                                                  // moving inside it never force a rebuild
    std::uint64_t seed = 23;
};

struct LightHashStats {
    bool ok = true;           // false: nothing built (message says why)
    bool degraded = false;    // the node size is larger than asked, to fit the budget
    std::string message;      // empty, or why degraded / not ok
    double node_size_m = 0.0; // leaf node size used
    int levels = 0;           // L; 0 when there are no lights with radius > 0
    std::size_t branch_nodes = 0, filled_leaves = 0, leaf_cells = 0;  // leaf_cells: filled cells at level L
    std::size_t index_count = 0, index_garbage = 0;                   // entries of indices(), of them unused
    std::size_t longest_list = 0;  // longest leaf list written since the last build or compaction: >= every live list
    std::size_t gpu_bytes = 0, cpu_bytes = 0;
    // What the last build() / update() did.
    bool full_rebuild = false;
    std::size_t lights_changed = 0;  // spheres that differ from the previous call
    std::size_t cells_changed = 0;   // leaf cells whose light list changed
    std::size_t tables_rebuilt = 0;  // perfect hashes built from scratch
    std::size_t entries_written = 0; // table entries inserted, erased or rewritten one by one
    double ms = 0.0;                 // wall time
};

class LightHash {
public:
    static constexpr int kMaxLevels = 20;        // root side at most d * 2^20
    static constexpr int kMaxCoarsenings = 12;   // node size doublings to fit the budget

    LightHash();
    ~LightHash();
    LightHash(LightHash&&) noexcept;
    LightHash& operator=(LightHash&&) noexcept;

    // Builds from scratch: light i is spheres[i] (world bounding spheres, renderer/lights.h).
    const LightHashStats& build(std::span<const Sphere> spheres, const LightHashSettings& settings);
    // Brings the structure to spheres (same ids; ids past spheres.size() are removed, new ones
    // added), changing only what moved (see the header comment).
    const LightHashStats& update(std::span<const Sphere> spheres);
    const LightHashStats& stats() const;

    // Light indices listed for the leaf cell holding world point p (through the tables, as the GPU).
    std::span<const std::uint32_t> query(const glm::dvec3& p) const;
    // The leaf-level list computed directly from the cells (no tables), for tests.
    std::span<const std::uint32_t> cellLights(const glm::dvec3& p) const;

    int levels() const;
    double nodeSize() const;      // d, m
    glm::dvec3 origin() const;    // m, world
    const PerfectSpatialHash& nodeTable(int level) const;  // level in [0, levels())
    const PerfectSpatialHash& dataTable(int level) const;  // level in [1, levels()]
    std::span<const std::uint32_t> indices() const;
    // Marks every table's and the index list's changes as uploaded.
    void clearDirty();
    // First index-list entry written since clearDirty() (indices().size() when none); a
    // compaction rewrites from 0.
    std::size_t indicesDirtyBegin() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace vista
