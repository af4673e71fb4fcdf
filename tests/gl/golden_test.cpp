// Golden images: the default scene at 256x144 from a fixed camera and time, once with every
// post effect off but the tone map, once per effect switched on alone, and once with the full
// chain, each compared with tests/golden/NAME.png by PSNR (>= 35 dB: loose enough for llvmpipe
// versions, tight enough to catch a changed effect). Regenerate them all after an intended
// change with `make golden` (VISTA_UPDATE_GOLDEN=1 on this test writes instead of comparing).
#include "app/frame.h"
#include "app/image_writer.h"
#include "app/scene.h"
#include "gl_fixture.h"

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <cstdlib>
#include <functional>

using namespace vista;

namespace {

struct Golden {
    const char* name;
    std::function<void(Settings&)> setup;
};

Settings baseScene() {
    Settings s;
    REQUIRE(loadScene(defaultScenePath(), {}, s).empty());
    s.sky.sun_azimuth_deg = 60.0f;  // in view of the scene's camera (yaw 45, pitch -6), for the flare
    s.sky.sun_elevation_deg = 6.0f;
    s.bloom.enabled = s.fxaa.enabled = s.ssao.enabled = false;
    s.exposure.mode = ExposureMode::Manual;
    s.exposure.ev = -1.0f;
    s.grade.enabled = s.dof.enabled = s.motion_blur.enabled = s.lens_flare.enabled = s.night_vision.enabled = false;
    return s;
}

double psnr(const std::vector<unsigned char>& a, const std::vector<unsigned char>& b) {
    double sum = 0.0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (i % 4 == 3) continue;  // alpha is not written
        const double d = double(a[i]) - double(b[i]);
        sum += d * d, ++n;
    }
    return sum == 0.0 ? 1e9 : 10.0 * std::log10(255.0 * 255.0 / (sum / double(n)));
}

}  // namespace

TEST_CASE("gl: golden images of the default scene, per post effect and the full chain") {
    test::glContext();
    const bool update = std::getenv("VISTA_UPDATE_GOLDEN") != nullptr;
    const std::vector<Golden> cases = {
        {"tonemap", [](Settings&) {}},
        {"bloom", [](Settings& s) { s.bloom.enabled = true; }},
        {"exposure_auto", [](Settings& s) { s.exposure.mode = ExposureMode::Auto; }},
        {"fxaa", [](Settings& s) { s.fxaa.enabled = true; }},
        {"ssao", [](Settings& s) { s.ssao.enabled = true; }},
        {"grade", [](Settings& s) { s.grade.enabled = true, s.grade.vignette = 0.5f, s.grade.saturation = 1.3f, s.grade.grain = 0.1f; }},
        {"dof", [](Settings& s) { s.dof.enabled = true, s.dof.focal_length_mm = 200.0f, s.dof.f_stop = 1.4f; }},
        {"motion_blur", [](Settings& s) { s.motion_blur.enabled = true, s.motion_blur.shutter_deg = 360.0f; }},
        {"lens_flare", [](Settings& s) { s.lens_flare.enabled = true, s.lens_flare.intensity = 0.02f; }},
        {"night_vision", [](Settings& s) { s.night_vision.enabled = true; }},
        {"full", [](Settings& s) {
             s.bloom.enabled = s.fxaa.enabled = s.ssao.enabled = s.grade.enabled = true;
             s.dof.enabled = s.motion_blur.enabled = s.lens_flare.enabled = true;
             s.exposure.mode = ExposureMode::Auto;
             s.grade.vignette = 0.4f;
         }},
    };
    FrameRenderer renderer(vistaRoot());
    const std::filesystem::path dir = vistaRoot() / "tests" / "golden";
    for (const Golden& g : cases) {
        INFO(g.name);
        Settings s = baseScene();
        g.setup(s);
        REQUIRE(renderer.prepare(s).empty());
        std::vector<unsigned char> ldr;
        FrameRequest request;
        request.capture_ldr = &ldr;
        // The scene's camera; two frames 1/30 s apart, moving 3 m forward and turning: motion blur has a
        // previous frame, the adaptation and autofocus start from the first.
        ViewParams view{s.camera.position, s.camera.yaw_deg, s.camera.pitch_deg, s.camera.fov_deg, s.camera.near_m, 256, 144};
        renderer.render(s, view, 0.0, request);
        view.position += 3.0 * viewMatrices(view).forward;
        view.yaw_deg += 1.0;
        renderer.render(s, view, 1.0 / 30.0, request);
        const std::filesystem::path file = dir / (std::string(g.name) + ".png");
        if (update) {
            std::filesystem::create_directories(dir);
            CHECK(writePng(file, 256, 144, ldr, true) == "");
            continue;
        }
        auto in = OIIO::ImageInput::open(file.string());
        INFO("missing " << file << ": run `make golden` to create it");
        REQUIRE(in);
        REQUIRE(in->spec().width == 256);
        REQUIRE(in->spec().height == 144);
        const int channels = in->spec().nchannels;
        std::vector<unsigned char> golden(std::size_t(256 * 144 * channels));
        REQUIRE(in->read_image(0, 0, 0, -1, OIIO::TypeDesc::UINT8, golden.data()));
        std::vector<unsigned char> expected(ldr.size(), 255);
        for (std::size_t p = 0; p < std::size_t(256 * 144); ++p)
            for (int c = 0; c < std::min(channels, 3); ++c) expected[p * 4 + std::size_t(c)] = golden[p * std::size_t(channels) + std::size_t(c)];
        const double db = psnr(ldr, expected);
        INFO("PSNR " << db << " dB");
        CHECK(db >= 35.0);
    }
}
