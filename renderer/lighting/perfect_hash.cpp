// Perfect spatial hash construction and incremental edits (Lefebvre & Hoppe 2006 with 002's
// table sizes). The CPU keeps, beside the GPU-visible offsets and values, each slot's key and a
// per-group list of slots, which find(), erase() and moving a group on insert() need.
#include "renderer/lighting/perfect_hash.h"

#include "renderer/random.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace vista {
namespace {

constexpr int kRandomTries = 32;              // random offsets tried per group before scanning
constexpr std::size_t kEditScan = 1u << 16;  // slots scanned per group by one insert()

std::uint64_t pack(glm::uvec3 p) { return std::uint64_t(p.x) | std::uint64_t(p.y) << 21 | std::uint64_t(p.z) << 42; }
glm::uvec3 unpack(std::uint64_t k) {
    return {std::uint32_t(k & 0x1FFFFF), std::uint32_t((k >> 21) & 0x1FFFFF), std::uint32_t(k >> 42)};
}
std::uint32_t packOffset(std::uint32_t x, std::uint32_t y, std::uint32_t z) { return x | y << 10 | z << 20; }

int sideFor(double count) {  // smallest side with side^3 >= count (at least 1)
    int s = std::max(1, int(std::floor(std::cbrt(count))));
    while (double(s) * s * s < count) ++s;
    return s;
}

}  // namespace

std::uint32_t PerfectSpatialHash::group(std::uint64_t key) const { return offsetIndex(unpack(key)); }

std::uint32_t PerfectSpatialHash::offsetIndex(glm::uvec3 p) const {
    std::uint32_t m = std::uint32_t(m_), q = std::uint32_t(q_);
    glm::uvec3 c = p % m, d = p / m;
    std::uint32_t h = (c.x * 73856093u) ^ (c.y * 19349663u) ^ (c.z * 83492791u);
    h ^= h >> 16;
    h *= 0x7FEB352Du;
    h ^= h >> 15;
    std::uint32_t r3 = std::uint32_t(r_) * std::uint32_t(r_) * std::uint32_t(r_);
    return (h % r3 + (d.x + q * (d.y + q * d.z)) % r3) % r3;
}

std::uint32_t PerfectSpatialHash::slotWith(std::uint64_t key, std::uint32_t offset) const {
    glm::uvec3 p = unpack(key);
    std::uint32_t m = std::uint32_t(m_);
    std::uint32_t hx = (p.x + (offset & 1023)) % m, hy = (p.y + ((offset >> 10) & 1023)) % m,
                  hz = (p.z + (offset >> 20)) % m;
    return hx + m * (hy + m * hz);
}

std::uint32_t PerfectSpatialHash::slot(glm::uvec3 key) const {
    if (m_ == 0) return 0;
    std::uint64_t k = pack(key);
    return slotWith(k, offsets_[group(k)]);
}

const std::uint64_t* PerfectSpatialHash::find(glm::uvec3 key) const {
    if (m_ == 0 || key.x > kMaxCoord || key.y > kMaxCoord || key.z > kMaxCoord) return nullptr;
    std::uint64_t k = pack(key);
    std::uint32_t g = group(k);
    if (head_[g] == kNone) return nullptr;
    std::uint32_t s = slotWith(k, offsets_[g]);
    return keys_[s] == k ? &values_[s] : nullptr;
}

bool PerfectSpatialHash::set(glm::uvec3 key, std::uint64_t value) {
    const std::uint64_t* v = find(key);
    if (!v) return false;
    std::uint32_t s = std::uint32_t(v - values_.data());
    values_[s] = value;
    touchSlot(s);
    return true;
}

void PerfectSpatialHash::touchSlot(std::uint32_t s) {
    dirty_.slot_begin = std::min(dirty_.slot_begin, s);
    dirty_.slot_end = std::max(dirty_.slot_end, s + 1);
}

void PerfectSpatialHash::touchOffset(std::uint32_t g) {
    dirty_.offset_begin = std::min(dirty_.offset_begin, g);
    dirty_.offset_end = std::max(dirty_.offset_end, g + 1);
}

bool PerfectSpatialHash::fits(std::span<const Item> items, std::uint32_t offset) const {
    for (std::size_t i = 0; i < items.size(); ++i) {
        std::uint32_t s = slotWith(items[i].key, offset);
        if (keys_[s] != kEmpty) return false;
        for (std::size_t j = 0; j < i; ++j)  // keys mbar * rbar apart share a slot
            if (slotWith(items[j].key, offset) == s) return false;
    }
    return true;
}

void PerfectSpatialHash::store(std::uint32_t g, std::span<const Item> items, std::uint32_t offset) {
    if (offsets_[g] != offset) {
        offsets_[g] = offset;
        touchOffset(g);
    }
    for (const Item& it : items) {
        std::uint32_t s = slotWith(it.key, offset);
        keys_[s] = it.key;
        values_[s] = it.value;
        next_[s] = head_[g];
        head_[g] = s;
        touchSlot(s);
    }
    n_ += items.size();
}

bool PerfectSpatialHash::placeGroup(std::uint32_t g, std::span<const Item> items, std::uint64_t& rng_state,
                                    std::size_t scan_limit) {
    std::uint32_t m = std::uint32_t(m_);
    Rng rng(rng_state);
    for (int t = 0; t < kRandomTries; ++t) {
        std::uint32_t o = packOffset(rng.below(m), rng.below(m), rng.below(m));
        if (fits(items, o)) {
            rng_state = rng.next();
            store(g, items, o);
            return true;
        }
    }
    // Then every offset that puts the first key on a free slot, from a random slot on: an
    // exhaustive search when scan_limit covers the table (construction), bounded for edits.
    std::size_t slots = keys_.size(), start = std::size_t(rng.below(std::uint32_t(slots)));
    rng_state = rng.next();
    glm::uvec3 p = unpack(items[0].key);
    std::size_t limit = std::min(slots, scan_limit);
    for (std::size_t i = 0; i < limit; ++i) {
        std::uint32_t s = std::uint32_t((start + i) % slots);
        if (keys_[s] != kEmpty) continue;
        std::uint32_t sx = s % m, sy = (s / m) % m, sz = s / (m * m);
        std::uint32_t o = packOffset((sx + m - p.x % m) % m, (sy + m - p.y % m) % m, (sz + m - p.z % m) % m);
        if (items.size() == 1 || fits(items, o)) {
            store(g, items, o);
            return true;
        }
    }
    return false;
}

bool PerfectSpatialHash::tryBuild(std::span<const Item> items, int m, int r, std::uint32_t extent, std::uint64_t seed) {
    m_ = m;
    r_ = r;
    q_ = int((extent + std::uint32_t(m) - 1) / std::uint32_t(m));
    n_ = 0;
    std::size_t slots = std::size_t(m) * m * m, entries = std::size_t(r) * r * r;
    keys_.assign(slots, kEmpty);
    values_.assign(slots, 0);
    next_.assign(slots, kNone);
    offsets_.assign(entries, 0);
    head_.assign(entries, kNone);
    // Keys grouped by offset entry (counting sort), groups placed largest first.
    std::vector<std::uint32_t> start(entries + 1, 0);
    for (const Item& it : items) ++start[group(it.key) + 1];
    std::partial_sum(start.begin(), start.end(), start.begin());
    std::vector<Item> sorted(items.size());
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for (const Item& it : items) sorted[fill[group(it.key)]++] = it;
    std::vector<std::uint32_t> order;
    for (std::uint32_t g = 0; g < entries; ++g)
        if (start[g + 1] > start[g]) order.push_back(g);
    std::stable_sort(order.begin(), order.end(),
                     [&](std::uint32_t a, std::uint32_t b) { return start[a + 1] - start[a] > start[b + 1] - start[b]; });
    std::uint64_t rng_state = seed;
    for (std::uint32_t g : order)
        if (!placeGroup(g, std::span<const Item>(sorted).subspan(start[g], start[g + 1] - start[g]), rng_state, keys_.size()))
            return false;
    return true;
}

bool PerfectSpatialHash::build(std::span<const glm::uvec3> keys, std::span<const std::uint64_t> values,
                               const Options& options) {
    std::vector<Item> items(keys.size());
    std::uint32_t extent = std::max<std::uint32_t>(options.key_extent, 1);
    for (std::size_t i = 0; i < keys.size(); ++i) {
        glm::uvec3 k = keys[i];
        if (k.x > kMaxCoord || k.y > kMaxCoord || k.z > kMaxCoord) return false;
        if (options.key_extent == 0) extent = std::max({extent, k.x + 1, k.y + 1, k.z + 1});
        items[i] = {pack(k), i < values.size() ? values[i] : 0};
    }
    double n = double(items.size());
    int base_m = sideFor((items.size() <= 255 ? n : 1.01 * n) * (1.0 + std::max(options.slack, 0.0)));
    double r_count = std::max(1.0, n * std::clamp(options.offset_ratio, 1e-3, 8.0));
    rng_ = options.seed ^ 0x5DEECE66Dull;
    for (int a = 0; a < std::max(options.max_attempts, 1); ++a, r_count *= 1.5) {
        int m = base_m + a / 3;
        if (m > kMaxSide) break;
        int r = sideFor(r_count);
        if (tryBuild(items, m, r, extent, hashIndex(options.seed, std::uint64_t(a)))) {
            attempts_ = a + 1;
            dirty_ = {};
            dirty_.resized = true;
            dirty_.slot_begin = dirty_.offset_begin = 0;
            dirty_.slot_end = std::uint32_t(keys_.size());
            dirty_.offset_end = std::uint32_t(offsets_.size());
            return true;
        }
    }
    *this = PerfectSpatialHash();
    attempts_ = options.max_attempts;
    return false;
}

bool PerfectSpatialHash::insert(glm::uvec3 key, std::uint64_t value) {
    if (m_ == 0 || key.x > kMaxCoord || key.y > kMaxCoord || key.z > kMaxCoord) return false;
    if (set(key, value)) return true;
    if (n_ + 1 > keys_.size()) return false;
    std::uint64_t k = pack(key);
    std::uint32_t g = group(k);
    Item item{k, value};
    if (head_[g] == kNone) return placeGroup(g, {&item, 1}, rng_, keys_.size());  // finds any free slot
    std::uint32_t s = slotWith(k, offsets_[g]);
    if (keys_[s] == kEmpty) {
        store(g, {&item, 1}, offsets_[g]);
        return true;
    }
    // The group's slot is taken: move the whole group, new key included, to another offset.
    std::vector<Item> items;
    for (std::uint32_t t = head_[g]; t != kNone; t = next_[t]) items.push_back({keys_[t], values_[t]});
    std::uint32_t old_offset = offsets_[g];
    for (std::uint32_t t = head_[g]; t != kNone;) {
        std::uint32_t after = next_[t];
        keys_[t] = kEmpty;
        values_[t] = 0;
        next_[t] = kNone;
        touchSlot(t);
        t = after;
    }
    head_[g] = kNone;
    n_ -= items.size();
    std::size_t old_count = items.size();
    items.push_back(item);
    if (placeGroup(g, items, rng_, kEditScan)) return true;
    store(g, std::span<const Item>(items).first(old_count), old_offset);
    return false;
}

void PerfectSpatialHash::unlink(std::uint32_t g, std::uint32_t s) {
    if (head_[g] == s) {
        head_[g] = next_[s];
    } else {
        std::uint32_t t = head_[g];
        while (next_[t] != s) t = next_[t];
        next_[t] = next_[s];
    }
    next_[s] = kNone;
}

bool PerfectSpatialHash::erase(glm::uvec3 key) {
    const std::uint64_t* v = find(key);
    if (!v) return false;
    std::uint32_t s = std::uint32_t(v - values_.data());
    unlink(group(keys_[s]), s);
    keys_[s] = kEmpty;
    values_[s] = 0;
    touchSlot(s);
    --n_;
    return true;
}

std::vector<std::pair<glm::uvec3, std::uint64_t>> PerfectSpatialHash::entries() const {
    std::vector<std::pair<glm::uvec3, std::uint64_t>> out;
    out.reserve(n_);
    for (std::size_t s = 0; s < keys_.size(); ++s)
        if (keys_[s] != kEmpty) out.emplace_back(unpack(keys_[s]), values_[s]);
    return out;
}

std::size_t PerfectSpatialHash::cpuBytes() const {
    return keys_.size() * (8 + 8 + 4) + offsets_.size() * (4 + 4);
}

}  // namespace vista
