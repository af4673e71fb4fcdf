// Headless captures under OSMesa: image files of the right size and format, a stats JSON
// with executed and culled passes, finite output, and the refusals that protect files.
#include "app/capture.h"
#include "app/frame.h"
#include "app/scene.h"
#include "config/ini.h"
#include "gl_fixture.h"

#include <OpenImageIO/imageio.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>

using namespace vista;

namespace {

CaptureJob smallJob(const std::filesystem::path& out, int frames = 2) {
    CaptureJob job;
    REQUIRE(loadScene(defaultScenePath(), {}, job.settings).empty());
    job.settings.capture.out = out.string();
    job.settings.capture.frames = frames;
    job.settings.capture.width = 96;
    job.settings.capture.height = 54;
    job.progress = false;
    return job;
}

bool contains(const nlohmann::json& list, const std::string& name) {
    return std::find(list.begin(), list.end(), name) != list.end();
}

}  // namespace

TEST_CASE("gl: capture writes PNGs of the requested size and a valid stats JSON") {
    test::TempDir dir("capture-png");
    CaptureJob job = smallJob(dir.path, 3);
    job.stats_file = dir.path / "stats.json";
    CaptureResult r = runCapture(job);
    REQUIRE(r.exit_code == 0);
    REQUIRE(r.images.size() == 3);
    for (const auto& file : r.images) {
        auto in = OIIO::ImageInput::open(file.string());
        REQUIRE(in);
        CHECK(in->spec().width == 96);
        CHECK(in->spec().height == 54);
        CHECK(in->spec().format == OIIO::TypeDesc::UINT8);
        std::vector<unsigned char> pixels(96 * 54 * std::size_t(in->spec().nchannels));
        REQUIRE(in->read_image(0, 0, 0, -1, OIIO::TypeDesc::UINT8, pixels.data()));
        // Not a blank image: the sky and the grid differ.
        auto [lo, hi] = std::minmax_element(pixels.begin(), pixels.end());
        CHECK(int(*hi) - int(*lo) > 20);
    }
    CHECK_FALSE(std::filesystem::exists(dir.path / "frame_0000.png.part"));

    std::ifstream in(dir.path / "stats.json");
    nlohmann::json stats = nlohmann::json::parse(in);
    CHECK(stats["backend"] == "osmesa");
    CHECK(stats["size"] == nlohmann::json::array({96, 54}));
    CHECK(stats["reference_copy_ms"].get<double>() > 0.0);
    for (const char* pass : {"frame.clear", "terrain.gbuffer", "sky.atmosphere", "postfx.tonemap", "capture.readback"})
        CHECK_MESSAGE(contains(stats["passes_executed"], pass), pass);
    REQUIRE(stats["frames"].size() == 3);
    for (const auto& frame : stats["frames"]) {
        CHECK(frame["counters"]["nonfinite_pixels"] == 0);
        CHECK(frame["counters"]["terrain.triangles"].get<double>() > 1000);
        CHECK(frame["counters"]["terrain.nodes"].get<double>() > 0);
        // One instanced draw per material tier in use (terrain.glsl MATERIAL_TIER).
        int tiers = 0;
        for (const char* tier : {"terrain.tier_near", "terrain.tier_mid", "terrain.tier_far"})
            tiers += frame["counters"][tier].get<double>() > 0.0 ? 1 : 0;
        CHECK(tiers >= 1);
        CHECK(frame["counters"]["terrain.draws"] == tiers);
        CHECK(frame["counters"].contains("terrain.select_ms"));
        CHECK(frame["gpu_ms"].get<double>() > 0.0);
        CHECK(frame["passes"].contains("postfx.tonemap"));
    }
    CHECK(stats["summary"]["gpu_ms_median"].get<double>() > 0.0);
}

TEST_CASE("gl: an EXR capture reads linear HDR and culls tone mapping") {
    test::TempDir dir("capture-exr");
    CaptureJob job = smallJob(dir.path, 1);
    job.settings.capture.format = ImageFormat::Exr;
    job.settings.sky.sun_illuminance = 20.0f;  // a bright day: lit ground and sky above 1
    job.stats_file = dir.path / "stats.json";
    CaptureResult r = runCapture(job);
    REQUIRE(r.exit_code == 0);
    REQUIRE(r.images.size() == 1);
    CHECK(r.images[0].extension() == ".exr");
    auto in = OIIO::ImageInput::open(r.images[0].string());
    REQUIRE(in);
    CHECK(in->spec().width == 96);
    CHECK(in->spec().format == OIIO::TypeDesc::HALF);
    std::vector<float> pixels(96 * 54 * std::size_t(in->spec().nchannels));
    REQUIRE(in->read_image(0, 0, 0, -1, OIIO::TypeDesc::FLOAT, pixels.data()));
    CHECK(*std::max_element(pixels.begin(), pixels.end()) > 1.0f);  // not clamped to [0, 1]
    nlohmann::json stats = nlohmann::json::parse(std::ifstream(dir.path / "stats.json"));
    CHECK(contains(stats["passes_culled"], "postfx.tonemap"));
    CHECK_FALSE(contains(stats["passes_executed"], "postfx.tonemap"));
}

TEST_CASE("gl: disabled features add no pass, and a debug view culls the final image") {
    test::glContext();
    FrameRenderer renderer(vistaRoot());
    Settings s;
    std::vector<unsigned char> ldr;
    FrameRequest request;
    request.capture_ldr = &ldr;
    ViewParams view{{0.0, 50.0, 0.0}, 0.0, -10.0, 60.0, 0.1, 64, 36};

    s.sky.enabled = false;
    s.debug.grid = false;
    FrameReport report = renderer.render(s, view, 0.0, request);
    for (const auto& pass : report.executed) {
        CHECK(pass.rfind("sky.", 0) != 0);
        CHECK(pass.rfind("debug.grid", 0) != 0);
    }
    CHECK(report.culled.empty());

    s = Settings{};
    s.debug.view = DebugView::Depth;
    report = renderer.render(s, view, 0.0, request);
    CHECK(std::find(report.executed.begin(), report.executed.end(), "debug.view") != report.executed.end());
    CHECK(std::find(report.culled.begin(), report.culled.end(), "postfx.tonemap") != report.culled.end());
    CHECK(ldr.size() == 64u * 36u * 4u);
}

TEST_CASE("gl: extreme inputs render finite: 1x1 target, camera 10,000 km out, sun below the horizon") {
    test::glContext();
    FrameRenderer renderer(vistaRoot());
    std::vector<std::uint16_t> hdr;
    FrameRequest request;
    request.capture_hdr = &hdr;
    request.count_nonfinite = true;
    Settings s;
    s.sky.sun_elevation_deg = -30.0f;
    struct Case {
        ViewParams view;
    } cases[] = {{{{0.0, 10.0, 0.0}, 0.0, -5.0, 60.0, 0.1, 1, 1}},
                 {{{1.0e7, 350.0, -1.0e7}, 30.0, -20.0, 60.0, 0.1, 48, 27}},
                 {{{0.0, 0.001, 0.0}, 0.0, -89.0, 120.0, 0.001, 48, 27}},
                 {{{0.0, 4.0e5, 0.0}, 0.0, 90.0, 5.0, 10.0, 48, 27}}};
    for (const auto& c : cases) renderer.render(s, c.view, 0.0, request);
    auto counts = renderer.counters().collect(true);
    REQUIRE(counts.size() == std::size(cases));
    for (const auto& c : counts) CHECK(c.value == 0);
}

TEST_CASE("gl: capture refuses to overwrite images without --force, and unwritable output") {
    test::TempDir dir("capture-refuse");
    CaptureJob job = smallJob(dir.path, 1);
    REQUIRE(runCapture(job).exit_code == 0);
    CHECK(runCapture(job).exit_code == 2);  // frame_0000.png exists
    job.force = true;
    CHECK(runCapture(job).exit_code == 0);

    std::ofstream(dir.path / "not-a-dir") << "x";
    job.settings.capture.out = (dir.path / "not-a-dir" / "sub").string();
    CHECK(runCapture(job).exit_code == 2);

    job.settings.capture.out = dir.path.string();
    job.settings.capture.path = (dir.path / "missing.path").string();
    CHECK(runCapture(job).exit_code == 2);
}

TEST_CASE("gl: a scene saved by the panel's writer reproduces the same frame") {
    test::glContext();
    FrameRenderer renderer(vistaRoot());
    Settings original;
    REQUIRE(loadScene(defaultScenePath(), {"sky.sun_elevation_deg=12.345", "postfx.exposure.ev=0.3"}, original).empty());
    test::TempDir dir("save-scene");
    REQUIRE(saveIniFile(dir.path / "saved.ini", original).empty());
    Settings reloaded;
    REQUIRE(loadScene(dir.path / "saved.ini", {}, reloaded).empty());

    ViewParams view{reloaded.camera.position, reloaded.camera.yaw_deg, reloaded.camera.pitch_deg,
                    reloaded.camera.fov_deg, reloaded.camera.near_m, 80, 45};
    std::vector<unsigned char> a, b;
    FrameRequest request;
    request.capture_ldr = &a;
    renderer.render(original, view, 1.0, request);
    request.capture_ldr = &b;
    renderer.resetHistory();  // both frames the first of a run (the same TAA jitter, no history)
    renderer.render(reloaded, view, 1.0, request);
    CHECK(a == b);
}
