// Forward surfaces (the sea, water.surface, and a transparent pane, objects.transparent) lit by
// more lights than one shader invocation may loop over on llvmpipe (65,535 iterations in all,
// LP_MAX_TGSI_LOOP_ITERATIONS; issue 19, defect 6): every culling method must give the image the
// lights give, and the chunked draws that make that so are counted (lights.chunks).
//
// The reference: 32 bright lights over the sea and the pane, 16 listed first and 16 last, with
// 70,000 tiny ones in the air between them (on the GPU, reaching no surface: a light that does not
// reach adds exactly 0), must light the image the 32 alone light, which the naive loop renders
// well below the cap. The last 16 have indices past 70,000: a loop cut at the cap drops them
// (it did before the forward chunks: naive, tiled and clustered differed by 1, the brightest
// pixel lost), and with chunks of 32,768 the first and the last land in different draws.
#include "app/frame.h"
#include "app/scene.h"
#include "config/file_io.h"
#include "renderer/lighting/light_settings.h"
#include "renderer/lighting/local_lights.h"
#include "renderer/meshes/gen_props.h"
#include "renderer_fixture.h"
#include "terrain/heightmap.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

using namespace vista;

namespace {

FrameRenderer& renderer() { return test::fileRenderer(); }

constexpr float kSeaLevelM = 30.0f;

// A 40 x 20 m double-sided pane in the model's x-y plane (facing +z), BLEND, pale at alpha 0.5.
Model widePane() { return test::paneModel("wide pane", 40.0f, 20.0f, {0.8f, 0.85f, 0.9f, 0.5f}, 0.6f, AlphaMode::Blend); }

void addVolume(Settings& s, const std::string& name, const std::string& spec) {
    NamedLightVolume v{name, {}};
    REQUIRE(parseVolumeSpec(spec, v.volume).empty());
    s.lights.volumes.push_back(v);
}

// Night over a shallow sea: low hills (8..32 m) mostly under the surface at 30 m, no sun, no
// sky; the pane stands in the water in front of the camera.
Settings seaScene(const std::filesystem::path& pane) {
    Settings s;
    s.terrain.heightmap = "forward-lights-test";
    s.terrain.size_m = 400.0f;
    s.terrain.height_scale_m = 40.0f;
    s.terrain.height_offset_m = 0.0f;
    s.sky.enabled = false;
    s.sky.sun_illuminance = 0.0f;
    s.debug.grid = false;
    s.grass.enabled = false;
    s.ssao.enabled = false;
    s.taa.enabled = false;
    s.shadows.enabled = false;
    s.water.enabled = true;
    s.water.level_m = kSeaLevelM;
    ObjectInstanceSpec o;
    o.file = pane.string();
    o.position = glm::dvec3(0.0, kSeaLevelM - 2.0, 40.0);
    s.objects.objects.push_back({"pane", o});
    s.objects.impostor_distance_m = 1.0e6f;
    s.lights.max_lights_per_cell = 4;  // tiled and clustered cells overflow: "every light" ranges
    return s;
}

// The light sets (see the top of the file), in this order.
void addFirst(Settings& s) {
    addVolume(s, "first", "box -40 40 0 40 44 70  count 4 1 4  radius 45  intensity 3000  seed 7");
}
void addAirborne(Settings& s) {
    addVolume(s, "airborne", "box -5 44 60 5 46 70  count 35 20 100  radius 0.05  intensity 20");
}
void addLast(Settings& s) {
    addVolume(s, "last", "box -30 36 10 30 40 60  count 4 1 4  radius 40  intensity 3000  seed 9");
}

const ViewParams kView{{0.0, 50.0, 100.0}, 0.0, -20.0, 60.0, 0.5, 16, 9};

test::RenderedFrame render(const Settings& s, LightCulling method, const ViewParams& view = kView) {
    FrameRenderer& r = renderer();
    static bool adopted = false;
    if (!adopted) {
        test::adoptTerrain(r, s.terrain, 65, [](int x, int z) {
            return 0.5f + 0.3f * std::sin(float(x) * 0.2f) * std::cos(float(z) * 0.15f);
        });
        adopted = true;
    }
    Settings m = s;
    m.lights.culling = method;
    REQUIRE(r.prepare(m).empty());
    FrameRequest request;
    request.count_nonfinite = true;
    request.count_objects = true;
    request.count_lights = true;
    r.resetHistory();  // a first frame: no temporal state
    return test::renderFrame(r, m, view, 0.0, request);
}

// Largest difference over RGB relative to the brightest reference pixel.
double maxRelativeDiff(const std::vector<float>& ref, const std::vector<float>& img) {
    REQUIRE(ref.size() == img.size());
    double peak = 1e-6, diff = 0.0;
    for (std::size_t i = 0; i < ref.size(); ++i) {
        if (i % 4 == 3) continue;
        peak = std::max(peak, double(ref[i]));
        diff = std::max(diff, std::abs(double(ref[i]) - double(img[i])));
    }
    return diff / peak;
}

}  // namespace

TEST_CASE("gl: the sea and a transparent pane under 70,032 lights: every method gives the image of the lights") {
    test::TempDir dir("forward-lights");
    const std::filesystem::path pane = dir / "pane.glb";
    REQUIRE(writeFileAtomic(pane, modelToGlb(widePane()), true).empty());
    const Settings base = seaScene(pane);

    Settings first = base, bright = base, all = base;
    addFirst(first);
    addFirst(bright);
    addLast(bright);
    addFirst(all);
    addAirborne(all);
    addLast(all);
    const test::RenderedFrame ref = render(bright, LightCulling::Naive);
    CHECK(ref.report.counters.at("objects.transparent") == 1.0);  // the pane is in view ...
    CHECK(ref.report.counters.at("water.triangles") > 0.0);        // ... and so is the sea
    CHECK(ref.report.counters.at("lights.chunks") == 1.0);
    // Not vacuous: the last lights (the ones a cut loop drops) change the image a lot.
    CHECK(maxRelativeDiff(ref.rgba, render(first, LightCulling::Naive).rgba) > 0.2);

    for (LightCulling m : {LightCulling::Naive, LightCulling::Tiled, LightCulling::Clustered, LightCulling::Hashed}) {
        CAPTURE(int(m));
        const test::RenderedFrame lit = render(all, m);
        REQUIRE(renderer().localLights());
        const LocalLightStats& st = renderer().localLights()->stats();
        const double diff = maxRelativeDiff(ref.rgba, lit.rgba);
        const auto chunks = lit.report.counters.find("lights.chunks");
        const double draws = chunks == lit.report.counters.end() ? 0.0 : chunks->second;
        std::printf("forward lights method %d: on the GPU %llu, exact %llu (reference %llu), overflow %llu, chunks %.0f, "
                    "diff %.3g\n",
                    int(m), (unsigned long long)st.visible, (unsigned long long)lit.counter("lights.exact"),
                    (unsigned long long)ref.counter("lights.exact"), (unsigned long long)lit.counter("lights.overflow"),
                    draws, diff);
        CHECK(lit.counter("nonfinite_pixels") == 0);
        CHECK(lit.counter("lights.exact") == ref.counter("lights.exact"));  // the deferred pass too
        if (m == LightCulling::Tiled || m == LightCulling::Clustered) CHECK(lit.counter("lights.overflow") > 0);
        if (m != LightCulling::Hashed) {
            CHECK(st.visible == 70032);  // every light on the GPU: past the cap for every "every light" range
            CHECK(draws == 3.0);         // 70,032 lights in chunks of 32,768
        }
        CHECK(diff <= 2e-3);
    }
}

// Issue 19 defect 6, at the light counts the adversarial run used: beyond the list capacities
// (shared tile list, per-cell cap, pool, hash tables) and llvmpipe's loop cap every method must
// still light the same image as naive, the sea and a transparent pane included, and say when a
// list overflowed. The terrain scene of lights_test.cpp (hills of 8..32 m) with the sea at 20 m
// and the pane in the middle of the view. Slow under llvmpipe (naive shades every light per
// pixel, and so do overflowed cells), so skipped in CI; run with
// vista_gl_tests --no-skip '-tc=gl: 150?000*'. Failed before the chunked draws (150,000 lights:
// exact 2,667 naive, 2,933 tiled/clustered, 12,608 hashed at 64x36, without the sea and pane).
TEST_CASE("gl: 150,000, 262,144 and 1,000,000 lights: every method lights the same image as naive" * doctest::skip()) {
    test::TempDir dir("forward-lights-many");
    const std::filesystem::path pane = dir / "pane.glb";
    REQUIRE(writeFileAtomic(pane, modelToGlb(widePane()), true).empty());
    Settings base = seaScene(pane);
    base.water.level_m = 20.0f;
    base.lights.max_lights_per_cell = LightsSettings{}.max_lights_per_cell;
    base.objects.objects[0].object.position = glm::dvec3(-80.0, 18.0, 80.0);
    base.objects.objects[0].object.yaw_deg = -45.0f;  // facing the camera
    const ViewParams view{{-150.0, 120.0, 150.0}, 45.0, -30.0, 60.0, 0.5, 32, 18};
    CHECK(render(base, LightCulling::Naive, view).report.counters.at("objects.transparent") == 1.0);
    struct Case {
        const char* spec;
        bool naive;  // naive's loop over 1M lights per pixel is the slow part: hashed is compared instead
    };
    for (const Case& c : {Case{"box -200 0 -200 200 30 200  count 150 10 100  radius 4  intensity 50  jitter 1", true},
                          Case{"box -200 0 -200 200 30 200  count 64 64 64  radius 4  intensity 50  jitter 1", true},
                          Case{"box -200 0 -200 200 30 200  count 100 100 100  radius 3  intensity 50  jitter 1", false}}) {
        CAPTURE(c.spec);
        Settings s = base;
        addVolume(s, "many", c.spec);
        const LightCulling ref_method = c.naive ? LightCulling::Naive : LightCulling::Hashed;
        const test::RenderedFrame ref = render(s, ref_method, view);
        CHECK(ref.counter("lights.exact") > 0);
        std::printf("many lights %s reference method %d: exact %llu chunks %.0f\n", c.spec, int(ref_method),
                    (unsigned long long)ref.counter("lights.exact"), ref.report.counters.at("lights.chunks"));
        for (LightCulling m : {LightCulling::Naive, LightCulling::Tiled, LightCulling::Clustered, LightCulling::Hashed}) {
            if (m == ref_method || (m == LightCulling::Naive && !c.naive)) continue;
            CAPTURE(int(m));
            const test::RenderedFrame lit = render(s, m, view);
            const double diff = maxRelativeDiff(ref.rgba, lit.rgba);
            std::printf("many lights %s method %d: exact %llu (ref %llu) overflow %llu chunks %.0f diff %.3g\n", c.spec,
                        int(m), (unsigned long long)lit.counter("lights.exact"),
                        (unsigned long long)ref.counter("lights.exact"), (unsigned long long)lit.counter("lights.overflow"),
                        lit.report.counters.at("lights.chunks"), diff);
            CHECK(lit.counter("lights.exact") == ref.counter("lights.exact"));
            CHECK(lit.counter("nonfinite_pixels") == 0);
            CHECK(diff <= 1e-3);
        }
    }
}
