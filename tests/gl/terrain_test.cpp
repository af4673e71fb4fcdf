// Terrain under OSMesa: flat, spiky and 2x2 heightmaps leave no holes and no NaN/Inf; a
// terrain 10,000 km from the origin looks the same as at the origin; bad heightmaps are
// refused with exit code 2.
#include "app/capture.h"
#include "app/frame.h"
#include "app/scene.h"
#include "renderer_fixture.h"
#include "renderer/half.h"
#include "terrain/heightmap.h"

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <random>

using namespace vista;

namespace {

std::filesystem::path writeMap(const test::TempDir& dir, const std::string& name, int w, int h,
                               const std::function<float(int, int)>& f) {
    Heightmap map{w, h, std::vector<float>(std::size_t(w) * std::size_t(h))};
    for (int z = 0; z < h; ++z)
        for (int x = 0; x < w; ++x) map.samples[std::size_t(z * w + x)] = f(x, z);
    std::filesystem::path file = dir.path / name;
    REQUIRE(saveHeightmapPng16(file, map).empty());
    return file;
}

Settings terrainOnly(const std::filesystem::path& heightmap, float size_m, float scale_m) {
    Settings s;
    s.terrain.heightmap = heightmap.string();
    s.terrain.size_m = size_m;
    s.terrain.height_scale_m = scale_m;
    s.sky.enabled = false;
    s.debug.grid = false;
    return s;
}

struct Rendered {
    std::vector<std::uint16_t> hdr;
    int holes = 0;  // pixels the terrain did not cover (alpha still 0)
    std::uint64_t nonfinite = 0;
};

Rendered render(FrameRenderer& renderer, const Settings& s, const ViewParams& view) {
    REQUIRE(renderer.prepare(s).empty());
    Rendered r;
    FrameRequest request;
    request.capture_hdr = &r.hdr;
    request.count_nonfinite = true;
    renderer.resetHistory();  // a first frame: no TAA jitter or history, as the test expects
    renderer.render(s, view, 0.0, request);
    for (std::size_t i = 3; i < r.hdr.size(); i += 4) r.holes += r.hdr[i] == 0;  // half 0.0
    for (const auto& c : renderer.counters().collect(true)) r.nonfinite += c.value;
    return r;
}

FrameRenderer& renderer() { return test::compiledFileRenderer(); }

ViewParams lookingDown(double height, double fov) {
    return ViewParams{{0.0, height, 0.0}, 0.0, -89.0, fov, 0.5, 96, 54};
}

}  // namespace

TEST_CASE("gl: flat, spiky and 2x2 heightmaps render with no holes and finite pixels") {
    test::TempDir dir("terrain-shapes");
    std::mt19937 rng(5);
    auto flat = writeMap(dir, "flat.png", 65, 65, [](int, int) { return 0.5f; });
    auto spiky = writeMap(dir, "spiky.png", 65, 65, [&](int, int) { return float(rng() & 1); });
    auto tiny = writeMap(dir, "tiny.png", 2, 2, [](int x, int z) { return 0.25f * float(x + 2 * z); });
    struct Case {
        std::filesystem::path map;
        float size, scale;
        ViewParams view;
    } cases[] = {
        {flat, 2000.0f, 100.0f, lookingDown(400.0, 60.0)},
        {spiky, 8000.0f, 5000.0f, lookingDown(9000.0, 20.0)},  // jumps of 5 km between texels
        {tiny, 1000.0f, 50.0f, lookingDown(500.0, 40.0)},
        // Grazing view over a huge flat map: everything below the horizon is ground.
        {flat, 1.0e6f, 100.0f, ViewParams{{0.0, 60.0, 0.0}, 30.0, 0.0, 60.0, 0.5, 96, 54}},
    };
    for (const auto& c : cases) {
        CAPTURE(c.map.filename().string());
        CAPTURE(c.size);
        Rendered r = render(renderer(), terrainOnly(c.map, c.size, c.scale), c.view);
        CHECK(r.nonfinite == 0);
        if (c.view.pitch_deg < -80.0) {
            CHECK(r.holes == 0);
        } else {  // the lower half of the image (below the horizon) is all terrain
            int lower_holes = 0;
            for (std::size_t i = 3; i < r.hdr.size() / 2; i += 4) lower_holes += r.hdr[r.hdr.size() / 2 + i] == 0;
            CHECK(lower_holes == 0);
            CHECK(r.holes > 0);  // the sky half is empty: the check can tell
        }
    }
}

TEST_CASE("gl: a terrain 10,000 km from the origin renders like one at the origin") {
    test::TempDir dir("terrain-far");
    auto hills = writeMap(dir, "hills.png", 129, 129, [](int x, int z) {
        return 0.5f + 0.25f * std::sin(float(x) * 0.2f) * std::cos(float(z) * 0.15f);
    });
    Settings near = terrainOnly(hills, 4000.0f, 400.0f);
    Settings far = near;
    far.terrain.origin = {1.0e7, 0.0, -1.0e7};
    ViewParams view{{-1500.0, 500.0, 1200.0}, 40.0, -15.0, 60.0, 0.5, 96, 54};
    ViewParams far_view = view;
    far_view.position += far.terrain.origin;
    Rendered a = render(renderer(), near, view);
    Rendered b = render(renderer(), far, far_view);
    REQUIRE(a.hdr.size() == b.hdr.size());
    // Half floats compared as values: camera-relative rendering keeps them nearly identical.
    auto half = halfToFloat;
    double max_diff = 0.0;
    int differing = 0;
    for (std::size_t i = 0; i < a.hdr.size(); ++i) {
        double d = std::abs(half(a.hdr[i]) - half(b.hdr[i]));
        max_diff = std::max(max_diff, d);
        differing += d > 0.02;
    }
    CHECK(a.holes < int(a.hdr.size() / 4));  // the terrain is in view
    CHECK(differing <= int(a.hdr.size() / 400));  // a few edge pixels at most
    CAPTURE(max_diff);
}

TEST_CASE("gl: bad heightmaps are refused with exit code 2 and say why") {
    test::TempDir dir("terrain-bad");
    auto one = writeMap(dir, "one.png", 2, 2, [](int, int) { return 0.0f; });
    std::filesystem::path tiny = dir.path / "tiny.png";
    {
        auto out = OIIO::ImageOutput::create("png");
        OIIO::ImageSpec spec(1, 1, 1, OIIO::TypeDesc::UINT8);
        unsigned char pixel = 7;
        REQUIRE(out->open(tiny.string(), spec));
        REQUIRE(out->write_image(OIIO::TypeDesc::UINT8, &pixel));
        out->close();
    }
    for (const auto& file : {dir.path / "missing.png", tiny}) {
        CaptureJob job;
        REQUIRE(loadScene(defaultScenePath(), {}, job.settings).empty());
        job.settings.terrain.heightmap = file.string();
        job.settings.capture.out = (dir.path / "out").string();
        job.settings.capture.frames = 1;
        job.progress = false;
        CAPTURE(file);
        CHECK(runCapture(job).exit_code == 2);
    }
    (void)one;
}

TEST_CASE("gl: a heightmap split into texture tiles renders like one texture") {
    // Maps larger than GL_MAX_TEXTURE_SIZE (16384 on llvmpipe) are stored as tiles; force
    // 32-texel tiles on a 100 x 77 map and compare with the single-texture image.
    Heightmap map{100, 77, std::vector<float>(100 * 77)};
    for (int z = 0; z < 77; ++z)
        for (int x = 0; x < 100; ++x)
            map.samples[std::size_t(z * 100 + x)] = 0.5f + 0.3f * std::sin(float(x) * 0.31f) * std::cos(float(z) * 0.23f);
    Settings s = terrainOnly("tiles-test", 3000.0f, 300.0f);
    ViewParams view{{-900.0, 600.0, 800.0}, 40.0, -25.0, 60.0, 0.5, 96, 54};
    std::vector<std::uint16_t> images[2];
    for (int tiled = 0; tiled < 2; ++tiled) {
        InputErrors errors;
        auto terrain = Terrain::create(map, s.terrain, renderer().shaders(), errors, tiled ? 33 : 0);
        REQUIRE(terrain);
        renderer().adoptTerrain(std::move(terrain));
        FrameRequest request;
        request.capture_hdr = &images[tiled];
        renderer().resetHistory();  // a first frame: no TAA jitter or history, as the test expects
        renderer().render(s, view, 0.0, request);
    }
    REQUIRE(images[0].size() == images[1].size());
    int holes = 0;
    for (std::size_t i = 3; i < images[0].size(); i += 4) holes += images[0][i] == 0;
    CHECK(holes < int(images[0].size() / 8));  // the terrain fills the view
    // Filtering weights differ in the last bits between the two layouts: compare values.
    double max_diff = 0.0;
    int differing = 0;
    for (std::size_t i = 0; i < images[0].size(); ++i) {
        double d = std::abs(halfToFloat(images[0][i]) - halfToFloat(images[1][i]));
        max_diff = std::max(max_diff, d);
        differing += d > 0.01;
    }
    CAPTURE(max_diff);
    CHECK(differing <= int(images[0].size() / 500));
}

TEST_CASE("gl: the error metric keeps the measured screen error within its bound with fewer triangles") {
    // Gentle hills with one rough quadrant: the rough part sets distance-only ranges for all.
    test::TempDir dir("terrain-error");
    std::mt19937 noise(3);
    std::filesystem::path file = writeMap(dir, "hills.png", 257, 257, [&](int x, int z) {
        float hills = 0.5f + 0.2f * std::sin(float(x) * 0.07f) * std::cos(float(z) * 0.05f);
        float rough = x > 160 && z > 160 ? 0.02f * std::uniform_real_distribution<float>(-1, 1)(noise) : 0.0f;
        return hills + rough;
    });
    Settings s = terrainOnly(file, 4096.0f, 300.0f);
    FrameRenderer& r = renderer();
    // The largest vertical screen error of a frame (the error view writes it to alpha).
    auto measure = [&](Settings settings, const ViewParams& view, double& triangles) {
        settings.terrain.view = TerrainView::Error;
        Rendered out = render(r, settings, view);
        triangles = double(r.terrain()->counters().triangles);
        double worst = 0.0;
        for (std::size_t i = 3; i < out.hdr.size(); i += 4) worst = std::max(worst, double(halfToFloat(out.hdr[i])));
        return worst;
    };
    double error_triangles = 0, distance_triangles = 0, coarse_error = 0;
    std::mt19937 rng(7);
    for (int i = 0; i < 6; ++i) {
        ViewParams v;
        double x = std::uniform_real_distribution<double>(-1500, 1500)(rng), z = std::uniform_real_distribution<double>(-1500, 1500)(rng);
        REQUIRE(r.prepare(s).empty());
        v.position = {x, r.terrain()->heightAt(x, z) + 20.0 + 40.0 * i, z};
        v.yaw_deg = 60.0 * i;
        v.pitch_deg = -12.0;
        v.width = 320;
        v.height = 180;
        CAPTURE(i);
        Settings error = s, distance = s;
        distance.terrain.lod_metric = LodMetric::Distance;
        double t = 0;
        CHECK(measure(error, v, t) <= 1.0);
        error_triangles += t;
        CHECK(measure(distance, v, t) <= 1.0);
        distance_triangles += t;
    }
    // Over the rough quadrant, looking around: a loose bound leaves visible error there.
    for (int yaw = 0; yaw < 360; yaw += 90) {
        Settings coarse = s;
        coarse.terrain.max_error_px = 100.0f;
        ViewParams v;
        v.position = {1200.0, r.terrain()->heightAt(1200.0, 1200.0) + 60.0, 1200.0};
        v.yaw_deg = yaw;
        v.pitch_deg = -20.0;
        v.width = 320;
        v.height = 180;
        double t = 0;
        coarse_error = std::max(coarse_error, measure(coarse, v, t));
    }
    CHECK(coarse_error > 1.0);
    MESSAGE("coarse error " << coarse_error << " px; triangles error/distance " << error_triangles << " / " << distance_triangles);
    CHECK(error_triangles < 0.95 * distance_triangles);
}
