// The extreme scenes (config/extreme/*.ini), each rendered headless as `vista capture` renders
// it (the camera from its [capture] path, scene time from the path's times) for at most three
// frames at no more than 160x90: no NaN/Inf pixel in the HDR target, no GL error, mean
// luminance within bounds, and a scene far from the origin looks the same moved back to it.
// A new file in config/extreme/ is tested without touching this file.
#include "app/camera_path.h"
#include "app/frame.h"
#include "app/scene.h"
#include "renderer/half.h"
#include "renderer_fixture.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <tuple>
#include <vector>

using namespace vista;

namespace {

constexpr int kMaxWidth = 160, kMaxHeight = 90, kMaxFrames = 3;
// A terrain this far out is also rendered moved back to the origin and compared.
constexpr double kFarFromOrigin_m = 1.0e6;
constexpr double kFarPsnrDb = 30.0;

struct Scene {
    std::filesystem::path file;
    Settings settings;
    CameraPath path;
    // Bounds on the mean luminance of the final (display) image, 0..1. A scene that is meant
    // to be black or white says so in a comment line "; expect display_luminance MIN MAX".
    double display_min = 0.002, display_max = 0.998;
};

Scene loadExtremeScene(const std::filesystem::path& file) {
    Scene scene{file, {}, {}};
    const InputErrors errors = loadScene(file, {}, scene.settings);
    for (const auto& e : errors) FAIL_CHECK(e.str());
    InputErrors path_errors;
    scene.path = CameraPath::load(resolveInput(scene.settings.capture.path), path_errors,
                                  scene.settings.camera.fov_deg);
    for (const auto& e : path_errors) FAIL_CHECK(e.str());
    std::ifstream in(file);
    for (std::string line; std::getline(in, line);) {
        const std::string key = "; expect display_luminance ";
        if (line.rfind(key, 0) == 0) {
            std::sscanf(line.c_str() + key.size(), "%lf %lf", &scene.display_min, &scene.display_max);
        }
    }
    return scene;
}

struct Result {
    std::vector<unsigned char> ldr;   // the display image of the last frame but one
    std::vector<std::uint16_t> hdr;   // the last frame's HDR target
    std::uint64_t nonfinite = 0;      // NaN/Inf pixels of the HDR target, all frames
    std::vector<GLenum> gl_errors;
    int width = 0, height = 0;
    double pre_exposure = 1.0;        // the last frame's (sky.pre_exposure): hdr holds radiance times it
};

void drainGlErrors() {
    while (glGetError() != GL_NO_ERROR) {
    }
}

// Renders the scene's first frames; offset is subtracted from the camera (the scene's terrain
// is moved by the caller).
Result renderScene(FrameRenderer& renderer, const Settings& s, const CameraPath& path, const glm::dvec3& offset = {}) {
    Result r;
    const InputErrors errors = renderer.prepare(s);
    for (const auto& e : errors) FAIL_CHECK(e.str());
    r.width = std::min(s.capture.width, kMaxWidth);
    r.height = std::min(s.capture.height, kMaxHeight);
    const int frames = std::clamp(s.capture.frames, 1, kMaxFrames);
    // The last frame reads the HDR target back, the ones before it the display image (an HDR
    // readback culls the post chain, whose adaptation would then miss a frame); a one-frame
    // scene renders its frame twice at the same time (no adaptation or motion in between).
    const int renders = std::max(frames, 2);
    drainGlErrors();
    for (int i = 0; i < renders; ++i) {
        const double t = path.startTime() + std::min(i, frames - 1) / double(s.capture.fps);
        const CameraPose pose = path.sample(t);
        const ViewParams view{pose.position - offset, pose.yaw_deg, pose.pitch_deg, pose.fov_deg, s.camera.near_m,
                              r.width, r.height};
        FrameRequest request;
        request.count_nonfinite = true;
        if (i + 1 == renders)
            request.capture_hdr = &r.hdr;
        else
            request.capture_ldr = &r.ldr;
        const FrameReport report = renderer.render(s, view, t, request);
        if (auto it = report.counters.find("sky.pre_exposure"); it != report.counters.end()) r.pre_exposure = it->second;
        for (GLenum e = glGetError(); e != GL_NO_ERROR; e = glGetError()) r.gl_errors.push_back(e);
    }
    for (const auto& c : renderer.counters().collect(true))
        if (c.name == "nonfinite_pixels") r.nonfinite += c.value;
    return r;
}

double luminance(double r, double g, double b) { return 0.2126 * r + 0.7152 * g + 0.0722 * b; }

double meanDisplayLuminance(const std::vector<unsigned char>& ldr) {
    double sum = 0.0;
    for (std::size_t i = 0; i + 3 < ldr.size(); i += 4) sum += luminance(ldr[i], ldr[i + 1], ldr[i + 2]) / 255.0;
    return ldr.empty() ? 0.0 : sum / double(ldr.size() / 4);
}

double psnrDb(const std::vector<unsigned char>& a, const std::vector<unsigned char>& b) {
    REQUIRE(a.size() == b.size());
    double se = 0.0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (i % 4 == 3) continue;  // alpha
        const double d = double(a[i]) - double(b[i]);
        se += d * d;
        ++n;
    }
    const double mse = se / double(std::max<std::size_t>(n, 1));
    return mse == 0.0 ? 99.0 : 10.0 * std::log10(255.0 * 255.0 / mse);
}

// Every scene, or only $VISTA_EXTREME_SCENE (a file name without .ini) when it is set.
std::vector<std::filesystem::path> extremeScenes() {
    std::vector<std::filesystem::path> files;
    const char* only = std::getenv("VISTA_EXTREME_SCENE");
    for (const auto& entry : std::filesystem::directory_iterator(vistaRoot() / "config" / "extreme"))
        if (entry.path().extension() == ".ini" && (!only || entry.path().stem() == only)) files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

}  // namespace

TEST_CASE("gl: extreme scenes (config/extreme/*.ini) render finite, without GL errors, within luminance bounds") {
    FrameRenderer& renderer = test::compiledFileRenderer();
    std::vector<Scene> scenes;
    for (const auto& file : extremeScenes()) scenes.push_back(loadExtremeScene(file));
    REQUIRE(scenes.size() >= (std::getenv("VISTA_EXTREME_SCENE") ? 1u : 20u));
    // Scenes on the same terrain in a row, so each heightmap is loaded once.
    std::stable_sort(scenes.begin(), scenes.end(), [](const Scene& a, const Scene& b) {
        return std::tie(a.settings.terrain.enabled, a.settings.terrain.heightmap) <
               std::tie(b.settings.terrain.enabled, b.settings.terrain.heightmap);
    });
    int far_scenes = 0;
    for (const Scene& scene : scenes) {
        const std::string name = scene.file.stem().string();
        CAPTURE(name);
        REQUIRE_FALSE(scene.path.empty());
        const Result r = renderScene(renderer, scene.settings, scene.path);
        CHECK(r.nonfinite == 0);
        CHECK(r.gl_errors.empty());
        REQUIRE(r.hdr.size() == std::size_t(r.width) * std::size_t(r.height) * 4);
        REQUIRE(r.ldr.size() == r.hdr.size());

        double hdr_sum = 0.0, hdr_min = 0.0;
        for (std::size_t i = 0; i < r.hdr.size(); i += 4) {
            const double l = luminance(halfToFloat(r.hdr[i]), halfToFloat(r.hdr[i + 1]), halfToFloat(r.hdr[i + 2]));
            hdr_sum += l;
            hdr_min = std::min(hdr_min, double(std::min({halfToFloat(r.hdr[i]), halfToFloat(r.hdr[i + 1]),
                                                         halfToFloat(r.hdr[i + 2])})));
        }
        const double hdr_mean = hdr_sum / double(r.hdr.size() / 4);
        CAPTURE(hdr_mean);
        CHECK(std::isfinite(hdr_mean));
        CHECK(hdr_min >= 0.0);       // radiance is never negative
        // The sun's disk is ~4e4 HDR units of radiance, a whole view of it is not sane; the target
        // holds radiance times the frame's pre-exposure (night: up to 4e5, sky/night_light.h).
        CHECK(hdr_mean / r.pre_exposure <= 1.0e4);
        const double display = meanDisplayLuminance(r.ldr);
        CAPTURE(display);
        CHECK(display >= scene.display_min);
        CHECK(display <= scene.display_max);
        MESSAGE(name << ": hdr mean " << hdr_mean << ", display mean " << display);

        const glm::dvec3 origin = scene.settings.terrain.origin;
        if (glm::length(origin) > kFarFromOrigin_m) {
            ++far_scenes;
            Settings moved = scene.settings;
            moved.terrain.origin = glm::dvec3(0.0);
            const Result at_origin = renderScene(renderer, moved, scene.path, origin);
            CHECK(at_origin.nonfinite == 0);
            const double psnr = psnrDb(r.ldr, at_origin.ldr);
            CAPTURE(psnr);
            MESSAGE(name << ": far from the origin vs at the origin " << psnr << " dB");
            CHECK(psnr >= kFarPsnrDb);
            // Not a trivial match: the image shows something.
            CHECK(meanDisplayLuminance(at_origin.ldr) > 0.01);
        }
    }
    if (!std::getenv("VISTA_EXTREME_SCENE")) CHECK(far_scenes >= 1);
}
