// Local lights under OSMesa: every culling method lights the same image as the naive loop and
// shades every (pixel, light) pair where the light reaches (lights.exact equal to naive's, so the
// GPU culling is conservative); overflowing lists stay conservative and are counted; extreme
// light sets give finite images; a scene without local lights runs no light pass.
#include "app/frame.h"
#include "app/scene.h"
#include "renderer/lighting/brdf.h"
#include "renderer/lighting/light_settings.h"
#include "renderer_fixture.h"
#include "terrain/heightmap.h"

#include <glm/gtc/packing.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

using namespace vista;

namespace {

FrameRenderer& renderer() { return test::fileRenderer(); }

// Gentle hills, 400 m square, heights 0..40 m.
Settings hillScene() {
    Settings s;
    s.terrain.heightmap = "lights-test";
    s.terrain.size_m = 400.0f;
    s.terrain.height_scale_m = 40.0f;
    s.terrain.height_offset_m = 0.0f;
    s.sky.enabled = false;
    s.sky.sun_illuminance = 0.0f;  // local lights only
    s.debug.grid = false;
    return s;
}

void useHills(const Settings& s) {
    static bool adopted = false;
    if (adopted) return;
    test::adoptTerrain(renderer(), s.terrain, 65, [](int x, int z) {
        return 0.5f + 0.3f * std::sin(float(x) * 0.2f) * std::cos(float(z) * 0.15f);
    });
    adopted = true;
}

void addVolume(Settings& s, const std::string& name, const std::string& spec) {
    NamedLightVolume v{name, {}};
    REQUIRE(parseVolumeSpec(spec, v.volume).empty());
    s.lights.volumes.push_back(v);
}
void addLight(Settings& s, const std::string& name, const std::string& spec) {
    NamedLight l{name, {}};
    REQUIRE(parseLightSpec(spec, l.light).empty());
    s.lights.lights.push_back(l);
}

struct Lit {
    std::vector<float> hdr;
    std::uint64_t evaluations = 0, exact = 0, overflow = 0, nonfinite = 0;
    std::vector<std::string> executed;
};

Lit render(Settings s, LightCulling method, const ViewParams& view, double t = 0.0) {
    useHills(s);
    s.lights.culling = method;
    FrameRequest request;
    request.count_lights = true;
    request.count_nonfinite = true;
    renderer().resetHistory();  // a first frame: no TAA jitter or history, as the test expects
    test::RenderedFrame f = test::renderFrame(renderer(), s, view, t, request);
    return Lit{std::move(f.rgba), f.counter("lights.evaluations"), f.counter("lights.exact"), f.counter("lights.overflow"),
               f.counter("nonfinite_pixels"), std::move(f.report.executed)};
}

// Largest difference over RGB relative to the brightest naive pixel.
double maxRelativeDiff(const Lit& a, const Lit& b) {
    double peak = 1e-6, diff = 0.0;
    for (std::size_t i = 0; i < a.hdr.size(); ++i) {
        if (i % 4 == 3) continue;
        peak = std::max(peak, double(a.hdr[i]));
        diff = std::max(diff, std::abs(double(a.hdr[i]) - double(b.hdr[i])));
    }
    return diff / peak;
}

bool contains(const std::vector<std::string>& v, const std::string& s) {
    return std::find(v.begin(), v.end(), s) != v.end();
}

// Draws a full-screen probe program (tests/gl/shaders/) with this frame's light buffers bound
// into a w x h RGBA32F target and reads it back (row 0 at the bottom).
std::vector<float> drawProbe(const std::string& shader, const std::string& define, int w, int h) {
    FrameRenderer& r = renderer();
    REQUIRE(r.localLights());
    return test::drawProbe(r.shaders(), shader, {define}, w, h, [&r] { r.localLights()->bindForForward(); });
}

const ViewParams kView{{-150.0, 120.0, 150.0}, 45.0, -30.0, 60.0, 0.5, 160, 90};

}  // namespace

TEST_CASE("gl: tiled, clustered and hashed culling light the same image as naive and miss no light") {
    Settings s = hillScene();
    addVolume(s, "grid", "box -200 0 -200 200 0 200  count 12 1 12  radius 35  intensity 400  jitter 0.8  ground 3");
    addLight(s, "spot", "spot 0 80 0  radius 150  color 1 0.9 0.7  intensity 8000  direction 0.2 -1 0.1  cone 10 25");
    addLight(s, "tiny", "point 30 30 30  radius 0.5  intensity 10");
    const Lit naive = render(s, LightCulling::Naive, kView);
    REQUIRE(naive.exact > 0);
    CHECK(naive.nonfinite == 0);
    CHECK(naive.evaluations > naive.exact);
    for (LightTileSize tile : {LightTileSize::Px16, LightTileSize::Px32}) {
        s.lights.tile_size = tile;
        for (LightCulling m : {LightCulling::Tiled, LightCulling::Clustered, LightCulling::Hashed}) {
            CAPTURE(int(m));
            CAPTURE(tilePixels(tile));
            const Lit lit = render(s, m, kView);
            CHECK(lit.exact == naive.exact);  // conservative: every reaching pair was shaded
            CHECK(lit.evaluations < naive.evaluations);
            CHECK(lit.overflow == 0);
            CHECK(lit.nonfinite == 0);
            const double diff = maxRelativeDiff(naive, lit);
            CAPTURE(diff);
            CHECK(diff <= 1e-3);
            std::printf("lights %-9s tile %2d: evaluations %8llu exact %7llu efficiency %.3f diff %.2g\n",
                        m == LightCulling::Tiled ? "tiled" : m == LightCulling::Clustered ? "clustered" : "hashed",
                        tilePixels(tile), (unsigned long long)lit.evaluations, (unsigned long long)lit.exact,
                        double(lit.exact) / double(std::max<std::uint64_t>(lit.evaluations, 1)), diff);
        }
    }
}

TEST_CASE("gl: overflowing light lists are counted and still shade every light that reaches") {
    Settings s = hillScene();
    addVolume(s, "dense", "box -60 0 -60 60 0 60  count 8 1 8  radius 60  intensity 200  ground 3");
    s.lights.max_lights_per_cell = 4;
    const Lit naive = render(s, LightCulling::Naive, kView);
    for (LightCulling m : {LightCulling::Tiled, LightCulling::Clustered}) {
        CAPTURE(int(m));
        const Lit lit = render(s, m, kView);
        CHECK(lit.overflow > 0);
        CHECK(lit.exact == naive.exact);
        CHECK(maxRelativeDiff(naive, lit) <= 1e-3);
    }
}

TEST_CASE("gl: 100,000 lights and zero-radius lights give finite images") {
    Settings s = hillScene();
    addVolume(s, "many", "box -200 0 -200 200 30 200  count 100 10 100  radius 4  intensity 50  jitter 1");
    ViewParams small = kView;
    small.width = 48;
    small.height = 27;
    for (LightCulling m : {LightCulling::Tiled, LightCulling::Clustered}) {
        CAPTURE(int(m));
        const Lit lit = render(s, m, small);
        CHECK(lit.nonfinite == 0);
        CHECK(lit.exact > 0);
    }
    Settings z = hillScene();
    addVolume(z, "zero", "box -200 0 -200 200 0 200  count 30 1 30  radius 0  intensity 1000  ground 0");
    for (LightCulling m : {LightCulling::Naive, LightCulling::Tiled, LightCulling::Clustered, LightCulling::Hashed}) {
        CAPTURE(int(m));
        const Lit lit = render(z, m, small);
        CHECK(lit.nonfinite == 0);
        CHECK(lit.exact == 0);  // radius 0 reaches nothing
        for (std::size_t i = 0; i < lit.hdr.size(); i += 4) CHECK_MESSAGE(lit.hdr[i] == 0.0f, i);
    }
}

TEST_CASE("gl: a light exactly at the camera and one behind it light the ground in front") {
    Settings s = hillScene();
    addLight(s, "at_camera", "point -150 120 150  radius 300  intensity 20000");
    addLight(s, "behind", "point -250 100 250  radius 400  intensity 20000");
    const Lit naive = render(s, LightCulling::Naive, kView);
    CHECK(naive.nonfinite == 0);
    CHECK(naive.exact > 0);
    for (LightCulling m : {LightCulling::Tiled, LightCulling::Clustered, LightCulling::Hashed}) {
        CAPTURE(int(m));
        const Lit lit = render(s, m, kView);
        CHECK(lit.nonfinite == 0);
        CHECK(lit.exact == naive.exact);
        CHECK(maxRelativeDiff(naive, lit) <= 1e-3);
    }
}

TEST_CASE("gl: moving lights: the hashed octree updates without a rebuild and matches naive") {
    Settings s = hillScene();
    addVolume(s, "grid", "box -200 0 -200 200 0 200  count 10 1 10  radius 30  intensity 400  ground 3");
    s.lights.animation.motion = LightMotion::Circle;
    s.lights.animation.amplitude_m = 6.0f;
    s.lights.animation.period_s = 8.0f;
    s.lights.animation.fraction = 0.1f;  // a few lights move, as in a village with some lanterns carried about
    const double times[2] = {1.0, 2.5};
    Lit naive[2];
    for (int i = 0; i < 2; ++i) naive[i] = render(s, LightCulling::Naive, kView, times[i]);
    render(s, LightCulling::Hashed, kView, 0.0);  // builds the octree
    REQUIRE(renderer().localLights());
    const std::size_t full_upload = renderer().localLights()->stats().hash_upload_bytes;
    CHECK(full_upload > 0);
    for (int i = 0; i < 2; ++i) {
        CAPTURE(times[i]);
        const Lit hashed = render(s, LightCulling::Hashed, kView, times[i]);
        REQUIRE(renderer().localLights());
        const LightHashStats& h = renderer().localLights()->stats().hash;
        CHECK_FALSE(h.full_rebuild);
        CHECK(h.lights_changed > 0);
        CHECK(renderer().localLights()->stats().hash_upload_bytes < full_upload);  // only what changed
        CHECK(hashed.exact == naive[i].exact);
        CHECK(maxRelativeDiff(naive[i], hashed) <= 1e-3);
    }
}

TEST_CASE("gl: a scene without local lights runs no light pass and holds no light buffers") {
    Settings s = hillScene();
    Lit none = render(s, LightCulling::Clustered, kView);
    CHECK_FALSE(contains(none.executed, "lights.cull"));
    CHECK_FALSE(contains(none.executed, "lights.shade"));
    CHECK(renderer().localLights() == nullptr);
    addVolume(s, "grid", "box -200 0 -200 200 0 200  count 4 1 4  radius 30  intensity 400  ground 3");
    Lit some = render(s, LightCulling::Clustered, kView);
    CHECK(contains(some.executed, "lights.cull"));
    CHECK(contains(some.executed, "lights.shade"));
    CHECK(renderer().localLights() != nullptr);
    // Lights whose spheres all miss the view frustum (behind the camera): tiled and clustered
    // skip their passes; their image is the same as naive's.
    Settings behind = hillScene();
    addVolume(behind, "behind", "box -400 0 300 -300 0 400  count 4 1 4  radius 30  intensity 400  ground 3");
    const Lit naive = render(behind, LightCulling::Naive, kView);
    CHECK(contains(naive.executed, "lights.shade"));
    CHECK(naive.exact == 0);
    for (LightCulling m : {LightCulling::Tiled, LightCulling::Clustered}) {
        const Lit lit = render(behind, m, kView);
        CHECK_FALSE(contains(lit.executed, "lights.cull"));
        CHECK_FALSE(contains(lit.executed, "lights.shade"));
        CHECK(renderer().localLights()->stats().visible == 0);
        CHECK(maxRelativeDiff(naive, lit) == 0.0);
    }
    s.lights.enabled = false;
    Lit off = render(s, LightCulling::Clustered, kView);
    CHECK_FALSE(contains(off.executed, "lights.shade"));
    CHECK(renderer().localLights() == nullptr);
}

TEST_CASE("gl: forward light lists cover transparent surfaces in front of the opaque ones") {
    Settings s = hillScene();
    addVolume(s, "near", "box -250 60 50 -50 180 250  count 6 3 6  radius 30  intensity 400");
    useHills(s);
    FrameRenderer& r = renderer();
    const int w = kView.width, h = kView.height;
    auto probe = [&](LightCulling method, bool forward) {
        s.lights.culling = method;
        FrameRequest request;
        std::vector<unsigned char> ldr;
        request.capture_ldr = &ldr;
        request.forward_lights = forward;
        r.resetHistory();  // a first frame: no TAA jitter or history, as the test expects
        r.render(s, kView, 0.0, request);
        REQUIRE(r.localLights());
        const std::vector<float> texels = drawProbe("tests/gl/shaders/forward_probe.glsl", r.localLights()->define(), w, h);
        double missed = 0, reaching = 0, evaluated = 0;
        for (std::size_t i = 0; i < texels.size(); i += 4) {
            missed += texels[i];
            reaching += texels[i + 1];
            evaluated += texels[i + 2];
        }
        std::printf("forward probe method %d forward %d: reaching %.0f evaluated %.0f missed %.0f\n", int(method),
                    int(forward), reaching, evaluated, missed);
        return std::array<double, 3>{missed, reaching, evaluated};
    };
    for (LightCulling m : {LightCulling::Naive, LightCulling::Tiled, LightCulling::Clustered, LightCulling::Hashed}) {
        CAPTURE(int(m));
        auto [missed, reaching, evaluated] = probe(m, true);
        CHECK(reaching > 0);
        CHECK(missed == 0);
        if (m != LightCulling::Naive) CHECK(evaluated < double(kView.width * kView.height) * 108.0);
    }
    // Without the forward flag the clustered lists only cover the opaque pixels' clusters: the
    // probe sees the difference (the check above is not vacuous).
    CHECK(probe(LightCulling::Clustered, false)[0] > 0);
}

TEST_CASE("gl: switching methods frees the structures the new method does not use") {
    Settings s = hillScene();
    addVolume(s, "grid", "box -200 0 -200 200 0 200  count 10 1 10  radius 30  intensity 400  ground 3");
    render(s, LightCulling::Hashed, kView);
    REQUIRE(renderer().localLights());
    const std::size_t hashed = renderer().localLights()->stats().memory_bytes;
    s.lights.volumes[0].volume.count = {12, 1, 12};  // new lights and a new method in one frame
    render(s, LightCulling::Naive, kView);
    const std::size_t naive = renderer().localLights()->stats().memory_bytes;
    CAPTURE(hashed);
    CAPTURE(naive);
    CHECK(naive <= std::size_t(144 * 48 * 3 / 2 + 256));  // the light buffer (grown at most 1.5x) and the grid block
    render(s, LightCulling::Clustered, kView);
    CHECK(renderer().localLights()->stats().memory_bytes > naive);
}

TEST_CASE("gl: the GPU's light shading matches the double-precision CPU mirror (falloff, spot cone, BRDF)") {
    FrameRenderer& r = renderer();
    const int w = 80, h = 40;
    for (const char* spec : {"point -150 118 146  radius 12  color 1 0.8 0.6  intensity 50",
                             "spot -148 124 140  radius 30  color 0.7 0.9 1  intensity 300  direction 0.2 -1 -0.3  cone 15 35",
                             "spot -150 119 147  radius 20  intensity 100  direction 0 -1 0  cone 30 30"}) {
        CAPTURE(spec);
        Settings s = hillScene();
        addLight(s, "probe", spec);
        s.lights.culling = LightCulling::Naive;
        useHills(s);
        FrameRequest request;
        std::vector<unsigned char> ldr;
        request.capture_ldr = &ldr;
        r.resetHistory();  // a first frame: no TAA jitter or history, as the test expects
        r.render(s, kView, 0.0, request);
        const std::vector<float> gpu = drawProbe("tests/gl/shaders/light_reference_probe.glsl", "LIGHTS_NAIVE", w, h);

        const Light& light = s.lights.lights[0].light;
        const glm::dvec3 albedo{0.8, 0.6, 0.4}, n = glm::normalize(glm::dvec3(0.1, 1.0, 0.2));
        double peak = 0.0, worst = 0.0;
        int reached = 0, disagree = 0;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const glm::dvec3 rel{x * 0.5 - 20.0, -6.0 + 0.05 * y, -2.0 - 0.5 * y};
                const glm::dvec3 world = kView.position + rel;
                const glm::dvec3 l = glm::normalize(light.position - world), v = glm::normalize(-rel);
                const glm::dvec3 cpu = attenuation(light, world) * evalBrdf(albedo, 0.35, 0.04, n, l, v) *
                                       glm::dvec3(light.color) * double(light.intensity) * std::max(glm::dot(n, l), 0.0);
                const float* g = &gpu[(std::size_t(y) * w + std::size_t(x)) * 4];
                // Reach is exact in double; float may differ within 1e-5 of the edge.
                const double edge = std::abs(glm::length(light.position - world) - light.radius_m);
                if ((g[3] > 0.5f) != reaches(light, world) && edge > 1e-3) ++disagree;
                reached += reaches(light, world);
                for (int c = 0; c < 3; ++c) {
                    peak = std::max(peak, cpu[c]);
                    worst = std::max(worst, std::abs(double(g[c]) - cpu[c]));
                }
            }
        CAPTURE(peak);
        CAPTURE(worst);
        CHECK(reached > 50);
        CHECK(disagree == 0);
        CHECK(worst <= 2e-3 * peak);
    }
}

// Issue 19 defect 6, the CI-sized case of the 150,000 / 262,144 / 1,000,000-light test (in
// forward_lights_test.cpp with the forward surfaces): 70,000 lights (past llvmpipe's 65,535 loop
// iterations per invocation, where naive's loop and overflowed cells' "every light" stopped) at 16x9.
TEST_CASE("gl: 70,000 lights at 16x9: every method lights the same image as naive") {
    Settings s = hillScene();
    addVolume(s, "many", "box -200 0 -200 200 30 200  count 70 10 100  radius 4  intensity 50  jitter 1");
    ViewParams tiny = kView;
    tiny.width = 16;
    tiny.height = 9;
    const Lit ref = render(s, LightCulling::Naive, tiny);
    REQUIRE(ref.exact > 0);
    for (LightCulling m : {LightCulling::Tiled, LightCulling::Clustered, LightCulling::Hashed}) {
        CAPTURE(int(m));
        const Lit lit = render(s, m, tiny);
        CHECK(lit.exact == ref.exact);
        CHECK(lit.nonfinite == 0);
        CHECK(maxRelativeDiff(ref, lit) <= 1e-3);
    }
}
