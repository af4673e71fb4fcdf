// Hashed shading's structures: the perfect spatial hash (every key its own slot, absent keys
// rejected, incremental edits), and the light octree (queries a superset of brute force and
// equal to the leaf cell's lights, incremental updates equal to a fresh build, memory bound,
// zero-radius lights, 100,000 lights).
#include "renderer/lighting/light_hash.h"
#include "renderer/random.h"

#include <doctest/doctest.h>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <chrono>
#include <set>
#include <unordered_set>

using namespace vista;

namespace {

std::vector<glm::uvec3> randomKeys(Rng& rng, std::size_t n, std::uint32_t extent) {
    std::set<std::tuple<std::uint32_t, std::uint32_t, std::uint32_t>> seen;
    std::vector<glm::uvec3> keys;
    while (keys.size() < n) {
        glm::uvec3 k(rng.below(extent), rng.below(extent), rng.below(extent));
        if (seen.insert({k.x, k.y, k.z}).second) keys.push_back(k);
    }
    return keys;
}

std::uint64_t valueOf(glm::uvec3 k) { return std::uint64_t(k.x) * 1000003u + std::uint64_t(k.y) * 7919u + k.z + 1u; }

// Every key found with its value, and no two keys in one slot.
void checkPerfect(const PerfectSpatialHash& h, const std::vector<glm::uvec3>& keys) {
    REQUIRE(h.size() == keys.size());
    std::unordered_set<std::uint32_t> slots;
    for (glm::uvec3 k : keys) {
        const std::uint64_t* v = h.find(k);
        REQUIRE(v != nullptr);
        CHECK(*v == valueOf(k));
        std::uint32_t s = h.slot(k);
        CHECK(s < h.slotCount());
        CHECK(h.values()[s] == valueOf(k));
        CHECK(slots.insert(s).second);
    }
}

std::vector<Sphere> randomLights(Rng& rng, std::size_t n, glm::dvec3 lo, glm::dvec3 hi, double r0, double r1) {
    std::vector<Sphere> out(n);
    for (Sphere& s : out) {
        s.center = {rng.uniform(lo.x, hi.x), rng.uniform(lo.y, hi.y), rng.uniform(lo.z, hi.z)};
        s.radius = rng.uniform(r0, r1);
    }
    return out;
}

// The lights whose sphere, grown by guard, touches the leaf cell holding p (brute force).
std::vector<std::uint32_t> bruteCell(const LightHash& h, const std::vector<Sphere>& lights, glm::dvec3 p, double guard) {
    double d = h.nodeSize();
    glm::dvec3 lo = glm::floor((p - h.origin()) / d) * d + h.origin(), hi = lo + d;
    std::vector<std::uint32_t> out;
    for (std::size_t i = 0; i < lights.size(); ++i) {
        if (!(lights[i].radius > 0.0)) continue;
        double r = lights[i].radius + guard;
        glm::dvec3 v = glm::clamp(lights[i].center, lo, hi) - lights[i].center;
        if (glm::dot(v, v) <= r * r) out.push_back(std::uint32_t(i));
    }
    return out;
}

std::vector<std::uint32_t> sorted(std::span<const std::uint32_t> s) {
    std::vector<std::uint32_t> v(s.begin(), s.end());
    std::sort(v.begin(), v.end());
    return v;
}

// Random points, many near lights: the query holds every light that reaches the point, and equals
// the brute-force list of its leaf cell.
void checkQueries(const LightHash& h, const std::vector<Sphere>& lights, Rng& rng, int points, double guard) {
    for (int i = 0; i < points; ++i) {
        glm::dvec3 p;
        if (i % 2 && !lights.empty()) {
            const Sphere& s = lights[rng.below(std::uint32_t(lights.size()))];
            p = s.center + glm::dvec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)) * (s.radius * 1.2 + 0.01);
        } else {
            p = h.origin() + glm::dvec3(rng.uniform(), rng.uniform(), rng.uniform()) * (h.nodeSize() * std::ldexp(1.0, h.levels()));
        }
        std::vector<std::uint32_t> got = sorted(h.query(p));
        CHECK(std::is_sorted(got.begin(), got.end()));
        for (std::size_t j = 0; j < lights.size(); ++j)
            if (glm::length(p - lights[j].center) < lights[j].radius)
                CHECK_MESSAGE(std::binary_search(got.begin(), got.end(), std::uint32_t(j)), "light ", j, " missing");
        CHECK(got == bruteCell(h, lights, p, guard));
        CHECK(got == sorted(h.cellLights(p)));
    }
}

}  // namespace

TEST_CASE("perfect hash: every key gets its own slot and absent keys are rejected") {
    Rng rng(1);
    for (std::size_t n : {std::size_t(0), std::size_t(1), std::size_t(7), std::size_t(255), std::size_t(256),
                          std::size_t(3000), std::size_t(60000)}) {
        std::vector<glm::uvec3> keys = randomKeys(rng, n, n < 300 ? 64u : 1024u);
        std::vector<std::uint64_t> values;
        for (glm::uvec3 k : keys) values.push_back(valueOf(k));
        PerfectSpatialHash h;
        REQUIRE(h.build(keys, values, {}));
        checkPerfect(h, keys);
        // 002's sizes: m^3 >= n (n <= 255) or 1.01 n, r^3 >= n / 6 (grown on failure).
        double m3 = std::pow(double(h.tableSide()), 3.0);
        CHECK(m3 >= (n <= 255 ? double(n) : 1.01 * double(n)));
        CHECK(std::pow(double(h.offsetSide()), 3.0) >= double(n) / 6.0);
        MESSAGE("n = ", n, ": mbar = ", h.tableSide(), ", rbar = ", h.offsetSide(), ", attempts = ", h.attempts(),
                ", load = ", double(n) / std::max(m3, 1.0));
        std::set<std::tuple<std::uint32_t, std::uint32_t, std::uint32_t>> present;
        for (glm::uvec3 k : keys) present.insert({k.x, k.y, k.z});
        for (int i = 0; i < 2000; ++i) {
            glm::uvec3 k(rng.below(2048), rng.below(2048), rng.below(2048));
            if (!present.count({k.x, k.y, k.z})) CHECK(h.find(k) == nullptr);
        }
        CHECK(h.find(glm::uvec3(PerfectSpatialHash::kMaxCoord + 1, 0, 0)) == nullptr);
        // Deterministic: the same keys and seed give the same tables.
        PerfectSpatialHash again;
        REQUIRE(again.build(keys, values, {}));
        CHECK(std::equal(h.offsets().begin(), h.offsets().end(), again.offsets().begin(), again.offsets().end()));
        CHECK(std::equal(h.values().begin(), h.values().end(), again.values().begin(), again.values().end()));
    }
}

TEST_CASE("perfect hash: inserts and erases one at a time keep it perfect") {
    Rng rng(2);
    std::vector<glm::uvec3> all = randomKeys(rng, 6000, 512);
    std::vector<glm::uvec3> keys(all.begin(), all.begin() + 3000);
    std::vector<std::uint64_t> values;
    for (glm::uvec3 k : keys) values.push_back(valueOf(k));
    PerfectSpatialHash h;
    PerfectSpatialHash::Options options;
    options.slack = 0.5;         // room for more keys
    options.offset_ratio = 1.0;  // about one key per offset entry: groups move easily
    REQUIRE(h.build(keys, values, options));
    h.clearDirty();
    std::size_t refused = 0;
    for (std::size_t i = 3000; i < 3600; ++i) {
        if (h.insert(all[i], valueOf(all[i]))) keys.push_back(all[i]);
        else ++refused;
    }
    MESSAGE("600 inserts into 3000 keys in ", h.slotCount(), " slots: ", refused, " refused (a rebuild would follow)");
    CHECK(refused < 30);
    CHECK(h.dirty().slot_begin < h.dirty().slot_end);
    CHECK(!h.dirty().resized);
    for (std::size_t i = 0; i < 1000; ++i) CHECK(h.erase(keys[i]));
    CHECK(!h.erase(keys[0]));
    keys.erase(keys.begin(), keys.begin() + 1000);
    checkPerfect(h, keys);
    for (std::size_t i = 0; i < 10; ++i) CHECK(h.find(all[i]) == nullptr);
    // An existing key's value can change in place.
    CHECK(h.set(keys[0], 5));
    CHECK(*h.find(keys[0]) == 5);
}

TEST_CASE("light hash: queries hold every reaching light and equal the leaf cell's lights") {
    Rng rng(3);
    LightHashSettings settings;
    for (double node : {0.0, 2.0, 10.0, 40.0}) {
        std::vector<Sphere> lights = randomLights(rng, 400, {-200, 0, -200}, {200, 60, 200}, 1.0, 25.0);
        lights[5].radius = 0.0;  // zero-radius lights reach nothing
        lights[6].radius = 60.0;  // one light much larger than the rest
        settings.node_size_m = node;
        LightHash h;
        const LightHashStats& st = h.build(lights, settings);
        REQUIRE(st.ok);
        CHECK(!st.degraded);
        CHECK(st.levels >= 1);
        CHECK(st.gpu_bytes > 0);
        CHECK(st.cpu_bytes > st.gpu_bytes / 2);
        MESSAGE("node ", st.node_size_m, " m: ", st.levels, " levels, ", st.branch_nodes, " branch nodes, ", st.filled_leaves,
                " filled leaves (", st.leaf_cells, " leaf cells), ", st.index_count, " indices, ", st.gpu_bytes,
                " GPU bytes, ", st.ms, " ms");
        CHECK(st.filled_leaves <= st.leaf_cells);
        checkQueries(h, lights, rng, 1500, settings.guard_m);
        for (std::size_t i = 0; i < h.indices().size(); ++i) CHECK(h.indices()[i] != 5u);
        CHECK(h.query(h.origin() - 1.0).empty());  // outside the root cube
    }
}

TEST_CASE("light hash: no lights and only zero-radius lights build an empty structure") {
    LightHash h;
    CHECK(h.build({}, {}).ok);
    CHECK(h.levels() == 0);
    CHECK(h.query({0.0, 0.0, 0.0}).empty());
    std::vector<Sphere> zero(100, Sphere{{1.0, 2.0, 3.0}, 0.0});
    const LightHashStats& st = h.build(zero, {});
    CHECK(st.ok);
    CHECK(st.levels == 0);
    CHECK(h.query({1.0, 2.0, 3.0}).empty());
    // Lights appearing later: the update builds.
    zero[3].radius = 5.0;
    h.update(zero);
    CHECK(h.stats().ok);
    CHECK(h.query({1.0, 2.0, 3.0}).size() == 1);
}

TEST_CASE("light hash: incremental updates of moving, added and removed lights equal a fresh build") {
    Rng rng(4);
    LightHashSettings settings;
    settings.node_size_m = 4.0;
    settings.bounds_min = {-300, -50, -300};  // the root cube covers the play area: no rebuilds
    settings.bounds_max = {300, 100, 300};
    std::vector<Sphere> lights = randomLights(rng, 600, {-150, 0, -150}, {150, 40, 150}, 2.0, 12.0);
    LightHash h;
    REQUIRE(h.build(lights, settings).ok);
    std::size_t rebuilt = 0, written = 0;
    for (int frame = 0; frame < 12; ++frame) {
        for (std::size_t i = 0; i < lights.size(); i += 3)  // a third of the lights move a little
            lights[i].center += glm::dvec3(rng.uniform(-1.5, 1.5), rng.uniform(-0.5, 0.5), rng.uniform(-1.5, 1.5));
        if (frame == 4) lights.resize(560);  // removed at the end
        if (frame == 5) lights[17].radius = 0.0;  // switched off
        if (frame == 6)
            for (const Sphere& s : randomLights(rng, 50, {-150, 0, -150}, {150, 40, 150}, 2.0, 12.0)) lights.push_back(s);
        if (frame == 7) lights[20].radius *= 2.0;
        const LightHashStats& st = h.update(lights);
        REQUIRE(st.ok);
        CHECK(!st.full_rebuild);
        rebuilt += st.tables_rebuilt;
        written += st.entries_written;
        if (frame == 0)
            MESSAGE("one update of ", st.lights_changed, " moved lights: ", st.cells_changed, " leaf cells changed, ",
                    st.entries_written, " table entries written, ", st.tables_rebuilt, " tables rebuilt, ", st.ms, " ms");
        LightHash fresh;
        REQUIRE(fresh.build(lights, settings).ok);
        CHECK(fresh.levels() == h.levels());
        CHECK(fresh.origin() == h.origin());
        CHECK(fresh.stats().branch_nodes == st.branch_nodes);
        CHECK(fresh.stats().filled_leaves == st.filled_leaves);
        CHECK(fresh.stats().index_count == st.index_count - st.index_garbage);
        for (int i = 0; i < 600; ++i) {
            const Sphere& s = lights[rng.below(std::uint32_t(lights.size()))];
            glm::dvec3 p = s.center + glm::dvec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)) * (s.radius + 1.0);
            CHECK(sorted(h.query(p)) == sorted(fresh.query(p)));
        }
        // Same tables, entry for entry (node masks; leaf lists through their ranges).
        for (int l = 0; l < h.levels(); ++l) {
            auto a = h.nodeTable(l).entries(), b = fresh.nodeTable(l).entries();
            auto less = [](const auto& x, const auto& y) {
                return std::tie(x.first.x, x.first.y, x.first.z) < std::tie(y.first.x, y.first.y, y.first.z);
            };
            std::sort(a.begin(), a.end(), less);
            std::sort(b.begin(), b.end(), less);
            CHECK(a == b);
        }
        checkQueries(h, lights, rng, 300, settings.guard_m);
    }
    MESSAGE("12 updates: ", rebuilt, " table rebuilds, ", written, " entries written one by one");
    // Moving a light out of the root cube rebuilds everything.
    lights[0].center = {5000.0, 0.0, 0.0};
    CHECK(h.update(lights).full_rebuild);
    checkQueries(h, lights, rng, 300, settings.guard_m);
    // Nothing changed: nothing to do.
    const LightHashStats& idle = h.update(lights);
    CHECK(!idle.full_rebuild);
    CHECK(idle.lights_changed == 0);
    CHECK(idle.entries_written == 0);
}

TEST_CASE("light hash: the memory bound coarsens the nodes, or refuses clearly") {
    Rng rng(6);
    std::vector<Sphere> lights = randomLights(rng, 800, {-300, 0, -300}, {300, 50, 300}, 3.0, 8.0);
    LightHashSettings settings;
    settings.node_size_m = 1.0;
    LightHash h;
    const LightHashStats& fine = h.build(lights, settings);
    REQUIRE(fine.ok);
    std::size_t fine_bytes = fine.gpu_bytes;
    settings.memory_budget_bytes = fine_bytes / 8;
    const LightHashStats& st = h.build(lights, settings);
    REQUIRE(st.ok);
    CHECK(st.degraded);
    CHECK(st.node_size_m > 1.0);
    CHECK(st.gpu_bytes <= settings.memory_budget_bytes);
    CHECK(!st.message.empty());
    MESSAGE("budget ", settings.memory_budget_bytes, " bytes: ", st.message, " (", st.gpu_bytes, " bytes; ", fine_bytes,
            " at 1 m)");
    checkQueries(h, lights, rng, 300, settings.guard_m);
    settings.memory_budget_bytes = 1024;
    const LightHashStats& refused = h.build(lights, settings);
    CHECK(!refused.ok);
    CHECK(refused.message.find("not built") != std::string::npos);
    CHECK(h.levels() == 0);
    CHECK(h.query(lights[0].center).empty());
}

TEST_CASE("light hash: 100,000 lights build, and 1,000 of them move") {
    Rng rng(8);
    // 002-style generation: lights of one radius spread through a large volume.
    std::vector<Sphere> lights = randomLights(rng, 100000, {-2000, 0, -2000}, {2000, 100, 2000}, 10.0, 10.0);
    LightHashSettings settings;
    settings.node_size_m = 10.0;
    LightHash h;
    auto t0 = std::chrono::steady_clock::now();
    const LightHashStats& st = h.build(lights, settings);
    double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    REQUIRE(st.ok);
    MESSAGE("100k lights, node 10 m: ", ms, " ms, ", st.levels, " levels, ", st.branch_nodes, " branch nodes, ",
            st.filled_leaves, " filled leaves, ", st.index_count, " indices, ", st.gpu_bytes, " GPU bytes, ", st.cpu_bytes,
            " CPU bytes");
    CHECK(st.gpu_bytes > 0);
    for (int i = 0; i < 300; ++i) {
        const Sphere& s = lights[rng.below(std::uint32_t(lights.size()))];
        glm::dvec3 p = s.center + glm::dvec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)) * s.radius;
        std::vector<std::uint32_t> got = sorted(h.query(p));
        CHECK(got == bruteCell(h, lights, p, settings.guard_m));
    }
    for (std::size_t i = 0; i < 1000; ++i) lights[i * 100].center.x += 3.0;
    const LightHashStats& up = h.update(lights);
    REQUIRE(up.ok);
    CHECK(!up.full_rebuild);
    MESSAGE("1,000 of 100k lights moved 3 m: ", up.ms, " ms, ", up.cells_changed, " cells changed, ", up.entries_written,
            " entries written, ", up.tables_rebuilt, " tables rebuilt");
}
