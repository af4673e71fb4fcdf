// Tessellated displacement (docs/terrain-detail.md) against its CPU mirror
// (terrain/tess_displacement.h): the rendered depth of a displaced flat plane, unprojected to world
// points, lies where tessDisplacement() puts the surface, and does not where a mirror with another
// amplitude or fade range would; the sun cascades that serve displaced ground draw displaced
// casters, so the displaced plane does not shadow itself (no acne against tessellation off); so do
// a spot light's atlas tile and a point light's cube faces (flat casters there leave 92-99% of
// the lamp-lit displaced plane in shadow).
#include "renderer_fixture.h"
#include "renderer/camera.h"
#include "terrain/materials.h"
#include "terrain/tess_displacement.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

using namespace vista;

namespace {

FrameRenderer& renderer() { return test::fileRenderer(); }

constexpr float kSample = 0.5f;  // the flat map's height sample

// A flat plane, the relief deep (1 m) and broad (a 64 m repeat: its features span many
// tessellated vertices, so the piecewise-linear surface follows the relief closely), fine factors.
Settings displacedPlane() {
    Settings s;
    s.terrain.size_m = 1024.0f;
    s.terrain.height_scale_m = 100.0f;
    s.terrain.texture_scale_m = 64.0f;
    // The finest grid (4 m steps) well past the range: the flat plane's LOD error is 0, and coarser
    // quadrants' long triangles would carry the last displaced vertices far past the fade.
    s.terrain.lod_metric = LodMetric::Distance;
    s.terrain.base_range_m = 120.0f;
    s.terrain.tessellation.enabled = true;
    s.terrain.tessellation.range_m = 40.0f;
    s.terrain.tessellation.edge_px = 1.0f;
    s.terrain.tessellation.max_factor = 32.0f;
    s.terrain.tessellation.depth_m = 1.0f;
    test::terrainOnly(s);
    return s;
}

void usePlane(const Settings& s) {
    static bool adopted = false;
    if (adopted) return;
    test::adoptTerrain(renderer(), s.terrain, 257, [](int, int) { return kSample; });
    adopted = true;
}

double planeHeight(const Settings& s) { return double(s.terrain.height_offset_m) + double(s.terrain.height_scale_m) * kSample; }

struct Fit {
    double rms = 0.0, max = 0.0;  // m, rendered height minus the mirror's
    double signal = 0.0;          // m, rms of the mirror's displacement itself
    int points = 0;
};

// Compares the rendered points (world, from depth) between near_m and far_m from the camera with
// the displaced plane of relief r.
Fit compare(const MaterialImages& m, const TessRelief& r, const std::vector<glm::dvec3>& points, const glm::dvec3& eye,
            double ground, double near_m, double far_m) {
    Fit f;
    for (const glm::dvec3& p : points) {
        const glm::dvec3 rel(p.x - eye.x, ground - eye.y, p.z - eye.z);  // the undisplaced point
        const double d = glm::length(rel);
        if (d < near_m || d > far_m) continue;
        const double expected = tessDisplacement(m, r, rel, glm::dvec2(p.x, p.z));
        const double e = (p.y - ground) - expected;
        f.rms += e * e;
        f.signal += expected * expected;
        f.max = std::max(f.max, std::abs(e));
        ++f.points;
    }
    if (f.points > 0) {
        f.rms = std::sqrt(f.rms / f.points);
        f.signal = std::sqrt(f.signal / f.points);
    }
    return f;
}

}  // namespace

TEST_CASE("gl: tessellated terrain lies on the CPU mirror of its displacement, and not with another amplitude or fade") {
    Settings s = displacedPlane();
    s.sky.enabled = false;
    s.shadows.enabled = false;
    s.terrain.view = TerrainView::Normals;  // unlit: only the depth matters
    usePlane(s);
    const double ground = planeHeight(s);
    const glm::dvec3 eye(3.7, ground + 3.0, -5.3);
    const ViewParams view{eye, 30.0, -22.0, 60.0, 0.1, 192, 108};
    std::vector<float> depth;
    FrameRequest request;
    request.depth = &depth;
    renderer().resetHistory();
    test::RenderedFrame frame = test::renderFrame(renderer(), s, view, 0.0, request);
    REQUIRE(depth.size() == std::size_t(view.width * view.height));
    CHECK(frame.report.counters["terrain.tess_patches"] > 0);

    // World points of every terrain pixel (depth 0 is the sky).
    const glm::dmat4 inv = glm::inverse(glm::dmat4(viewMatrices(view).view_proj));
    std::vector<glm::dvec3> points;
    for (int row = 0; row < view.height; ++row)
        for (int x = 0; x < view.width; ++x) {
            const float z = depth[std::size_t(row) * std::size_t(view.width) + std::size_t(x)];
            if (z <= 0.0f) continue;
            const glm::dvec2 ndc(2.0 * (x + 0.5) / view.width - 1.0, 1.0 - 2.0 * (row + 0.5) / view.height);
            const glm::dvec4 h = inv * glm::dvec4(ndc, double(z), 1.0);
            points.push_back(eye + glm::dvec3(h) / h.w);
        }

    const MaterialImages m = generateMaterialImages(256);  // what Terrain::create generated
    const TessRelief r = renderer().terrain()->tessRelief(s.terrain);
    CHECK(r.fade_end_m < s.terrain.tessellation.range_m);
    // Where the relief is at full depth, where it fades, and beyond (flat).
    const Fit full = compare(m, r, points, eye, ground, 4.0, r.fade_start_m);
    const Fit fading = compare(m, r, points, eye, ground, r.fade_start_m, r.fade_end_m);
    // Past the fade plus one grid triangle (4 m texels: a triangle with a corner inside the fade
    // interpolates its small displacement up to a diagonal beyond it).
    const Fit beyond = compare(m, r, points, eye, ground, r.fade_end_m + 6.0, 200.0);
    std::printf("tess displacement: rms error %.4f m (max %.3f) over %d points at full depth (relief rms %.3f m), %.4f m "
                "(max %.3f) over %d fading, %.5f m over %d beyond\n",
                full.rms, full.max, full.points, full.signal, fading.rms, fading.max, fading.points, beyond.rms, beyond.points);
    REQUIRE(full.points > 2000);
    REQUIRE(fading.points > 500);
    REQUIRE(beyond.points > 500);
    // The bound: 1 cm rms, where the relief's rms is ~0.5 m (measured ~1.5 mm: the tessellated
    // surface is piecewise linear between vertices about 1 px apart, the relief bilinear between
    // 25 cm texels).
    const double bound_full = 0.01, bound_fading = 0.01;
    CHECK(full.rms < bound_full);
    CHECK(fading.rms < bound_fading);
    CHECK(beyond.rms < 1e-3);  // no displacement past the fade
    CHECK(full.signal > 0.2);  // the displacement is there to be measured

    // The same comparison fails for a mirror whose amplitude or fade range differs (the shader's
    // own numbers come from tessRelief(), so a change there moves both; a change in the shader
    // alone shows up as one of these).
    TessRelief deeper = r, later = r, earlier = r;
    deeper.depth_m *= 1.05;
    later.fade_start_m += 2.0;
    later.fade_end_m += 2.0;
    earlier.fade_start_m -= 2.0;
    earlier.fade_end_m -= 2.0;
    const double deeper_rms = compare(m, deeper, points, eye, ground, 4.0, r.fade_start_m).rms;
    const double later_rms = compare(m, later, points, eye, ground, r.fade_start_m, r.fade_end_m).rms;
    const double earlier_rms = compare(m, earlier, points, eye, ground, r.fade_start_m, r.fade_end_m).rms;
    std::printf("tess displacement: rms error with amplitude x1.05 %.4f m (full depth), fade 2 m later %.4f m, 2 m earlier %.4f m "
                "(fade band)\n",
                deeper_rms, later_rms, earlier_rms);
    CHECK(deeper_rms > bound_full);
    CHECK(later_rms > bound_fading);
    CHECK(earlier_rms > bound_fading);
}

TEST_CASE("gl: every sun cascade serving displaced ground casts displaced, so a sunlit displaced plane has no acne") {
    Settings s = displacedPlane();
    s.debug.view = DebugView::Shadow;  // the HDR target is the sun's visibility (red), alpha 0 off the terrain
    s.shadows.enabled = true;
    s.sky.sun_mode = SunMode::Angles;
    s.sky.sun_elevation_deg = 55.0f;  // steeper than any relief slope: nothing on the plane can shade it
    s.sky.sun_azimuth_deg = 200.0f;
    usePlane(s);
    const double ground = planeHeight(s);
    // Eye height, looking along the plane: the view crosses several cascades inside the range.
    const ViewParams view{{3.7, ground + 1.7, -5.3}, 30.0, -12.0, 60.0, 0.1, 160, 90};
    auto shadowed = [&](bool tess, double& patches) {
        Settings t = s;
        t.terrain.tessellation.enabled = tess;
        std::vector<float> depth;
        FrameRequest request;
        request.depth = &depth;
        renderer().resetHistory();
        test::RenderedFrame f = test::renderFrame(renderer(), t, view, 0.0, request);
        patches = f.report.counters["terrain.tess_shadow_patches"];
        CHECK(f.report.counters["shadows.drawn"] >= 2);
        // Terrain pixels within the tessellated range (from the camera, by depth).
        const glm::dmat4 inv = glm::inverse(glm::dmat4(viewMatrices(view).view_proj));
        int pixels = 0, dark = 0;
        for (int row = 0; row < view.height; ++row)
            for (int x = 0; x < view.width; ++x) {
                const std::size_t i = std::size_t(row) * std::size_t(view.width) + std::size_t(x);
                if (depth[i] <= 0.0f || f.rgba[i * 4 + 3] == 0.0f) continue;
                const glm::dvec2 ndc(2.0 * (x + 0.5) / view.width - 1.0, 1.0 - 2.0 * (row + 0.5) / view.height);
                const glm::dvec4 h = inv * glm::dvec4(ndc, double(depth[i]), 1.0);
                if (glm::length(glm::dvec3(h) / h.w) > double(s.terrain.tessellation.range_m)) continue;
                ++pixels;
                dark += f.rgba[i * 4] < 0.5f;
            }
        REQUIRE(pixels > 2000);
        return double(dark) / double(pixels);
    };
    double patches_off = 0.0, patches_on = 0.0;
    const double off = shadowed(false, patches_off);
    const double on = shadowed(true, patches_on);
    std::printf("tess shadows: shadowed share within the range %.4f off, %.4f on; %.0f shadow patches\n", off, on, patches_on);
    CHECK(patches_on > 0.0);
    CHECK(off < 0.01);  // a sunlit plane
    // Undisplaced casters above the displaced surface shade it wherever the relief sinks deeper
    // than the bias (most of it at 1 m): displaced ones do not.
    CHECK(on < off + 0.01);
}

TEST_CASE("gl: spot tiles and point faces serving displaced ground cast displaced, so a lamp-lit displaced plane has no acne") {
    Settings s = displacedPlane();
    s.sky.sun_mode = SunMode::Angles;
    s.sky.sun_elevation_deg = -30.0f;  // night: no sun cascade, the lamp's shadow view alone serves the ground
    s.shadows.enabled = true;
    s.shadows.point_enabled = true;
    s.lights.enabled = true;
    usePlane(s);
    const double ground = planeHeight(s);
    const ViewParams view{{3.7, ground + 1.7, -5.3}, 30.0, -12.0, 60.0, 0.1, 160, 90};
    // 20 m above the ground 14 m ahead of the eye, inside the displacement's full depth (up to half
    // the range): a spot whose 35 degree cone keeps every lit point at least 55 degrees below the
    // lamp (steeper than any relief slope, so the relief cannot shade itself), or a point lamp
    // (its downward cube face) measured over the same points.
    const double yaw = glm::radians(view.yaw_deg);
    const glm::dvec3 lamp = view.position + glm::dvec3(14.0 * std::sin(yaw), 0.0, -14.0 * std::cos(yaw)) +
                            glm::dvec3(0.0, ground + 20.0 - view.position.y, 0.0);
    const glm::dmat4 inv = glm::inverse(glm::dmat4(viewMatrices(view).view_proj));
    for (LightType type : {LightType::Spot, LightType::Point}) {
        const bool spot = type == LightType::Spot;
        CAPTURE(spot);
        Light l;
        l.type = type;
        l.position = lamp;
        l.direction = {0.0f, -1.0f, 0.0f};
        l.radius_m = 60.0f;
        l.intensity = 2000.0f;
        l.inner_deg = 30.0f;
        l.outer_deg = 35.0f;
        // The lamp's own light per pixel: lit minus unlit (the night sky's), with and without its shadow.
        auto light = [&](bool tess, bool shadow, bool on, std::vector<float>* depth, double* patches) {
            Settings t = s;
            t.terrain.tessellation.enabled = tess;
            Light k = l;
            k.shadow = shadow;
            t.lights.lights = {{"lamp", k}};
            if (!on) t.lights.lights.clear();
            FrameRequest request;
            request.depth = depth;
            renderer().resetHistory();
            test::RenderedFrame f = test::renderFrame(renderer(), t, view, 0.0, request);
            if (patches) {
                *patches = f.report.counters["terrain.tess_shadow_patches"];
                CHECK(f.report.counters["shadows.drawn"] == 0.0);  // no sun cascade
                CHECK(f.report.counters[spot ? "shadows.spot_shadowed" : "shadows.point_shadowed"] == 1.0);
            }
            return f.rgba;
        };
        auto shadowedShare = [&](bool tess, double& patches) {
            std::vector<float> depth;
            const std::vector<float> dark = light(tess, true, false, &depth, nullptr);
            const std::vector<float> open = light(tess, false, true, nullptr, nullptr);
            const std::vector<float> shadowed = light(tess, true, true, nullptr, &patches);
            const auto lum = [](const std::vector<float>& c, std::size_t i) {
                return 0.2126 * c[i * 4] + 0.7152 * c[i * 4 + 1] + 0.0722 * c[i * 4 + 2];
            };
            double brightest = 0.0;
            for (std::size_t i = 0; i < depth.size(); ++i) brightest = std::max(brightest, lum(open, i) - lum(dark, i));
            int pixels = 0, acne = 0;
            for (int row = 0; row < view.height; ++row)
                for (int x = 0; x < view.width; ++x) {
                    const std::size_t i = std::size_t(row) * std::size_t(view.width) + std::size_t(x);
                    if (depth[i] <= 0.0f) continue;
                    const glm::dvec2 ndc(2.0 * (x + 0.5) / view.width - 1.0, 1.0 - 2.0 * (row + 0.5) / view.height);
                    const glm::dvec4 h = inv * glm::dvec4(ndc, double(depth[i]), 1.0);
                    const glm::dvec3 p = view.position + glm::dvec3(h) / h.w;
                    const glm::dvec3 to_lamp = glm::normalize(lamp - p);
                    const double lit = lum(open, i) - lum(dark, i);
                    // Steeply below the lamp, lit by it, and inside the tessellated range.
                    if (to_lamp.y < std::sin(glm::radians(56.0)) || lit < 0.2 * brightest ||
                        glm::length(p - view.position) > double(s.terrain.tessellation.range_m))
                        continue;
                    ++pixels;
                    acne += lum(shadowed, i) - lum(dark, i) < 0.5 * lit;
                }
            REQUIRE(pixels > 1000);
            return double(acne) / double(pixels);
        };
        double patches_off = 0.0, patches_on = 0.0;
        const double off = shadowedShare(false, patches_off);
        const double on = shadowedShare(true, patches_on);
        std::printf("tess %s shadows: shadowed share under the lamp %.4f off, %.4f on; %.0f shadow patches\n",
                    spot ? "spot" : "point", off, on, patches_on);
        CHECK(patches_off == 0.0);
        CHECK(patches_on > 0.0);
        CHECK(off < 0.01);  // a lamp-lit plane
        // Flat casters above the displaced surface shade it wherever the relief sinks deeper than
        // the bias: displaced ones do not.
        CHECK(on < off + 0.01);
    }
}

TEST_CASE("gl: the displacement ignores the material arrays' anisotropic filtering") {
    // The evaluation stage has no derivatives: through the arrays' sampler, 16x anisotropy made
    // llvmpipe run its footprint loop over much of the texture per vertex (minutes a frame, and a
    // relief averaged flat). It filters the finest level itself (material.glsl texelBilinearRepeat),
    // so the displaced depth is the same bits at 1x and 16x.
    Settings s = displacedPlane();
    s.sky.enabled = false;
    s.shadows.enabled = false;
    s.terrain.view = TerrainView::Normals;
    s.terrain.tessellation.range_m = 12.0f;  // few patches: the slow path stays seconds when this fails
    s.terrain.tessellation.max_factor = 4.0f;
    usePlane(s);
    const double ground = planeHeight(s);
    const ViewParams view{{3.7, ground + 3.0, -5.3}, 30.0, -60.0, 50.0, 0.1, 48, 27};
    auto depthAt = [&](int anisotropy, double& patches) {
        Settings t = s;
        t.terrain.material_anisotropy = anisotropy;
        std::vector<float> depth;
        FrameRequest request;
        request.depth = &depth;
        renderer().resetHistory();
        test::RenderedFrame f = test::renderFrame(renderer(), t, view, 0.0, request);
        patches = f.report.counters["terrain.tess_patches"];
        return depth;
    };
    double patches_1 = 0.0, patches_16 = 0.0;
    const std::vector<float> one = depthAt(1, patches_1), sixteen = depthAt(16, patches_16);
    REQUIRE(one.size() == sixteen.size());
    int differ = 0, terrain = 0;
    for (std::size_t i = 0; i < one.size(); ++i) {
        terrain += one[i] > 0.0f;
        differ += one[i] != sixteen[i];
    }
    std::printf("tess anisotropy: %.0f patches, %d of %d terrain pixels differ between 1x and 16x\n", patches_16, differ, terrain);
    CHECK(patches_1 > 0.0);
    CHECK(terrain > int(one.size()) / 2);
    CHECK(differ == 0);
}
