// The hashed light octree: leaf cells with light lists, a pyramid of merge states above them,
// the linkless-octree tables derived from it, and the incremental path that keeps all three in
// step as lights move.
//
// Pyramid. Every level-l cell with a filled leaf cell below it has a state: the mask of its
// non-empty children and whether it is *uniform*, i.e. all 8^(L-l) leaf cells below it are
// filled with one list (then `rep` names one of those leaf cells). A uniform cell's children are
// uniform too, so a cell is a node of the final octree exactly when its parent is not uniform
// (or is the root, always a branch): a filled leaf if it is uniform, a branch otherwise. When
// cells change, their ancestors are recomputed bottom-up while their states change; the final
// role of a cell can change only if its own state, a child's state or its parent's state
// changed, so only those cells are re-examined against the tables.
#include "renderer/lighting/light_hash.h"

#include "renderer/random.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <unordered_map>

namespace vista {
namespace {

constexpr std::uint64_t kNoKey = ~0ull;

std::uint64_t pack(glm::uvec3 p) { return std::uint64_t(p.x) | std::uint64_t(p.y) << 21 | std::uint64_t(p.z) << 42; }
glm::uvec3 unpack(std::uint64_t k) {
    return {std::uint32_t(k & 0x1FFFFF), std::uint32_t((k >> 21) & 0x1FFFFF), std::uint32_t(k >> 42)};
}
std::uint64_t parentKey(std::uint64_t k) { return pack(unpack(k) >> 1u); }
std::uint64_t childKey(std::uint64_t k, int octant) {
    return pack(unpack(k) * 2u + glm::uvec3(octant & 1, (octant >> 1) & 1, octant >> 2));
}

std::uint64_t listHash(const std::vector<std::uint32_t>& list) {
    std::uint64_t h = 0x243F6A8885A308D3ull ^ list.size();
    for (std::uint32_t v : list) h = hashIndex(h, v);
    return h;
}

void sortUnique(std::vector<std::uint64_t>& v) {
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
}

struct Leaf {
    std::vector<std::uint32_t> lights;  // sorted light ids
    std::uint64_t hash = 0;
};

struct State {
    bool exists = false;
    bool uniform = false;
    std::uint64_t rep = kNoKey;  // a leaf cell with the list, when uniform
    std::uint64_t hash = 0;      // the list's hash, when uniform
    std::uint8_t mask = 0;       // non-empty children (pyramid levels)
    bool operator==(const State& o) const {
        return exists == o.exists && uniform == o.uniform && hash == o.hash && mask == o.mask;
    }
};

enum class Role { None, Branch, Leaf };

struct TableEdits {
    std::vector<glm::uvec3> keys;
    std::vector<std::uint64_t> values;
};

double msSince(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

struct LightHash::Impl {
    LightHashSettings settings;
    LightHashStats stats;
    double d = 0.0;  // leaf node size
    int L = 0;
    glm::dvec3 origin{0.0};
    std::vector<Sphere> spheres;
    std::vector<std::vector<std::uint64_t>> cells_of;  // per light: sorted leaf keys it is listed in
    std::unordered_map<std::uint64_t, Leaf> leaves;    // level L
    std::vector<std::unordered_map<std::uint64_t, State>> pyramid;  // levels [0, L)
    std::vector<PerfectSpatialHash> node;  // [0, L)
    std::vector<PerfectSpatialHash> data;  // [0, L]; data[0] unused
    std::vector<std::uint32_t> indices;
    std::size_t garbage = 0;
    std::size_t longest = 0;  // LightHashStats::longest_list
    std::size_t indices_dirty = 0;
    std::size_t pairs = 0;  // (leaf cell, light) pairs
    PerfectSpatialHash empty_table;

    double rootSize() const { return d * std::ldexp(1.0, L); }

    State state(int l, std::uint64_t key) const {
        State s;
        if (l == L) {
            auto it = leaves.find(key);
            if (it != leaves.end()) s = {true, true, key, it->second.hash, 0};
            return s;
        }
        auto it = pyramid[std::size_t(l)].find(key);
        return it != pyramid[std::size_t(l)].end() ? it->second : s;
    }

    bool sameList(std::uint64_t a, std::uint64_t b) const {
        return a == b || leaves.at(a).lights == leaves.at(b).lights;
    }

    State recompute(int l, std::uint64_t key) const {
        State s;
        bool all_uniform = true;
        for (int o = 0; o < 8; ++o) {
            State c = state(l + 1, childKey(key, o));
            if (!c.exists) continue;
            s.mask |= std::uint8_t(1u << o);
            if (!c.uniform) all_uniform = false;
            else if (s.rep == kNoKey) s.rep = c.rep, s.hash = c.hash;
            else if (c.hash != s.hash || !sameList(c.rep, s.rep)) all_uniform = false;
        }
        s.exists = s.mask != 0;
        s.uniform = s.mask == 0xFF && all_uniform;
        if (!s.uniform) s.rep = kNoKey, s.hash = 0;
        return s;
    }

    std::uint64_t masks(int l, std::uint64_t key) const {
        std::uint64_t v = 0;
        for (int o = 0; o < 8; ++o) {
            State c = state(l + 1, childKey(key, o));
            if (!c.exists) v |= 1u << o;                     // empty leaf
            else if (c.uniform) v |= (1u << o) | (1u << (8 + o));  // filled leaf
        }
        return v;
    }

    // Cells of level L touched by the sphere with its radius inflated by the guard.
    void coveredCells(const Sphere& s, std::vector<std::uint64_t>& out) const {
        out.clear();
        if (!(s.radius > 0.0) || L == 0) return;
        double rr = s.radius + settings.guard_m;
        glm::dvec3 c = s.center - origin;
        double top = std::ldexp(1.0, L) - 1.0;
        glm::dvec3 lo = glm::clamp(glm::floor((c - rr) / d), 0.0, top), hi = glm::clamp(glm::floor((c + rr) / d), 0.0, top);
        for (int z = int(lo.z); z <= int(hi.z); ++z)
            for (int y = int(lo.y); y <= int(hi.y); ++y)
                for (int x = int(lo.x); x <= int(hi.x); ++x) {
                    glm::dvec3 k(x, y, z);
                    glm::dvec3 v = glm::clamp(c, k * d, (k + 1.0) * d) - c;
                    if (glm::dot(v, v) <= rr * rr) out.push_back(pack(glm::uvec3(x, y, z)));
                }
    }

    bool inside(const Sphere& s) const {
        if (!(s.radius > 0.0)) return true;
        double rr = s.radius + settings.guard_m, size = rootSize();
        glm::dvec3 lo = s.center - rr - origin, hi = s.center + rr - origin;
        return lo.x >= 0.0 && lo.y >= 0.0 && lo.z >= 0.0 && hi.x < size && hi.y < size && hi.z < size;
    }

    void clear() {
        L = 0;
        spheres.clear();
        cells_of.clear();
        leaves.clear();
        pyramid.clear();
        node.clear();
        data.clear();
        indices.clear();
        garbage = 0;
        longest = 0;
        indices_dirty = 0;
        pairs = 0;
    }

    // Root cube and level count for node size d around the spheres; false when it needs more
    // than kMaxLevels levels.
    bool frame(std::span<const Sphere> in) {
        glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
        for (const Sphere& s : in)
            if (s.radius > 0.0) {
                lo = glm::min(lo, s.center - (s.radius + settings.guard_m));
                hi = glm::max(hi, s.center + (s.radius + settings.guard_m));
            }
        if (!(lo.x <= hi.x)) {
            L = 0;
            return true;
        }
        glm::dvec3 bmin = settings.bounds_min, bmax = settings.bounds_max;
        if (bmax.x > bmin.x && bmax.y > bmin.y && bmax.z > bmin.z) {
            lo = glm::min(lo, bmin);
            hi = glm::max(hi, bmax);
        }
        double extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
        double margin = settings.margin_m > 0.0 ? settings.margin_m : std::max(extent * 0.25, 4.0 * d);
        lo -= margin;
        hi += margin;
        origin = glm::floor(lo / d) * d;
        glm::dvec3 span = hi - origin;
        double need = std::max({span.x, span.y, span.z});
        L = 1;
        while (d * std::ldexp(1.0, L) <= need && L <= kMaxLevels) ++L;
        return L <= kMaxLevels;
    }

    std::uint64_t allocate(const std::vector<std::uint32_t>& list) {
        std::uint64_t offset = indices.size();
        indices.insert(indices.end(), list.begin(), list.end());
        longest = std::max(longest, list.size());
        return offset | std::uint64_t(list.size()) << 32;
    }
    void release(std::uint64_t value) { garbage += std::size_t(value >> 32); }
    bool sameRange(std::uint64_t value, const std::vector<std::uint32_t>& list) const {
        std::size_t offset = std::size_t(value & 0xFFFFFFFFu), count = std::size_t(value >> 32);
        return count == list.size() && std::equal(list.begin(), list.end(), indices.begin() + std::ptrdiff_t(offset));
    }

    // Applies collected inserts to a table: one by one, or a rebuild when many arrive or one
    // does not fit. false when no perfect hash could be built.
    bool applyInserts(PerfectSpatialHash& table, TableEdits& edits, int level) {
        if (edits.keys.empty()) return true;
        std::size_t first = 0;
        bool rebuild = table.slotCount() == 0 || edits.keys.size() > std::max<std::size_t>(64, table.size() / 4);
        if (!rebuild) {
            for (; first < edits.keys.size(); ++first)
                if (!table.insert(edits.keys[first], edits.values[first])) break;
                else ++stats.entries_written;
            rebuild = first < edits.keys.size();
        }
        if (!rebuild) return true;
        std::vector<glm::uvec3> keys;
        std::vector<std::uint64_t> values;
        for (const auto& [k, v] : table.entries()) keys.push_back(k), values.push_back(v);
        keys.insert(keys.end(), edits.keys.begin() + std::ptrdiff_t(first), edits.keys.end());
        values.insert(values.end(), edits.values.begin() + std::ptrdiff_t(first), edits.values.end());
        ++stats.tables_rebuilt;
        return table.build(keys, values,
                           {settings.slack, hashIndex(settings.seed, stats.tables_rebuilt), 24, std::uint32_t(1) << level,
                            settings.offset_ratio});
    }

    // Re-derives the pyramid above the changed leaf cells and brings the tables in line.
    bool commit(std::vector<std::uint64_t> changed_leaves) {
        if (L == 0) return true;
        sortUnique(changed_leaves);
        std::vector<std::vector<std::uint64_t>> dirty(std::size_t(L) + 1), changed(std::size_t(L) + 1);
        dirty[std::size_t(L)] = changed_leaves;
        changed[std::size_t(L)] = std::move(changed_leaves);
        for (int l = L - 1; l >= 0; --l) {
            auto& parents = dirty[std::size_t(l)];
            for (std::uint64_t k : changed[std::size_t(l) + 1]) parents.push_back(parentKey(k));
            sortUnique(parents);
            auto& level = pyramid[std::size_t(l)];
            for (std::uint64_t p : parents) {
                State now = recompute(l, p);
                auto it = level.find(p);
                State before = it != level.end() ? it->second : State{};
                if (now == before) {
                    if (it != level.end()) it->second.rep = now.rep;  // same list, maybe another cell
                    continue;
                }
                changed[std::size_t(l)].push_back(p);
                if (now.exists) level[p] = now;
                else if (it != level.end()) level.erase(it);
            }
        }
        std::vector<TableEdits> node_inserts(static_cast<std::size_t>(L)), data_inserts(static_cast<std::size_t>(L) + 1);
        std::vector<std::uint64_t> todo;
        for (int l = 0; l <= L; ++l) {
            todo = dirty[std::size_t(l)];
            if (l > 0)
                for (std::uint64_t p : changed[std::size_t(l) - 1])
                    for (int o = 0; o < 8; ++o) todo.push_back(childKey(p, o));
            sortUnique(todo);
            for (std::uint64_t key : todo) examine(l, key, node_inserts, data_inserts);
        }
        for (int l = 0; l < L; ++l)
            if (!applyInserts(node[std::size_t(l)], node_inserts[std::size_t(l)], l)) return false;
        for (int l = 1; l <= L; ++l)
            if (!applyInserts(data[std::size_t(l)], data_inserts[std::size_t(l)], l)) return false;
        return true;
    }

    // Compares a cell's role in the octree with what the tables hold, and edits them.
    void examine(int l, std::uint64_t key, std::vector<TableEdits>& node_inserts, std::vector<TableEdits>& data_inserts) {
        State s = state(l, key);
        Role want = Role::None;
        if (s.exists) {
            bool parent_branch = l <= 1 || !state(l - 1, parentKey(key)).uniform;
            if (l == 0) want = Role::Branch;
            else if (parent_branch) want = s.uniform ? Role::Leaf : Role::Branch;
        }
        glm::uvec3 k = unpack(key);
        const std::uint64_t* as_branch = l < L ? node[std::size_t(l)].find(k) : nullptr;
        const std::uint64_t* as_leaf = l > 0 ? data[std::size_t(l)].find(k) : nullptr;
        if (as_branch && want != Role::Branch) {
            node[std::size_t(l)].erase(k);
            ++stats.entries_written;
        }
        if (as_leaf && want != Role::Leaf) {
            release(*as_leaf);
            data[std::size_t(l)].erase(k);
            ++stats.entries_written;
        }
        if (want == Role::Branch) {
            std::uint64_t v = masks(l, key);
            if (!as_branch) {
                node_inserts[std::size_t(l)].keys.push_back(k);
                node_inserts[std::size_t(l)].values.push_back(v);
            } else if (*as_branch != v) {
                node[std::size_t(l)].set(k, v);
                ++stats.entries_written;
            }
        } else if (want == Role::Leaf) {
            const std::vector<std::uint32_t>& list = leaves.at(s.rep).lights;
            if (!as_leaf) {
                data_inserts[std::size_t(l)].keys.push_back(k);
                data_inserts[std::size_t(l)].values.push_back(allocate(list));
            } else if (!sameRange(*as_leaf, list)) {
                release(*as_leaf);
                data[std::size_t(l)].set(k, allocate(list));
                ++stats.entries_written;
            }
        }
    }

    // Rewrites the index list without garbage; every data value changes.
    void compact() {
        std::vector<std::uint32_t> fresh;
        fresh.reserve(indices.size() - garbage);
        longest = 0;
        for (int l = 1; l <= L; ++l) {
            PerfectSpatialHash& t = data[std::size_t(l)];
            for (const auto& [k, v] : t.entries()) {
                std::size_t offset = std::size_t(v & 0xFFFFFFFFu), count = std::size_t(v >> 32);
                std::uint64_t nv = std::uint64_t(fresh.size()) | std::uint64_t(count) << 32;
                longest = std::max(longest, count);
                fresh.insert(fresh.end(), indices.begin() + std::ptrdiff_t(offset),
                             indices.begin() + std::ptrdiff_t(offset + count));
                t.set(k, nv);
            }
        }
        indices = std::move(fresh);
        garbage = 0;
        indices_dirty = 0;
    }

    void fillStats() {
        stats.node_size_m = d;
        stats.levels = L;
        stats.branch_nodes = stats.filled_leaves = 0;
        std::size_t gpu = indices.size() * 4, cpu = indices.capacity() * 4;
        for (const PerfectSpatialHash& t : node) {
            stats.branch_nodes += t.size();
            gpu += t.gpuBytes(4);
            cpu += t.cpuBytes();
        }
        for (const PerfectSpatialHash& t : data) {
            stats.filled_leaves += t.size();
            gpu += t.gpuBytes(8);
            cpu += t.cpuBytes();
        }
        stats.leaf_cells = leaves.size();
        stats.index_count = indices.size();
        stats.index_garbage = garbage;
        stats.longest_list = longest;
        // Estimated in O(1): hash-map nodes (key, value, bucket, allocator overhead) at 64 bytes,
        // each (cell, light) pair as 4 bytes in the cell's list and 8 in the light's cell list.
        cpu += leaves.size() * 64 + pairs * 12;
        for (const auto& level : pyramid) cpu += level.size() * 64;
        cpu += spheres.capacity() * (sizeof(Sphere) + sizeof(std::vector<std::uint64_t>));
        stats.gpu_bytes = gpu;
        stats.cpu_bytes = cpu;
    }

    // Everything from scratch at node size d; false when more levels than allowed or no hash.
    bool buildAt(std::span<const Sphere> in) {
        clear();
        if (!frame(in)) return false;
        spheres.assign(in.begin(), in.end());
        cells_of.resize(in.size());
        if (L == 0) return true;
        pyramid.resize(std::size_t(L));
        node.resize(std::size_t(L));
        data.resize(std::size_t(L) + 1);
        std::vector<std::uint64_t> changed;
        for (std::size_t i = 0; i < in.size(); ++i) {
            coveredCells(in[i], cells_of[i]);
            pairs += cells_of[i].size();
        }
        leaves.reserve(pairs / 2);
        for (std::size_t i = 0; i < in.size(); ++i)
            for (std::uint64_t k : cells_of[i]) leaves[k].lights.push_back(std::uint32_t(i));
        changed.reserve(leaves.size());
        for (auto& [k, leaf] : leaves) {
            leaf.hash = listHash(leaf.lights);
            changed.push_back(k);
        }
        return commit(std::move(changed));
    }

    double autoNodeSize(std::span<const Sphere> in) const {
        double sum = 0.0;
        std::size_t n = 0;
        for (const Sphere& s : in)
            if (s.radius > 0.0) sum += s.radius, ++n;
        return n ? 0.5 * sum / double(n) : 1.0;
    }

    // Lower estimate of the index list's bytes at node size nd: cells a sphere's box covers,
    // times the share of a box a ball fills.
    double indexBytesEstimate(std::span<const Sphere> in, double nd) const {
        double pairs = 0.0;
        for (const Sphere& s : in)
            if (s.radius > 0.0) pairs += std::pow(2.0 * (s.radius + settings.guard_m) / nd + 1.0, 3.0) * 0.52;
        return pairs * 4.0;
    }

    void fullBuild(std::span<const Sphere> in) {
        auto t0 = std::chrono::steady_clock::now();
        double asked = settings.node_size_m > 0.0 ? settings.node_size_m : autoNodeSize(in);
        d = asked;
        stats = {};
        stats.full_rebuild = true;
        stats.lights_changed = in.size();
        std::string why;
        for (int c = 0; c <= kMaxCoarsenings; ++c, d *= 2.0) {
            if (c > 0) stats.degraded = true;
            if (indexBytesEstimate(in, d) > double(settings.memory_budget_bytes)) {
                why = "the light index list alone would exceed the memory budget";
                continue;
            }
            if (!buildAt(in)) {
                why = L > kMaxLevels ? "the lights span more than 2^20 leaf nodes" : "no perfect hash was found";
                continue;
            }
            fillStats();
            if (stats.gpu_bytes <= settings.memory_budget_bytes) {
                if (stats.degraded)
                    stats.message = "node size raised from " + std::to_string(asked) + " m to " + std::to_string(d) +
                                    " m: " + why;
                stats.ok = true;
                stats.cells_changed = leaves.size();
                stats.ms = msSince(t0);
                return;
            }
            why = "the tables (" + std::to_string(stats.gpu_bytes) + " bytes) exceed the memory budget (" +
                  std::to_string(settings.memory_budget_bytes) + " bytes)";
        }
        clear();
        fillStats();
        stats.ok = false;
        stats.message = "hashed light octree not built: " + why + " even at node size " + std::to_string(d / 2.0) + " m";
        stats.ms = msSince(t0);
    }

    void update(std::span<const Sphere> in) {
        auto t0 = std::chrono::steady_clock::now();
        bool rebuild = !stats.ok;
        std::size_t n = std::max(in.size(), spheres.size());
        for (std::size_t i = 0; i < in.size() && !rebuild; ++i) rebuild = in[i].radius > 0.0 && (L == 0 || !inside(in[i]));
        if (rebuild) {
            fullBuild(in);
            return;
        }
        stats.full_rebuild = false;
        stats.lights_changed = stats.cells_changed = stats.tables_rebuilt = stats.entries_written = 0;
        std::vector<std::uint64_t> cells, changed;
        cells_of.resize(n);
        for (std::size_t i = 0; i < n; ++i) {
            Sphere now = i < in.size() ? in[i] : Sphere{};
            Sphere before = i < spheres.size() ? spheres[i] : Sphere{};
            if (now.center == before.center && now.radius == before.radius) continue;
            ++stats.lights_changed;
            coveredCells(now, cells);
            std::vector<std::uint64_t>& old = cells_of[i];
            if (cells == old) continue;
            std::uint32_t id = std::uint32_t(i);
            std::size_t a = 0, b = 0;  // merge the two sorted key lists
            while (a < old.size() || b < cells.size()) {
                if (b == cells.size() || (a < old.size() && old[a] < cells[b])) {
                    auto it = leaves.find(old[a]);
                    auto& list = it->second.lights;
                    list.erase(std::lower_bound(list.begin(), list.end(), id));
                    if (list.empty()) leaves.erase(it);
                    changed.push_back(old[a++]);
                } else if (a == old.size() || cells[b] < old[a]) {
                    auto& list = leaves[cells[b]].lights;
                    list.insert(std::lower_bound(list.begin(), list.end(), id), id);
                    changed.push_back(cells[b++]);
                } else {
                    ++a, ++b;
                }
            }
            pairs = pairs + cells.size() - old.size();
            old = cells;
        }
        spheres.assign(in.begin(), in.end());
        cells_of.resize(in.size());
        sortUnique(changed);
        for (std::uint64_t k : changed) {
            auto it = leaves.find(k);
            if (it != leaves.end()) it->second.hash = listHash(it->second.lights);
        }
        stats.cells_changed = changed.size();
        std::size_t dirty_before = indices.size();
        if (!commit(std::move(changed))) {
            fullBuild(in);
            return;
        }
        indices_dirty = std::min(indices_dirty, dirty_before);
        if (garbage > 4096 && garbage > indices.size() - garbage) compact();
        fillStats();
        stats.ms = msSince(t0);
        if (stats.gpu_bytes > settings.memory_budget_bytes) fullBuild(in);
    }

    std::span<const std::uint32_t> query(const glm::dvec3& p) const {
        if (L == 0) return {};
        glm::dvec3 q = glm::floor((p - origin) / d);
        double cells = std::ldexp(1.0, L);
        if (q.x < 0.0 || q.y < 0.0 || q.z < 0.0 || q.x >= cells || q.y >= cells || q.z >= cells) return {};
        glm::uvec3 u(q);
        for (int l = 0; l < L; ++l) {
            glm::uvec3 c = u >> std::uint32_t(L - l), k = u >> std::uint32_t(L - l - 1);
            std::uint32_t bit = (k.x & 1u) + 2u * (k.y & 1u) + 4u * (k.z & 1u);
            const PerfectSpatialHash& t = node[std::size_t(l)];
            if (t.slotCount() == 0) return {};
            std::uint64_t v = t.values()[t.slot(c)];
            if ((v >> bit) & 1u) {
                if (!((v >> (8 + bit)) & 1u)) return {};
                const PerfectSpatialHash& dt = data[std::size_t(l) + 1];
                std::uint64_t dv = dt.values()[dt.slot(k)];
                return std::span<const std::uint32_t>(indices).subspan(std::size_t(dv & 0xFFFFFFFFu), std::size_t(dv >> 32));
            }
        }
        return {};
    }
};

LightHash::LightHash() : impl_(std::make_unique<Impl>()) {}
LightHash::~LightHash() = default;
LightHash::LightHash(LightHash&&) noexcept = default;
LightHash& LightHash::operator=(LightHash&&) noexcept = default;

const LightHashStats& LightHash::build(std::span<const Sphere> spheres, const LightHashSettings& settings) {
    impl_->settings = settings;
    impl_->fullBuild(spheres);
    return impl_->stats;
}

const LightHashStats& LightHash::update(std::span<const Sphere> spheres) {
    impl_->update(spheres);
    return impl_->stats;
}

const LightHashStats& LightHash::stats() const { return impl_->stats; }

std::span<const std::uint32_t> LightHash::query(const glm::dvec3& p) const { return impl_->query(p); }

std::span<const std::uint32_t> LightHash::cellLights(const glm::dvec3& p) const {
    const Impl& m = *impl_;
    if (m.L == 0) return {};
    glm::dvec3 q = glm::floor((p - m.origin) / m.d);
    double cells = std::ldexp(1.0, m.L);
    if (q.x < 0.0 || q.y < 0.0 || q.z < 0.0 || q.x >= cells || q.y >= cells || q.z >= cells) return {};
    auto it = m.leaves.find(pack(glm::uvec3(q)));
    return it != m.leaves.end() ? std::span<const std::uint32_t>(it->second.lights) : std::span<const std::uint32_t>();
}

int LightHash::levels() const { return impl_->L; }
double LightHash::nodeSize() const { return impl_->d; }
glm::dvec3 LightHash::origin() const { return impl_->origin; }
const PerfectSpatialHash& LightHash::nodeTable(int level) const {
    return level >= 0 && level < impl_->L ? impl_->node[std::size_t(level)] : impl_->empty_table;
}
const PerfectSpatialHash& LightHash::dataTable(int level) const {
    return level >= 1 && level <= impl_->L ? impl_->data[std::size_t(level)] : impl_->empty_table;
}
std::span<const std::uint32_t> LightHash::indices() const { return impl_->indices; }

void LightHash::clearDirty() {
    for (PerfectSpatialHash& t : impl_->node) t.clearDirty();
    for (PerfectSpatialHash& t : impl_->data) t.clearDirty();
    impl_->indices_dirty = impl_->indices.size();
}

std::size_t LightHash::indicesDirtyBegin() const { return impl_->indices_dirty; }

}  // namespace vista
