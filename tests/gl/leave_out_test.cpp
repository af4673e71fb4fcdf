// "Leave out what a scene does not need": from the scene with every feature on
// (config/extreme/everything_on.ini, the sun turned into view for the lens flare), each feature
// is switched off in turn. Its passes must be gone from the executed list, its long-lived GPU
// objects freed (no "FEATURE.memory_bytes" counter, the renderer's object reset), and the
// renderer's GPU memory ("gpu.memory_bytes") no larger than with it on; strictly smaller where
// the feature holds memory of its own.
#include "app/camera_path.h"
#include "app/frame.h"
#include "app/scene.h"
#include "renderer_fixture.h"

#include <algorithm>
#include <functional>
#include <string>
#include <vector>

using namespace vista;

namespace {

struct Frame {
    FrameReport report;
    double memory = 0.0;
};

double counter(const FrameReport& r, const std::string& name, double missing = -1.0) {
    const auto it = r.counters.find(name);
    return it == r.counters.end() ? missing : it->second;
}

bool executes(const FrameReport& r, const std::string& prefix) {
    return std::any_of(r.executed.begin(), r.executed.end(),
                       [&](const std::string& p) { return p == prefix || p.rfind(prefix + ".", 0) == 0; });
}

// Two frames 1/30 s apart with the camera moving (motion blur needs both), from an emptied
// transient pool, so the second frame's memory is what this configuration holds.
Frame renderTwo(FrameRenderer& renderer, const Settings& s, const CameraPath& path) {
    REQUIRE(renderer.prepare(s).empty());
    renderer.trimTransients();
    Frame f;
    for (int i = 0; i < 2; ++i) {
        const double t = path.startTime() + i / 30.0;
        const CameraPose pose = path.sample(t);
        const ViewParams view{pose.position, pose.yaw_deg, pose.pitch_deg, pose.fov_deg, s.camera.near_m, 96, 54};
        std::vector<unsigned char> ldr;
        FrameRequest request;
        request.capture_ldr = &ldr;  // the root that keeps the frame's passes
        f.report = renderer.render(s, view, t, request);
    }
    f.memory = counter(f.report, "gpu.memory_bytes");
    renderer.counters().collect(true);
    return f;
}

struct Feature {
    const char* name;
    std::function<void(Settings&)> off;
    std::vector<std::string> passes;  // pass name prefixes that must be gone
    const char* memory_counter;       // its long-lived memory counter, or null
    std::function<bool(FrameRenderer&)> object_freed;
};

}  // namespace

TEST_CASE("gl: each feature switched off leaves its passes out and frees its GPU memory") {
    FrameRenderer& renderer = test::compiledFileRenderer();
    Settings all;
    REQUIRE(loadScene(vistaRoot() / "config/extreme/everything_on.ini", {}, all).empty());
    all.sky.sun_azimuth_deg = -10.0f;  // in front of the camera: the lens flare runs
    all.sky.sun_elevation_deg = 6.0f;
    InputErrors errors;
    const CameraPath path = CameraPath::load(resolveInput(all.capture.path), errors);
    REQUIRE(errors.empty());

    const Frame base = renderTwo(renderer, all, path);
    CAPTURE(base.report.executed);
    REQUIRE(base.memory > 0.0);
    // Every memory counter adds up to the total.
    double parts = counter(base.report, "gpu.transient_bytes");
    for (const char* c : {"terrain.memory_bytes", "grass.memory_bytes", "sky.memory_bytes", "clouds.memory_bytes",
                          "lights.memory_bytes", "lights.glow_memory_bytes", "shadows.memory_bytes", "shadows.spot_memory_bytes", "shadows.point_memory_bytes", "water.memory_bytes",
                          "weather.memory_bytes", "postfx.memory_bytes", "objects.memory_bytes"})
        parts += std::max(counter(base.report, c), 0.0);
    CHECK(parts <= base.memory);
    CHECK(parts >= base.memory - 65536.0);  // the rest: frame uniforms and counter buffers
    MESSAGE("all features on: gpu.memory_bytes " << base.memory << " (transient " << counter(base.report, "gpu.transient_bytes") << ")");

    const std::vector<Feature> features = {
        {"terrain", [](Settings& s) { s.terrain.enabled = false; }, {"terrain", "grass", "shadows", "weather.splash", "objects"},
         "terrain.memory_bytes", [](FrameRenderer& r) { return r.terrain() == nullptr && r.objects() == nullptr; }},
        {"objects", [](Settings& s) { s.objects.enabled = false; }, {"objects"}, "objects.memory_bytes",
         [](FrameRenderer& r) { return r.objects() == nullptr; }},
        {"objects without entries", [](Settings& s) { s.objects.objects.clear(); s.objects.scatters.clear(); }, {"objects"},
         "objects.memory_bytes", [](FrameRenderer& r) { return r.objects() == nullptr; }},
        {"grass", [](Settings& s) { s.grass.enabled = false; }, {"grass"}, "grass.memory_bytes",
         [](FrameRenderer& r) { return r.grass() == nullptr; }},
        {"sky", [](Settings& s) { s.sky.enabled = false; }, {"sky", "clouds"}, "sky.memory_bytes",
         [](FrameRenderer& r) { return r.sky() == nullptr && r.clouds() == nullptr; }},
        {"clouds", [](Settings& s) { s.clouds.enabled = false; }, {"clouds"}, "clouds.memory_bytes",
         [](FrameRenderer& r) { return r.clouds() == nullptr; }},
        {"cloud shadows", [](Settings& s) { s.clouds.shadows = false; }, {"clouds.shadow"}, nullptr, nullptr},
        {"shadows", [](Settings& s) { s.shadows.enabled = false; }, {"shadows"}, "shadows.memory_bytes",
         [](FrameRenderer& r) { return r.sunShadows() == nullptr; }},
        {"lights", [](Settings& s) { s.lights.enabled = false; }, {"lights", "shadows.spot_atlas"}, "lights.memory_bytes",
         [](FrameRenderer& r) { return r.localLights() == nullptr && r.spotShadows() == nullptr; }},
        {"lamp glow", [](Settings& s) { s.lights.glow = false; }, {"lights.glow"}, "lights.glow_memory_bytes", nullptr},
        {"spot shadows", [](Settings& s) { s.shadows.spot_enabled = false; }, {"shadows.spot_atlas"},
         "shadows.spot_memory_bytes", [](FrameRenderer& r) { return r.spotShadows() == nullptr; }},
        {"water", [](Settings& s) { s.water.enabled = false; }, {"water"}, "water.memory_bytes",
         [](FrameRenderer& r) { return r.water() == nullptr; }},
        {"weather", [](Settings& s) { s.weather.enabled = false; }, {"weather"}, "weather.memory_bytes",
         [](FrameRenderer& r) { return r.weather() == nullptr; }},
        {"aerial perspective", [](Settings& s) { s.sky.aerial_perspective = false; }, {"sky.aerial", "sky.aerial_volume"},
         nullptr, nullptr},
        {"debug grid", [](Settings& s) { s.debug.grid = false; }, {"debug.grid"}, nullptr, nullptr},
        {"ssao", [](Settings& s) { s.ssao.enabled = false; }, {"postfx.ssao"}, nullptr, nullptr},
        {"bloom", [](Settings& s) { s.bloom.enabled = false; }, {"postfx.bloom"}, nullptr, nullptr},
        {"exposure", [](Settings& s) { s.exposure.enabled = false; }, {"postfx.exposure"}, nullptr,
         [](FrameRenderer& r) { return r.postfx().autoExposure() == nullptr; }},
        {"tonemap", [](Settings& s) { s.tonemap.enabled = false; }, {"postfx.tonemap"}, nullptr, nullptr},
        {"fxaa", [](Settings& s) { s.fxaa.enabled = false; }, {"postfx.fxaa"}, nullptr, nullptr},
        {"taa", [](Settings& s) { s.taa.enabled = false; }, {"postfx.taa"}, nullptr,
         [](FrameRenderer& r) { return r.taa() == nullptr; }},
        {"grade", [](Settings& s) { s.grade.enabled = false; }, {"postfx.grade"}, nullptr, nullptr},
        {"night_vision", [](Settings& s) { s.night_vision.enabled = false; }, {"postfx.night_vision"}, nullptr, nullptr},
        {"dof", [](Settings& s) { s.dof.enabled = false; }, {"postfx.dof"}, nullptr,
         [](FrameRenderer& r) { return r.postfx().dof() == nullptr; }},
        {"motion_blur", [](Settings& s) { s.motion_blur.enabled = false; }, {"postfx.motion_blur"}, nullptr, nullptr},
        {"lens_flare", [](Settings& s) { s.lens_flare.enabled = false; }, {"postfx.lens_flare"}, nullptr,
         [](FrameRenderer& r) { return r.postfx().lensFlare() == nullptr; }},
    };
    for (const Feature& f : features) {
        const std::string name = f.name;
        CAPTURE(name);
        for (const std::string& p : f.passes)
            if (p == f.passes.front()) CHECK_MESSAGE(executes(base.report, p), "with everything on, " << p << " runs");
        Settings s = all;
        f.off(s);
        const Frame off = renderTwo(renderer, s, path);
        CAPTURE(off.report.executed);
        for (const std::string& p : f.passes) CHECK_MESSAGE(!executes(off.report, p), p << " is gone");
        if (f.memory_counter) {
            CHECK(counter(base.report, f.memory_counter) > 0.0);
            CHECK(counter(off.report, f.memory_counter) == -1.0);  // no object, no counter
        }
        if (f.object_freed) CHECK(f.object_freed(renderer));
        CHECK(off.memory <= base.memory);
        const bool own_memory = f.memory_counter || f.object_freed;
        if (own_memory) CHECK(off.memory < base.memory);
        MESSAGE(name << " off: gpu.memory_bytes " << off.memory << " (" << (off.memory - base.memory) << ")");
    }
}
