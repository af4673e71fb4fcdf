// Per-cell scatter placement (see scatter.h).
#include "terrain/scatter/scatter.h"

#include "renderer/random.h"

#include <glm/common.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace vista {
namespace {

std::string shortNumber(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", v);
    return text;
}

std::string metres(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.0f", v);
    return text;
}

double unit(std::uint32_t h, std::uint32_t k) { return double(hashInts(h, k, 0x2545f491u, 0x9e3779b9u) >> 8) / 16777216.0; }

}  // namespace

glm::ivec2 scatterCellOf(const ScatterRule& r, glm::dvec2 xz) {
    return glm::ivec2(int(std::floor(xz.x / r.cell_m)), int(std::floor(xz.y / r.cell_m)));
}

int scatterCandidates(const ScatterRule& r, glm::ivec2 cell) {
    const double mean = r.density * double(r.cell_m) * double(r.cell_m);
    const std::uint32_t h = hashInts(std::uint32_t(cell.x), std::uint32_t(cell.y), r.seed, 0xc0ffeeu);
    return int(std::floor(mean + unit(h, 0)));
}

void scatterCell(const ScatterRule& r, glm::ivec2 cell, const GroundFunction& ground, std::vector<PlacedObject>& out) {
    if (r.files.empty()) return;
    const int n = scatterCandidates(r, cell);
    for (int j = 0; j < n; ++j) {
        const std::uint32_t h = hashInts(std::uint32_t(cell.x), std::uint32_t(cell.y), std::uint32_t(j), r.seed);
        const double x = (double(cell.x) + unit(h, 1)) * r.cell_m, z = (double(cell.y) + unit(h, 2)) * r.cell_m;
        const GroundSample g = ground(x, z);
        if (!g.valid || g.height_m < r.height_min_m || g.height_m > r.height_max_m || g.slope > r.slope_max ||
            g.grass < r.grass_min)
            continue;
        PlacedObject p;
        p.position = glm::dvec3(x, g.height_m, z);
        p.yaw_rad = float(unit(h, 3) * 6.283185307179586);
        p.scale = float(r.scale_min + (r.scale_max - r.scale_min) * unit(h, 4));
        p.file = std::min(int(unit(h, 5) * double(r.files.size())), int(r.files.size()) - 1);
        out.push_back(p);
    }
}

std::vector<PlacedObject> scatterRegion(const ScatterRule& r, glm::ivec2 min_cell, glm::ivec2 max_cell,
                                        const GroundFunction& ground) {
    std::vector<PlacedObject> out;
    for (int k = min_cell.y; k <= max_cell.y; ++k)
        for (int i = min_cell.x; i <= max_cell.x; ++i) scatterCell(r, {i, k}, ground, out);
    return out;
}

ScatterArea terrainScatterArea(const glm::dvec3& origin, double size_m) {
    const double half = size_m * 0.5;
    return {{origin.x - half, origin.z - half}, {origin.x + half, origin.z + half}};
}

ScatterArea localScatterArea(glm::dvec2 centre, double max_distance_m) {
    const double half = kLocalScatterReach * max_distance_m;
    return {centre - half, centre + half};
}

double localScatterDrift(glm::dvec2 centre, glm::dvec2 camera) {
    const glm::dvec2 d = glm::abs(camera - centre);
    return std::max(d.x, d.y);
}

bool localScatterStale(glm::dvec2 centre, glm::dvec2 camera, double max_distance_m) {
    return localScatterDrift(centre, camera) > (kLocalScatterReach - 1.0) * max_distance_m;
}

std::string scatterBudgetProblem(const ObjectsSettings& s, const ScatterArea& area, const std::string& where) {
    const glm::dvec2 extent = glm::max(area.max - area.min, glm::dvec2(0.0));
    double total = 0.0;
    std::string each;
    for (const NamedScatter& sc : s.scatters) {
        if (sc.rule.files.empty()) continue;
        const double n = sc.rule.density * extent.x * extent.y;
        total += n;
        each += (each.empty() ? "" : ", ") + ("scatter." + sc.name) + " " + shortNumber(n);
    }
    if (total <= kMaxScatterCandidates) return {};
    return "the scatter rules would test " + shortNumber(total) + " candidates over " + where + " " + metres(extent.x) +
           " x " + metres(extent.y) + " m (" + each + "); accepted: at most " + shortNumber(kMaxScatterCandidates) +
           " (lower the densities or [objects] max_distance_m, or [objects] enabled = false)";
}

std::vector<ObjectPlacement> placeObjects(const ObjectsSettings& s, const GroundFunction& ground, const ScatterArea& area) {
    std::vector<ObjectPlacement> out;
    for (const NamedObject& o : s.objects) {
        PlacedObject p;
        p.position = o.object.position;
        if (o.object.ground_m >= 0.0f) {
            const GroundSample g = ground ? ground(p.position.x, p.position.z) : GroundSample{};
            p.position.y = (g.valid ? g.height_m : 0.0) + o.object.ground_m;
        }
        p.yaw_rad = float(glm::radians(double(o.object.yaw_deg)));
        p.scale = o.object.scale;
        out.push_back({"object." + o.name, {o.object.file}, {p}});
    }
    for (const NamedScatter& sc : s.scatters) {
        ObjectPlacement& placement = out.emplace_back(ObjectPlacement{"scatter." + sc.name, sc.rule.files, {}});
        if (!ground || area.max.x <= area.min.x) continue;  // scatter needs a terrain
        placement.instances = scatterRegion(sc.rule, scatterCellOf(sc.rule, area.min), scatterCellOf(sc.rule, area.max), ground);
    }
    return out;
}

bool samePlacement(const ObjectsSettings& a, const ObjectsSettings& b) { return a.objects == b.objects && a.scatters == b.scatters; }

}  // namespace vista
