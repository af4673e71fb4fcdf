// [postfx] order and the effect sections through the ini loader, --set and the writer, and
// the constants the post effects share with their shaders.
#include "config/ini.h"
#include "postfx/dof.h"
#include "postfx/lut.h"
#include "postfx/postfx_bindings.h"

#include <doctest/doctest.h>

using namespace vista;

TEST_CASE("postfx: order reads names in order, blanks or commas between, and writes them back") {
    Settings s;
    CHECK(loadIniString("[postfx]\norder = fxaa, Tonemap bloom\n", "scene.ini", s).empty());
    CHECK(s.postfx.order == std::vector<PostEffect>{PostEffect::Fxaa, PostEffect::Tonemap, PostEffect::Bloom});
    CHECK(saveIniString(s).find("\norder = fxaa tonemap bloom\n") != std::string::npos);

    CHECK(applyOverride("postfx.order=", s).empty());  // an empty chain
    CHECK(s.postfx.order.empty());
    Settings back;
    CHECK(loadIniString(saveIniString(s), "saved.ini", back).empty());
    CHECK(back.postfx.order.empty());

    CHECK(applyOverride("postfx.order=exposure tonemap", s).empty());
    CHECK(s.postfx.order == std::vector<PostEffect>{PostEffect::Exposure, PostEffect::Tonemap});
}

TEST_CASE("postfx: an unknown or repeated effect in order is an error naming it, the order stays") {
    Settings s;
    InputErrors e = loadIniString("[postfx]\norder = bloom glare tonemap\n", "scene.ini", s);
    REQUIRE(e.size() == 1);
    CHECK(e[0].line == 2);
    CHECK(e[0].str().find("[postfx] order = bloom glare tonemap is not accepted ('glare'); accepted: names from bloom, "
                          "exposure, tonemap, fxaa, grade, dof, motion_blur, lens_flare, night_vision, scotopic, each at most once") != std::string::npos);
    CHECK(s.postfx.order == Settings{}.postfx.order);
    e = applyOverride("postfx.order=tonemap,tonemap", s);
    REQUIRE(e.size() == 1);
    CHECK(e[0].str().find("('tonemap' twice)") != std::string::npos);
}

TEST_CASE("postfx: every effect section has enabled and ranged parameters") {
    Settings s;
    CHECK(applyOverride("postfx.bloom.intensity=0.2", s).empty());
    CHECK(applyOverride("postfx.bloom.levels=3", s).empty());
    CHECK(applyOverride("postfx.exposure.mode=manual", s).empty());
    CHECK(applyOverride("postfx.tonemap.op=agx", s).empty());
    CHECK(applyOverride("postfx.fxaa.enabled=false", s).empty());
    CHECK(applyOverride("postfx.grade.lift=0.1 0 -0.1", s).empty());
    CHECK(s.grade.lift == glm::vec3(0.1f, 0.0f, -0.1f));
    CHECK(applyOverride("postfx.ssao.half_resolution=false", s).empty());
    CHECK(applyOverride("postfx.ssao.radius_m=0.5", s).empty());
    CHECK_FALSE(s.ssao.half_resolution);
    CHECK(s.ssao.radius_m == 0.5f);
    CHECK(applyOverride("postfx.ssao.directions=0", s).size() == 1);
    CHECK(s.bloom.intensity == 0.2f);
    CHECK(s.bloom.levels == 3);
    CHECK(s.exposure.mode == ExposureMode::Manual);
    CHECK(s.tonemap.op == Tonemapper::Agx);
    CHECK_FALSE(s.fxaa.enabled);
    CHECK(applyOverride("postfx.bloom.levels=11", s).size() == 1);
    CHECK(applyOverride("postfx.exposure.speed_up=0", s).size() == 1);
    CHECK(applyOverride("postfx.exposure.mode=camera", s).empty());
    CHECK(s.exposure.mode == ExposureMode::Camera);
    CHECK(applyOverride("postfx.exposure.iso=400", s).empty());
    CHECK(applyOverride("postfx.exposure.iso=0", s).size() == 1);  // names the key and the range
    CHECK(applyOverride("postfx.exposure.mode=manual", s).empty());
    const std::string text = saveIniString(s);
    for (const char* section :
         {"[postfx]", "[postfx.exposure]", "[postfx.tonemap]", "[postfx.bloom]", "[postfx.fxaa]", "[postfx.grade]", "[postfx.ssao]"})
        CHECK(text.find(std::string("\n") + section + "\n") != std::string::npos);
}

TEST_CASE("postfx: shared constants: one histogram bin per invocation, state layout") {
    CHECK(postfx::kHistogramGroup * postfx::kHistogramGroup == postfx::kHistogramBins);
    CHECK(sizeof(postfx::ExposureState) == 16);
    CHECK(postfx::kHistogramLogMin < postfx::kHistogramLogMax);
    CHECK(postfx::kHistogramLogMin <= -20.0f);  // the [postfx.exposure] min_ev/max_ev range fits
    CHECK(postfx::kHistogramLogMax >= 20.0f);
}

TEST_CASE("postfx: depth of field's circle of confusion is the thin-lens formula") {
    DofSettings s;
    s.focal_length_mm = 50.0f;
    s.f_stop = 2.0f;
    s.sensor_height_mm = 24.0f;
    // c = f^2 / (N (S1 - f)) * |S - S1| / S on the sensor: f = 0.05 m, N = 2, S1 = 10 m,
    // S = 20 m: 0.0025 / 19.9 * 0.5 = 6.2814e-5 m; over 24 mm of 1000 px: 2.6172 px; radius 1.3086.
    CHECK(dofCocRadiusPx(20.0, 10.0, s, 1000) == doctest::Approx(1.30863).epsilon(1e-5));
    CHECK(dofCocRadiusPx(5.0, 10.0, s, 1000) == doctest::Approx(-2.61726).epsilon(1e-5));  // |5-10|/5 = 1, twice |20-10|/20: -2.6172
    CHECK(dofCocRadiusPx(10.0, 10.0, s, 1000) == 0.0);
    CHECK(dofCocRadiusPx(INFINITY, 10.0, s, 1000) == doctest::Approx(2.0 * 1.30863).epsilon(1e-5));
    CHECK(dofCocRadiusPx(INFINITY, 10.0, s, 500) == doctest::Approx(1.30863).epsilon(1e-5));  // scales with the height
    s.f_stop = 4.0f;
    CHECK(dofCocRadiusPx(20.0, 10.0, s, 1000) == doctest::Approx(1.30863 / 2.0).epsilon(1e-5));  // stopping down halves it
    CHECK(dofClampDiopters(100.0f, s) == doctest::Approx(10.0f));  // focus no closer than twice the focal length
    CHECK(dofClampDiopters(-1.0f, s) == 0.0f);
}

TEST_CASE("postfx: .cube LUTs parse, and every malformed line is an error naming file:line") {
    InputErrors e;
    std::optional<CubeLut> lut = parseCube("# a comment\nTITLE \"x\"\nLUT_3D_SIZE 2\nDOMAIN_MIN 0 0 0\n"
                                           "0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 0 1\n1 0 1\n0 1 1\n1 1 1\n",
                                           "id.cube", e);
    CHECK(e.empty());
    REQUIRE(lut);
    CHECK(lut->size == 2);
    REQUIRE(lut->table.size() == 8);
    CHECK(lut->table[1] == glm::vec3(1, 0, 0));  // red fastest
    CHECK(lut->table[2] == glm::vec3(0, 1, 0));
    CHECK(lut->table[4] == glm::vec3(0, 0, 1));

    e.clear();
    CHECK_FALSE(parseCube("LUT_3D_SIZE 2\n0 0 0\n1 0 x\n0 1 0\n1 1 0 7\n", "bad.cube", e));
    REQUIRE(e.size() == 2);
    CHECK(e[0].str() == "bad.cube:3: '1 0 x' is not a keyword (TITLE, LUT_3D_SIZE, DOMAIN_MIN, DOMAIN_MAX) or three numbers");
    CHECK(e[1].line == 5);
    e.clear();
    CHECK_FALSE(parseCube("LUT_3D_SIZE 1\n", "small.cube", e));
    REQUIRE(e.size() == 1);
    CHECK(e[0].str().find("small.cube:1: LUT_3D_SIZE 1 is not accepted") == 0);
    e.clear();
    CHECK_FALSE(parseCube("LUT_3D_SIZE 2\n0 0 0\n", "short.cube", e));
    REQUIRE(e.size() == 1);
    CHECK(e[0].message == "1 entries; LUT_3D_SIZE 2 needs 8");
    e.clear();
    CHECK_FALSE(parseCube("0 0 0\n", "early.cube", e));
    CHECK(e.at(0).str() == "early.cube:1: data before LUT_3D_SIZE");
    e.clear();
    CHECK_FALSE(loadCube("/nonexistent/x.cube", e));
    CHECK(e.size() == 1);
}
