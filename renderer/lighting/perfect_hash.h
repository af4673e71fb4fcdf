// Perfect spatial hashing (Lefebvre & Hoppe 2006), the building block of the hashed light
// octree (002): n distinct integer 3D keys p are stored in a table of m = mbar^3 slots with
//     h(p) = (p + Phi[h1(p)]) mod mbar        (per component)
// where Phi is an offset table of r = rbar^3 entries. No two keys share a slot, so a lookup is
// two memory reads and no probing. Sizes follow 002: mbar is the smallest with
// mbar^3 >= n (n <= 255) or >= 1.01 n, times (1 + slack); rbar the smallest with rbar^3 >= sigma n,
// sigma = 1/6 by default (Options::offset_ratio).
//
// One deliberate change from 002: h1 is not p mod rbar. With p mod rbar every group of keys
// sharing an offset is a lattice of stride rbar, and for dense 3D key sets (leaf cells filled by
// whole light spheres) the groups are nearly the same box shape, which does not pack into the
// table: construction needed rbar^3 several times n (measured: rbar = 199 for 1.2 M clustered
// keys, 10 restarts). Instead, with c = p mod mbar (the key's h0 class) and d = p / mbar:
//     h1(p) = (mix(c) mod r + (d.x + Q (d.y + Q d.z)) mod r) mod r,   Q = ceil(extent / mbar)
// mix scrambles c, so groups are random sets of h0 classes; the second term keeps keys of one class
// (which always collide in h0) in different groups while the quotients fit in r (keys < extent).
// The lookup is still two reads; Phi loses its spatial coherence.
//
// Construction (deterministic, seeded splitmix64): groups are placed largest first, each at a
// random offset where all its keys find free slots, else at the first offset (from a random slot
// on) that puts its first key on a free slot and fits the rest (exhaustive, so a one-key group
// always fits). When a group cannot be placed, rbar^3 grows by 1.5 (and every third try mbar by
// one) and the build restarts, at most Options::max_attempts times.
//
// The layout a shader reads (slot indices are x + mbar * (y + mbar * z)):
//   offsets()[g]  packed offset of entry g: ox | oy << 10 | oz << 20 (each < mbar <= 1023)
//   values()[s]   the 64-bit value stored with the key in slot s (0 for an empty slot)
//   g = offsetIndex(p):  c = p % mbar, d = p / mbar, r = rbar^3,
//                        h = c.x * 73856093 ^ c.y * 19349663 ^ c.z * 83492791 (uint32 wrap);
//                        h ^= h >> 16; h *= 0x7FEB352D; h ^= h >> 15;
//                        g = (h % r + (d.x + Q * (d.y + Q * d.z)) % r) % r,  Q = quotientSide()
//   slot(p) = hx + mbar * (hy + mbar * hz), h = (p + offset[g]) mod mbar
// Keys are non-negative with components < 2^21. A lookup of a key that was never inserted still
// returns some slot: callers either know the key is present (the octree's parent says so) or
// check with find(), which compares the stored key (CPU only).
//
// Keys can also be inserted and erased one at a time (insert() places the key in its group's
// slot when free, or moves the group to a new offset); when that fails the caller rebuilds.
// Every write is recorded in dirty() so a GPU copy can be updated by ranges.
#pragma once

#include <glm/vec3.hpp>

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

namespace vista {

class PerfectSpatialHash {
public:
    static constexpr std::uint32_t kMaxCoord = (1u << 21) - 1;  // largest key component
    static constexpr int kMaxSide = 1023;                          // largest mbar (10-bit offsets)

    struct Options {
        double slack = 0.0;          // extra table room, fraction (helps later inserts)
        std::uint64_t seed = 23;
        int max_attempts = 24;       // builds with growing tables before giving up
        std::uint32_t key_extent = 0;  // keys' components are below this (for h1's Q); 0: from the keys
        double offset_ratio = 1.0 / 6.0;  // sigma: rbar^3 >= sigma n; larger: smaller groups, easier edits
    };
    // Slot and offset-entry ranges written since the last clearDirty(); begin >= end: none.
    struct Dirty {
        std::uint32_t slot_begin = ~0u, slot_end = 0;
        std::uint32_t offset_begin = ~0u, offset_end = 0;
        bool resized = false;  // rebuilt with new sizes: upload everything
    };

    // Builds over distinct keys with their values. false when no perfect hash was found in
    // max_attempts tries (the table is then empty).
    bool build(std::span<const glm::uvec3> keys, std::span<const std::uint64_t> values, const Options& options);

    int tableSide() const { return m_; }   // mbar
    int offsetSide() const { return r_; }  // rbar
    std::size_t size() const { return n_; }
    std::size_t slotCount() const { return keys_.size(); }
    int attempts() const { return attempts_; }  // tries the last build() took

    std::uint32_t slot(glm::uvec3 key) const;
    // h1: the offset entry of key p (formula above).
    std::uint32_t offsetIndex(glm::uvec3 p) const;
    int quotientSide() const { return q_; }  // Q
    // The stored value of key, or nullptr when key is not in the table.
    const std::uint64_t* find(glm::uvec3 key) const;
    // Changes the value of a present key; false when absent.
    bool set(glm::uvec3 key, std::uint64_t value);
    // Adds (or updates) key without a rebuild. false when it does not fit (table full, or its
    // group finds no offset): the table is unchanged and the caller should rebuild.
    bool insert(glm::uvec3 key, std::uint64_t value);
    bool erase(glm::uvec3 key);  // false when absent
    // Every (key, value) stored, in slot order.
    std::vector<std::pair<glm::uvec3, std::uint64_t>> entries() const;

    std::span<const std::uint32_t> offsets() const { return offsets_; }
    std::span<const std::uint64_t> values() const { return values_; }
    const Dirty& dirty() const { return dirty_; }
    void clearDirty() { dirty_ = {}; }
    // Bytes a GPU copy takes with value_bytes per slot and 4 per offset entry.
    std::size_t gpuBytes(std::size_t value_bytes) const { return keys_.size() * value_bytes + offsets_.size() * 4; }
    std::size_t cpuBytes() const;

private:
    static constexpr std::uint64_t kEmpty = ~0ull;
    static constexpr std::uint32_t kNone = ~0u;
    struct Item {
        std::uint64_t key;
        std::uint64_t value;
    };
    std::uint32_t group(std::uint64_t key) const;
    std::uint32_t slotWith(std::uint64_t key, std::uint32_t offset) const;
    bool fits(std::span<const Item> items, std::uint32_t offset) const;
    bool placeGroup(std::uint32_t g, std::span<const Item> items, std::uint64_t& rng_state, std::size_t scan_limit);
    void store(std::uint32_t g, std::span<const Item> items, std::uint32_t offset);
    void unlink(std::uint32_t g, std::uint32_t s);
    void touchSlot(std::uint32_t s);
    void touchOffset(std::uint32_t g);
    bool tryBuild(std::span<const Item> items, int m, int r, std::uint32_t extent, std::uint64_t seed);

    int m_ = 0, r_ = 0, q_ = 1;
    std::size_t n_ = 0;
    int attempts_ = 0;
    std::uint64_t rng_ = 0;                // state for incremental inserts
    std::vector<std::uint64_t> keys_;      // per slot: packed key or kEmpty
    std::vector<std::uint64_t> values_;    // per slot
    std::vector<std::uint32_t> next_;      // per slot: next slot of the same group, kNone ends
    std::vector<std::uint32_t> offsets_;   // per entry: packed offset
    std::vector<std::uint32_t> head_;      // per entry: first slot of its group, kNone: no keys
    Dirty dirty_;
};

}  // namespace vista
