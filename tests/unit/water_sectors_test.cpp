// The sea grid's sector cull (terrain/water/grid_sectors.h) on the CPU: every displaced grid
// point that lies inside the view frustum belongs to a drawn segment, over eye heights above and
// below the surface, headings and pitches; a view along the horizon draws under half the
// circle, a view straight down all of it, a view of the sky from under the cloud base none.
#include "renderer/camera.h"
#include "terrain/water/grid_sectors.h"
#include "terrain/water/water.h"

#include <doctest/doctest.h>

#include <cmath>
#include <random>

using namespace vista;

namespace {

bool sectorDrawn(const SectorRange& r, int segment, int segments) {
    return ((segment - r.first) % segments + segments) % segments < r.count;
}

bool insideFrustum(const Frustum& f, const glm::dvec3& p) {
    for (const glm::dvec4& plane : f)
        if (glm::dot(glm::dvec3(plane), p) + plane.w < 0.0) return false;
    return true;
}

struct SectorCase {
    SectorRange range;
    int seen = 0;    // sampled displaced points inside the frustum
    int missed = 0;  // of those, in a segment that is not drawn
};

// Samples every cell of the grid (two random rest points each, randomly displaced within the bounds).
SectorCase sampleSectors(double height, double yaw, double pitch, double max_height, double max_chop) {
    WaterSettings s;
    const WaterGrid grid = waterGrid(s, height);
    ViewParams v;
    v.position = {0.0, height, 0.0};
    v.yaw_deg = yaw;
    v.pitch_deg = pitch;
    v.width = 1280;
    v.height = 720;
    const Frustum f = frustumFromViewProj(glm::dmat4(viewMatrices(v).view_proj));
    SectorCase out;
    out.range = visibleSectors(grid, height, max_height, max_chop, f);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    auto radius = [&](int j) { return grid.ring_constant * std::expm1(grid.angle * j); };
    for (int i = 0; i < grid.segments; ++i)
        for (int j = 0; j < grid.rings; ++j)
            for (int k = 0; k < 2; ++k) {
                const double r = radius(j) + (radius(j + 1) - radius(j)) * u(rng);
                const double a = grid.angle * (double(i) + u(rng));
                const glm::dvec3 d{max_chop * (2.0 * u(rng) - 1.0), max_height * (2.0 * u(rng) - 1.0),
                                   max_chop * (2.0 * u(rng) - 1.0)};
                const glm::dvec3 p = glm::dvec3(r * std::cos(a), -height, r * std::sin(a)) + d;
                if (!insideFrustum(f, p)) continue;
                ++out.seen;
                if (!sectorDrawn(out.range, i, grid.segments)) ++out.missed;
            }
    return out;
}

}  // namespace

TEST_CASE("water: the grid's sector cull keeps every segment a displaced point in view lies in") {
    int seen = 0;
    for (double height : {-6.0, 1.5, 40.0, 300.0, 4000.0})
        for (double pitch : {-89.0, -40.0, -10.0, 0.0, 25.0})
            for (double yaw : {0.0, 37.0, 133.0, 251.0}) {
                CAPTURE(height);
                CAPTURE(pitch);
                CAPTURE(yaw);
                const SectorCase c = sampleSectors(height, yaw, pitch, 2.5, 1.8);
                CHECK(c.missed == 0);
                seen += c.seen;
            }
    CHECK(seen > 10000);  // the views do see the sea
}

TEST_CASE("water: the grid's sector cull draws under half the circle along the horizon, all of it looking down") {
    WaterSettings s;
    for (double yaw : {0.0, 90.0, 200.0, 315.0}) {
        CAPTURE(yaw);
        const SectorCase level = sampleSectors(300.0, yaw, -10.0, 2.5, 1.8);
        CHECK(level.seen > 0);
        CHECK(level.range.count > 0);
        CHECK(level.range.count < s.grid_segments / 2);
        CHECK(sampleSectors(300.0, yaw, -89.0, 2.5, 1.8).range.count == s.grid_segments);
    }
    // From 300 m up, looking 60 degrees above the horizon (30 degrees half field of view): the
    // sea is out of view, nothing is drawn.
    const SectorCase sky = sampleSectors(300.0, 45.0, 60.0, 2.5, 1.8);
    CHECK(sky.seen == 0);
    CHECK(sky.range.count == 0);
}
