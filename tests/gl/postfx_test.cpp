// Post effects on small synthetic inputs under OSMesa: the chain's order and culling, auto
// exposure's metering and adaptation, tone maps, bloom and FXAA, each on an image made here
// (imported into a frame graph) rather than on a rendered scene; SSAO on a synthetic G-buffer.
#include "app/frame.h"
#include "app/scene.h"
#include "postfx/bloom.h"
#include "postfx/chain.h"
#include "postfx/dof.h"
#include "postfx/fxaa.h"
#include "postfx/lens_flare.h"
#include "postfx/lut.h"
#include "sky/atmosphere.h"
#include "sky/night_light.h"
#include "postfx/motion_blur.h"
#include "postfx/grade.h"
#include "postfx/ssao.h"
#include "gl_fixture.h"

#include <algorithm>
#include <cmath>
#include <limits>

using namespace vista;

namespace {

// Runs post passes on an RGBA32F image (rows bottom first, as GL stores them) and reads the
// result back as floats (RGBA8 results in [0, 1]).
struct Bench {
    ShaderLibrary shaders{vistaRoot()};
    GlDevice device;
    TransientPool pool{device};
    gl::VertexArray vao = gl::createVertexArray("postfx test");
    PostChain chain;
    std::vector<std::string> executed;
    ViewParams camera;  // the view the passes see (its size is the image's)
    SkySettings sky;    // the frame's sun and units come from it (as FrameRenderer::context sets them)

    template <class AddPasses>
    std::vector<float> run(const std::vector<float>& rgba, int w, int h, double time_s, AddPasses&& add, bool read = true) {
        gl::Texture input = gl::Texture::create2D(w, h, GL_RGBA32F, 1, "postfx test input");
        glTextureSubImage2D(input.id(), 0, 0, 0, w, h, GL_RGBA, GL_FLOAT, rgba.data());
        ViewParams view = camera;
        view.width = w, view.height = h;
        RenderContext rc{shaders, device, vao.id(), view, ViewMatrices{}, 0, time_s};
        rc.sun_direction = sunDirection(sky);
        rc.sun_illuminance = sky.sun_illuminance;
        rc.cd_per_value = luxPerHdrUnit(sky.sun_illuminance);
        FrameGraph graph;
        TextureHandle in = graph.importTexture("input", {w, h, PixelFormat::RGBA32F}, input.id());
        TextureHandle out = add(graph, rc, in);
        std::vector<float> result;
        if (read) test::addReadback(graph, out, result);
        graph.compile();
        graph.execute(pool, nullptr);
        pool.endFrame();
        executed = graph.executedPasses();
        return result;
    }
    // shown = false: nothing reads the chain's image (an HDR-only capture), the graph culls it.
    std::vector<float> chainRun(const std::vector<float>& rgba, int w, int h, const Settings& s, double time_s = 0.0,
                                bool shown = true) {
        sky = s.sky;
        return run(rgba, w, h, time_s, [&](FrameGraph& g, const RenderContext& rc, TextureHandle in) {
            return chain.addPasses(g, rc, in, s, {}, shown);
        }, shown);
    }
};

std::vector<float> uniform(int w, int h, float value) {
    std::vector<float> v(std::size_t(w) * std::size_t(h) * 4, value);
    for (std::size_t i = 3; i < v.size(); i += 4) v[i] = 1.0f;
    return v;
}

void setPixel(std::vector<float>& v, int w, int x, int y, float value) {
    for (int c = 0; c < 3; ++c) v[(std::size_t(y) * std::size_t(w) + std::size_t(x)) * 4 + std::size_t(c)] = value;
}

float pixel(const std::vector<float>& v, int w, int x, int y, int c = 0) {
    return v[(std::size_t(y) * std::size_t(w) + std::size_t(x)) * 4 + std::size_t(c)];
}

bool allFinite(const std::vector<float>& v) {
    return std::all_of(v.begin(), v.end(), [](float x) { return std::isfinite(x); });
}

float srgb(float linear) {
    return linear <= 0.0031308f ? linear * 12.92f : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

std::vector<std::string> postfxPasses(const std::vector<std::string>& executed) {
    std::vector<std::string> out;
    for (const auto& p : executed)
        if (p.rfind("postfx.", 0) == 0) out.push_back(p);
    return out;
}

bool has(const std::vector<std::string>& passes, const std::string& prefix) {
    return std::any_of(passes.begin(), passes.end(), [&](const std::string& p) { return p.rfind(prefix, 0) == 0; });
}

}  // namespace

TEST_CASE("gl: postfx programs compile") {
    test::glContext();
    ShaderLibrary shaders(vistaRoot());
    for (const auto& [file, defines] : postfxPrograms()) {
        INFO(file);
        CHECK(shaders.get(file, defines) != nullptr);
        CHECK(shaders.lastError() == "");
    }
}

TEST_CASE("gl: the post chain runs in [postfx] order, disabled effects add no pass, an empty chain still encodes") {
    test::glContext();
    Bench bench;
    Settings s;
    const std::vector<float> image = uniform(32, 18, 0.5f);
    bench.chainRun(image, 32, 18, s);
    std::vector<std::string> passes = postfxPasses(bench.executed);
    REQUIRE(!passes.empty());
    CHECK_FALSE(has(passes, "postfx.fxaa"));  // off by default: TAA anti-aliases (docs/temporal.md)
    CHECK(passes.back() == "postfx.tonemap");

    s.fxaa.enabled = true;  // the low preset's anti-aliasing; on here so the order covers every effect
    bench.chainRun(image, 32, 18, s);
    passes = postfxPasses(bench.executed);
    REQUIRE(!passes.empty());
    CHECK(passes.front() == "postfx.bloom.down1");
    CHECK(passes.back() == "postfx.fxaa");
    const auto at = [&](const std::string& name) { return std::find(passes.begin(), passes.end(), name) - passes.begin(); };
    CHECK(at("postfx.bloom.composite") < at("postfx.exposure.histogram"));
    CHECK(at("postfx.exposure.adapt") < at("postfx.tonemap"));
    CHECK_FALSE(has(passes, "postfx.exposure.apply"));  // the tone map applies it

    s.postfx.order = {PostEffect::Fxaa, PostEffect::Exposure, PostEffect::Bloom, PostEffect::Tonemap};
    bench.chainRun(image, 32, 18, s);
    passes = postfxPasses(bench.executed);
    CHECK(passes.front() == "postfx.fxaa");
    CHECK(at("postfx.exposure.adapt") < at("postfx.exposure.apply"));  // bloom comes between
    CHECK(at("postfx.exposure.apply") < at("postfx.bloom.down1"));
    CHECK(passes.back() == "postfx.tonemap");

    s = Settings{};
    s.bloom.enabled = false;
    s.fxaa.enabled = false;
    s.exposure.mode = ExposureMode::Manual;
    bench.chainRun(image, 32, 18, s);
    passes = postfxPasses(bench.executed);
    CHECK(passes == std::vector<std::string>{"postfx.tonemap"});
    CHECK(bench.chain.autoExposure() == nullptr);  // nothing kept for an effect that is off

    s.postfx.order.clear();
    std::vector<float> out = bench.chainRun(image, 32, 18, s);
    CHECK(postfxPasses(bench.executed) == std::vector<std::string>{"postfx.encode"});
    CHECK(pixel(out, 32, 5, 5) == doctest::Approx(srgb(0.5f)).epsilon(0.01));

    s = Settings{};
    s.postfx.enabled = false;
    bench.chainRun(image, 32, 18, s);
    CHECK(postfxPasses(bench.executed) == std::vector<std::string>{"postfx.encode"});
}

TEST_CASE("gl: auto exposure brings a uniform image to middle grey and ignores NaN and Inf pixels") {
    test::glContext();
    Bench bench;
    Settings s;
    s.postfx.order = {PostEffect::Exposure};  // then the clamp encode: the output is 0.18 encoded
    const float luminance = 3.7f;
    std::vector<float> image = uniform(40, 24, luminance);
    std::vector<float> out = bench.chainRun(image, 40, 24, s);
    REQUIRE(bench.chain.autoExposure());
    const postfx::ExposureState clean = bench.chain.autoExposure()->read();
    // Metering resolves half a histogram bin: 48 / 254 / 2 stops, 6.8 %.
    const double half_bin = std::exp2(48.0 / 254.0 / 2.0) - 1.0;
    CHECK(clean.valid == 1.0f);
    CHECK(clean.scale * luminance == doctest::Approx(0.18).epsilon(half_bin));
    CHECK(pixel(out, 40, 20, 12) == doctest::Approx(srgb(0.18f)).epsilon(0.05));

    for (int y = 0; y < 24; y += 3)
        for (int x = y % 5; x < 40; x += 5)
            setPixel(image, 40, x, y, (x + y) % 2 ? std::numeric_limits<float>::quiet_NaN() : std::numeric_limits<float>::infinity());
    Bench again;
    again.chainRun(image, 40, 24, s);
    const postfx::ExposureState dirty = again.chain.autoExposure()->read();
    CHECK(dirty.scale == doctest::Approx(clean.scale).epsilon(1e-6));  // the same bin, summed in another order
    CHECK(std::isfinite(dirty.adapted_log2));

    s.exposure.ev = 1.0f;  // compensation doubles the scale
    Bench brighter;
    brighter.chainRun(uniform(40, 24, luminance), 40, 24, s);
    CHECK(brighter.chain.autoExposure()->read().scale == doctest::Approx(2.0f * clean.scale).epsilon(1e-5));

    s.exposure.ev = 0.0f;
    s.exposure.max_ev = -2.0f;  // the meter stops at 2^-2: a brighter scene stays brighter
    Bench clamped;
    clamped.chainRun(uniform(40, 24, luminance), 40, 24, s);
    CHECK(clamped.chain.autoExposure()->read().scale == doctest::Approx(0.18f * 4.0f).epsilon(1e-5));
}

TEST_CASE("gl: auto exposure adapts exponentially in time, independent of the frame rate") {
    test::glContext();
    Settings s;
    s.postfx.order = {PostEffect::Exposure};
    s.exposure.speed_up = 1.5f;
    const std::vector<float> dark = uniform(16, 16, 1.0f), bright = uniform(16, 16, 16.0f);
    Bench fine, coarse;
    fine.chainRun(dark, 16, 16, s, 10.0);
    coarse.chainRun(dark, 16, 16, s, 10.0);
    const float start = fine.chain.autoExposure()->read().adapted_log2;
    for (int i = 1; i <= 10; ++i) fine.chainRun(bright, 16, 16, s, 10.0 + 0.1 * i);
    coarse.chainRun(bright, 16, 16, s, 11.0);
    const postfx::ExposureState a = fine.chain.autoExposure()->read(), b = coarse.chain.autoExposure()->read();
    CHECK(a.adapted_log2 == doctest::Approx(b.adapted_log2).epsilon(1e-4));
    const float expected = a.target_log2 + (start - a.target_log2) * std::exp(-1.5f);
    CHECK(a.adapted_log2 == doctest::Approx(expected).epsilon(1e-4));
    CHECK(a.adapted_log2 > start);
    CHECK(a.adapted_log2 < a.target_log2);

    coarse.chainRun(bright, 16, 16, s, 0.0);  // time went back (a restart): take the target at once
    CHECK(coarse.chain.autoExposure()->read().adapted_log2 == coarse.chain.autoExposure()->read().target_log2);

    // Frames nobody shows (culled chain) do not eat adaptation time: shown at 10 and 11 s with
    // hidden frames between, the exposure adapts as far as over the one 1 s step.
    Bench hidden;
    hidden.chainRun(dark, 16, 16, s, 10.0);
    for (int i = 1; i < 10; ++i) {
        hidden.chainRun(bright, 16, 16, s, 10.0 + 0.1 * i, false);
        CHECK(hidden.executed.empty());
    }
    hidden.chainRun(bright, 16, 16, s, 11.0);
    CHECK(hidden.chain.autoExposure()->read().adapted_log2 == doctest::Approx(b.adapted_log2).epsilon(1e-4));
}

TEST_CASE("gl: every tone map is monotonic and maps 0 to 0") {
    test::glContext();
    const int w = 256;
    std::vector<float> ramp = uniform(w, 1, 0.0f);
    for (int x = 1; x < w; ++x) setPixel(ramp, w, x, 0, float(1e-4 * std::pow(1e8, double(x - 1) / double(w - 2))));
    for (Tonemapper op : {Tonemapper::Reinhard, Tonemapper::Aces, Tonemapper::Clamp, Tonemapper::Agx}) {
        INFO("operator " << int(op));
        Bench bench;
        Settings s;
        s.postfx.order = {PostEffect::Tonemap};
        s.tonemap.op = op;
        std::vector<float> out = bench.chainRun(ramp, w, 1, s);
        for (int c = 0; c < 3; ++c) {
            CHECK(pixel(out, w, 0, 0, c) == 0.0f);
            for (int x = 1; x < w; ++x) CHECK(pixel(out, w, x, 0, c) >= pixel(out, w, x - 1, 0, c));
            CHECK(pixel(out, w, w - 1, 0, c) > 0.95f);  // 1e4 is white
            CHECK(pixel(out, w, 1, 0, c) < 0.01f);      // 1e-4 is black
        }
        // Middle grey lands in the middle third of the display range.
        std::vector<float> grey = bench.chainRun(uniform(4, 4, 0.18f), 4, 4, s);
        CHECK(grey[0] > 0.3f);
        CHECK(grey[0] < 0.7f);
    }
}

TEST_CASE("gl: bloom of a single hot pixel is bounded, symmetric and conserves energy") {
    test::glContext();
    Bench bench;
    BloomSettings b;
    b.intensity = 0.5f;
    b.levels = 5;  // 63 -> 31 -> 15 -> 7 -> 3 -> 1: the centre pixel stays a texel centre
    const int n = 63, c = 31;
    std::vector<float> image = uniform(n, n, 0.0f);
    setPixel(image, n, c, c, 100.0f);
    std::vector<float> out = bench.run(image, n, n, 0.0, [&](FrameGraph& g, const RenderContext& rc, TextureHandle in) {
        return addBloomPasses(g, rc, in, b);
    });
    REQUIRE(allFinite(out));
    double sum = 0.0;
    float peak = 0.0f;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const float v = pixel(out, n, x, y);
            sum += v;
            peak = std::max(peak, v);
            CHECK(v >= 0.0f);
        }
    CHECK(peak <= 100.0f);
    CHECK(pixel(out, n, c, c) == peak);
    CHECK(pixel(out, n, c + 1, c) > 0.0f);   // it spreads
    // Mixing never adds energy; the Karis average takes some from a lone firefly on purpose.
    CHECK(sum <= 100.0 * 1.001);
    CHECK(sum > 50.0);  // the hot pixel keeps half (intensity 0.5) and the glow gets some
    float asymmetry = 0.0f;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const float v = pixel(out, n, x, y);
            asymmetry = std::max({asymmetry, std::abs(v - pixel(out, n, n - 1 - x, y)), std::abs(v - pixel(out, n, x, n - 1 - y)),
                                  std::abs(v - pixel(out, n, y, x))});
        }
    CHECK(asymmetry <= 1e-3f * peak);
}

TEST_CASE("gl: bloom keeps a NaN or 1e30 pixel finite and local") {
    test::glContext();
    BloomSettings b;
    b.intensity = 0.5f;
    b.levels = 2;
    const int w = 128, h = 72, x0 = 50, y0 = 30;
    for (float bad : {std::numeric_limits<float>::quiet_NaN(), 1e30f, std::numeric_limits<float>::infinity()}) {
        INFO("bad pixel " << bad);
        Bench bench;
        std::vector<float> image = uniform(w, h, 0.5f);
        setPixel(image, w, x0, y0, bad);
        std::vector<float> out = bench.run(image, w, h, 0.0, [&](FrameGraph& g, const RenderContext& rc, TextureHandle in) {
            return addBloomPasses(g, rc, in, b);
        });
        CHECK(allFinite(out));
        float far_change = 0.0f, near_max = 0.0f;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const float v = pixel(out, w, x, y);
                if (std::max(std::abs(x - x0), std::abs(y - y0)) > 24) far_change = std::max(far_change, std::abs(v - 0.5f));
                else near_max = std::max(near_max, v);
            }
        CHECK(far_change < 1e-3f);
        CHECK(near_max <= 65504.0f);
        // A huge but finite highlight is clamped and still blooms; NaN and Inf count as 0 (a
        // bilinear tap across Inf is NaN, so the two cannot be told apart).
        if (std::isfinite(bad)) CHECK(near_max > 1.0f);
    }
}

TEST_CASE("gl: FXAA softens a stair-stepped edge and leaves flat areas alone") {
    test::glContext();
    Bench bench;
    const int w = 64, h = 64;
    std::vector<float> image = uniform(w, h, 0.0f);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            if (x * 3 < y * 2 + 16) setPixel(image, w, x, y, 1.0f);  // a slope of 1.5: stairs
    FxaaSettings f;
    std::vector<float> out = bench.run(image, w, h, 0.0, [&](FrameGraph& g, const RenderContext& rc, TextureHandle in) {
        return addFxaaPass(g, rc, in, f, false);
    });
    REQUIRE(allFinite(out));
    int softened = 0, changed_far = 0;
    for (int y = 2; y < h - 2; ++y)
        for (int x = 2; x < w - 2; ++x) {
            const float v = pixel(out, w, x, y), before = pixel(image, w, x, y);
            CHECK(v >= 0.0f);
            CHECK(v <= 1.0f);
            const float edge = std::abs(float(x * 3) - float(y * 2 + 16)) / 3.6f;  // px from the edge line
            if (v > 0.02f && v < 0.98f) ++softened;
            if (edge > 3.0f && v != before) ++changed_far;
        }
    CHECK(softened > h / 2);
    CHECK(changed_far == 0);
}

namespace {

// A synthetic G-buffer seen from the origin looking along -z: a floor at y = -1 and, with
// wall, a wall at z = -6 facing the camera. Depth (reversed-Z) and normals (octahedral, lit)
// per pixel, rows bottom first; also each pixel's distance to the floor/wall crease.
struct Gbuffer {
    int w, h;
    std::vector<float> depth, normal, crease;
};

Gbuffer syntheticGbuffer(const ViewParams& view, bool wall) {
    const ViewMatrices m = viewMatrices(view);
    Gbuffer g{view.width, view.height, {}, {}, {}};
    for (int y = 0; y < g.h; ++y)
        for (int x = 0; x < g.w; ++x) {
            glm::vec4 far = m.inv_view_proj * glm::vec4((x + 0.5f) / g.w * 2 - 1, (y + 0.5f) / g.h * 2 - 1, 0.5f, 1.0f);
            glm::vec3 dir = glm::normalize(glm::vec3(far) / far.w);
            float t = 1e30f;
            glm::vec3 n{0.0f};
            if (dir.y < 0.0f) t = -1.0f / dir.y, n = {0, 1, 0};
            if (wall && dir.z < 0.0f && -6.0f / dir.z < t) t = -6.0f / dir.z, n = {0, 0, 1};
            float d = 0.0f, c = 1e30f;
            glm::vec4 e{0.0f};
            if (t < 1e29f) {
                glm::vec3 p = dir * t;
                glm::vec4 clip = m.view_proj * glm::vec4(p, 1.0f);
                d = clip.z / clip.w;
                c = glm::length(glm::vec2(p.y + 1.0f, p.z + 6.0f));
                glm::vec3 o = n / (std::abs(n.x) + std::abs(n.y) + std::abs(n.z));  // octahedral (n.y >= 0 here)
                e = {o.x * 0.5f + 0.5f, o.z * 0.5f + 0.5f, 0.25f, 1.0f};
            }
            g.depth.push_back(d);
            for (int i = 0; i < 4; ++i) g.normal.push_back(e[i]);
            g.crease.push_back(c);
        }
    return g;
}

// frame: the screen estimators' blue-noise frame (u_time.w; TAA's sequence index in a frame).
std::vector<float> runSsao(FrameRenderer& renderer, const Gbuffer& g, const ViewParams& view, const SsaoSettings& s,
                           std::uint32_t frame = 0) {
    Settings settings;
    RenderContext rc = renderer.context(view, settings, 0.0, {}, frame);  // binds the frame uniforms
    gl::Texture depth = gl::Texture::create2D(g.w, g.h, GL_DEPTH_COMPONENT32F, 1, "test depth");
    glTextureSubImage2D(depth.id(), 0, 0, 0, g.w, g.h, GL_DEPTH_COMPONENT, GL_FLOAT, g.depth.data());
    gl::Texture normal = gl::Texture::create2D(g.w, g.h, GL_RGBA16F, 1, "test normal");
    glTextureSubImage2D(normal.id(), 0, 0, 0, g.w, g.h, GL_RGBA, GL_FLOAT, g.normal.data());
    TransientPool pool(rc.device);
    FrameGraph graph;
    SceneTargets scene;
    scene.depth = graph.importTexture("depth", {g.w, g.h, PixelFormat::Depth32F}, depth.id());
    scene.normal = graph.importTexture("normal", {g.w, g.h, PixelFormat::RGBA16F}, normal.id());
    TextureHandle ao = addSsaoPasses(graph, rc, scene, s);
    std::vector<float> out;
    test::addReadback(graph, ao, out);
    graph.compile();
    graph.execute(pool, nullptr);
    pool.clear();
    return out;
}

std::vector<float> runSsao(const Gbuffer& g, const ViewParams& view, const SsaoSettings& s) {
    FrameRenderer renderer(vistaRoot());
    return runSsao(renderer, g, view, s);
}

}  // namespace

TEST_CASE("gl: SSAO leaves flat ground open and darkens a crease, at full and half size") {
    test::glContext();
    ViewParams view;
    view.width = 96, view.height = 64;
    view.pitch_deg = -20.0;
    for (bool half : {false, true}) {
        INFO("half resolution " << half);
        SsaoSettings s;
        s.half_resolution = half;
        s.radius_m = 1.0f;
        const Gbuffer flat = syntheticGbuffer(view, false);
        std::vector<float> ao = runSsao(flat, view, s);
        REQUIRE(allFinite(ao));
        float lowest = 1.0f;
        for (std::size_t i = 0; i < flat.depth.size(); ++i) lowest = std::min(lowest, ao[i * 4]);
        CHECK(lowest >= 0.98f);

        const Gbuffer crease = syntheticGbuffer(view, true);
        ao = runSsao(crease, view, s);
        REQUIRE(allFinite(ao));
        double near_sum = 0.0, far_min = 1.0;
        int near_count = 0;
        for (std::size_t i = 0; i < crease.depth.size(); ++i) {
            const float v = ao[i * 4];
            CHECK(v >= 0.0f);
            CHECK(v <= 1.0f);
            if (crease.depth[i] <= 0.0f) CHECK(v == 1.0f);  // sky
            else if (crease.crease[i] < 0.25f) near_sum += v, ++near_count;
            else if (crease.crease[i] > 1.5f) far_min = std::min(far_min, double(v));
        }
        REQUIRE(near_count > 0);
        CHECK(near_sum / near_count < 0.9);  // about 0.86: from 1 or 2 of the 4 directions the wall rises
        CHECK(far_min >= 0.95);
    }
}

// The directions' rotation and the steps' offset come from spatiotemporal blue noise indexed by
// the frame, so TAA's average over frames converges towards the many-direction answer; a fixed
// per-pixel hash (the interleaved gradient noise used before) gives the same error every frame.
TEST_CASE("gl: SSAO's blue noise averages out over frames towards a converged reference") {
    test::glContext();
    ViewParams view;
    view.width = 96, view.height = 64;
    view.pitch_deg = -20.0;
    const Gbuffer crease = syntheticGbuffer(view, true);
    SsaoSettings s;
    s.half_resolution = false;
    s.blur = false;  // the raw estimator
    s.radius_m = 1.0f;
    s.directions = 4;
    s.steps = 4;
    // Converged: 64 directions, averaged over 16 frames (also over the steps' offsets).
    SsaoSettings many = s;
    many.directions = 64;
    const std::size_t n = crease.depth.size();
    FrameRenderer renderer(vistaRoot());
    auto mean = [&](const SsaoSettings& settings, int frames) {
        std::vector<double> sum(n, 0.0);
        for (int k = 0; k < frames; ++k) {
            const std::vector<float> ao = runSsao(renderer, crease, view, settings, std::uint32_t(k));
            REQUIRE(ao.size() == n * 4);
            for (std::size_t i = 0; i < n; ++i) sum[i] += ao[i * 4] / double(frames);
        }
        return sum;
    };
    const std::vector<double> reference = mean(many, 16);
    auto rms = [&](const std::vector<double>& a) {
        double e = 0.0;
        int count = 0;
        for (std::size_t i = 0; i < n; ++i)
            if (crease.depth[i] > 0.0f && crease.crease[i] < 1.0f) e += (a[i] - reference[i]) * (a[i] - reference[i]), ++count;
        REQUIRE(count > 100);
        return std::sqrt(e / count);
    };
    const double one = rms(mean(s, 1)), eight = rms(mean(s, 8));
    MESSAGE("SSAO rms error against the converged reference: 1 frame " << one << ", mean of 8 frames " << eight);
    CHECK(one > 0.005);          // the 4-direction estimate is noisy near the crease
    CHECK(eight < 0.5 * one);    // white noise would give 0.35; a fixed hash 1.0
}

TEST_CASE("gl: SSAO runs before the sun lighting, and adds no pass when disabled") {
    test::glContext();
    FrameRenderer renderer(vistaRoot());
    Settings s;
    REQUIRE(renderer.prepare(s).empty());  // the terrain: a G-buffer to occlude
    std::vector<unsigned char> ldr;
    FrameRequest request;
    request.capture_ldr = &ldr;
    ViewParams view{{0.0, 50.0, 0.0}, 0.0, -10.0, 60.0, 0.1, 64, 36};
    FrameReport report = renderer.render(s, view, 0.0, request);
    const auto at = [&](const std::string& name) {
        return std::find(report.executed.begin(), report.executed.end(), name) - report.executed.begin();
    };
    REQUIRE(at("postfx.ssao") < std::ptrdiff_t(report.executed.size()));
    CHECK(at("postfx.ssao") < at("postfx.ssao.blur"));
    CHECK(at("postfx.ssao.blur") < at("lighting.sun"));
    s.ssao.enabled = false;
    report = renderer.render(s, view, 0.0, request);
    CHECK_FALSE(has(report.executed, "postfx.ssao"));
    CHECK_FALSE(has(report.culled, "postfx.ssao"));
}

TEST_CASE("gl: grading is neutral at its defaults, lifts, gains, desaturates and vignettes") {
    test::glContext();
    const int w = 64, h = 36;
    std::vector<float> image = uniform(w, h, 0.0f);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::size_t i = (std::size_t(y) * w + std::size_t(x)) * 4;
            image[i] = float(x) / float(w - 1), image[i + 1] = float(y) / float(h - 1), image[i + 2] = 0.5f;
        }
    const auto grade = [&](const GradeSettings& g) {
        Bench bench;
        return bench.run(image, w, h, 0.0, [&](FrameGraph& graph, const RenderContext& rc, TextureHandle in) {
            return addGradePass(graph, rc, in, g);
        });
    };
    GradeSettings g;
    std::vector<float> out = grade(g);
    float largest = 0.0f;
    for (std::size_t i = 0; i < out.size(); ++i) largest = std::max(largest, std::abs(out[i] - image[i]));
    CHECK(largest < 1e-5f);

    g.lift = glm::vec3(0.2f);
    out = grade(g);
    CHECK(pixel(out, w, 0, 0, 0) == doctest::Approx(0.2f).epsilon(1e-4));   // black lifted
    CHECK(pixel(out, w, w - 1, 0, 0) == doctest::Approx(1.0f).epsilon(1e-4));  // white stays

    g = GradeSettings{};
    g.gain = glm::vec3(0.5f, 1.0f, 1.0f);
    out = grade(g);
    CHECK(pixel(out, w, w - 1, 0, 0) == doctest::Approx(0.5f).epsilon(1e-4));

    g = GradeSettings{};
    g.saturation = 0.0f;
    out = grade(g);
    CHECK(pixel(out, w, 40, 20, 0) == doctest::Approx(pixel(out, w, 40, 20, 1)).epsilon(1e-5));
    CHECK(pixel(out, w, 40, 20, 1) == doctest::Approx(pixel(out, w, 40, 20, 2)).epsilon(1e-5));

    g = GradeSettings{};
    g.vignette = 1.0f;
    std::vector<float> flat = uniform(w, h, 0.5f);
    Bench bench;
    out = bench.run(flat, w, h, 0.0, [&](FrameGraph& graph, const RenderContext& rc, TextureHandle in) {
        return addGradePass(graph, rc, in, g);
    });
    CHECK(pixel(out, w, w / 2, h / 2) == doctest::Approx(0.5f).epsilon(1e-5));  // the centre is untouched
    CHECK(pixel(out, w, 0, 0) < 0.05f);                                         // the corner nearly black
    CHECK(pixel(out, w, 0, 0) == doctest::Approx(pixel(out, w, w - 1, h - 1)).epsilon(1e-4));
    CHECK(allFinite(out));
}

namespace {

// A reversed-Z depth image (near 0.1 m, infinite far) from distances in metres (inf: sky).
std::vector<float> depthFromDistances(const std::vector<float>& distances, float near_m = 0.1f) {
    std::vector<float> d;
    for (float s : distances) d.push_back(std::isinf(s) ? 0.0f : near_m / s);
    return d;
}

// Runs add(graph, rc, image, depth) on an RGBA32F image and a Depth32F depth (rows bottom first).
template <class AddPasses>
std::vector<float> runWithDepth(Bench& bench, const std::vector<float>& rgba, const std::vector<float>& depth, int w,
                                int h, double time_s, AddPasses&& add) {
    gl::Texture d = gl::Texture::create2D(w, h, GL_DEPTH_COMPONENT32F, 1, "test depth");
    glTextureSubImage2D(d.id(), 0, 0, 0, w, h, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
    return bench.run(rgba, w, h, time_s, [&](FrameGraph& g, const RenderContext& rc, TextureHandle in) {
        TextureHandle dh = g.importTexture("depth", {w, h, PixelFormat::Depth32F}, d.id());
        return add(g, rc, in, dh);
    });
}

Settings dofOnly() {
    Settings s;
    s.postfx.order = {PostEffect::Dof};
    s.dof.enabled = true;
    return s;
}

}  // namespace

TEST_CASE("gl: depth of field's circle of confusion matches the thin-lens closed form") {
    test::glContext();
    const int w = 64, h = 36;
    DofSettings s;
    s.enabled = true;
    s.autofocus = false;
    s.focus_distance_m = 8.0f;
    s.focal_length_mm = 85.0f;
    s.f_stop = 1.8f;
    s.max_coc_px = 4.0f;
    std::vector<float> distances;
    for (int i = 0; i < w * h; ++i) distances.push_back(i == 0 ? INFINITY : 0.5f * std::pow(1.01f, float(i % 700)));
    Bench bench;
    const std::vector<float> out = runWithDepth(bench, uniform(w, h, 0.3f), depthFromDistances(distances), w, h, 0.0,
        [&](FrameGraph& g, const RenderContext& rc, TextureHandle in, TextureHandle depth) {
            return addDofCocPass(g, rc, in, depth, s, {});
        });
    REQUIRE(allFinite(out));
    int clamped = 0, checked = 0;
    for (int i = 0; i < w * h; ++i) {
        // The distance the shader sees: the stored float depth turned back into metres.
        const double stored = double(depthFromDistances({distances[std::size_t(i)]})[0]);
        const double distance = stored > 0.0 ? 0.1 / stored : INFINITY;
        const double expected = std::clamp(dofCocRadiusPx(distance, 8.0, s, h), -4.0, 4.0);
        const float got = out[std::size_t(i) * 4 + 3];
        INFO("distance " << distance << " m");
        CHECK(got == doctest::Approx(expected).epsilon(2e-3).scale(1.0));  // half float: 11 bits
        if (std::abs(expected) >= 4.0) ++clamped;
        ++checked;
        CHECK(out[std::size_t(i) * 4] == doctest::Approx(0.3f).epsilon(1e-3));
    }
    CHECK(clamped > 0);
    CHECK(clamped < checked);
    // The sky: f^2 / (N (S1 - f)) on the sensor, times height / sensor, halved.
    const double f = 0.085, sky = 0.5 * f * f / (1.8 * (8.0 - f)) / 0.024 * h;
    CHECK(out[3] == doctest::Approx(sky).epsilon(2e-3));
}

TEST_CASE("gl: autofocus moves smoothly at its rate, independent of the frame rate, and converges") {
    test::glContext();
    const int w = 48, h = 32;
    Settings s = dofOnly();
    s.dof.autofocus_rate = 2.0f;
    const auto scene = [&](float centre_m) {
        std::vector<float> d(std::size_t(w * h), 200.0f);
        for (int y = h / 2 - 4; y <= h / 2 + 4; ++y)
            for (int x = w / 2 - 4; x <= w / 2 + 4; ++x) d[std::size_t(y * w + x)] = centre_m;
        return depthFromDistances(d);
    };
    const std::vector<float> image = uniform(w, h, 0.5f);
    const auto frame = [&](Bench& bench, const std::vector<float>& depth, double t) {
        bench.sky = s.sky;
        runWithDepth(bench, image, depth, w, h, t, [&](FrameGraph& g, const RenderContext& rc, TextureHandle in, TextureHandle dh) {
            return bench.chain.addPasses(g, rc, in, s, dh);
        });
        REQUIRE(bench.chain.dof());
        return bench.chain.dof()->read();
    };
    Bench fine, coarse;
    postfx::DofFocusState st = frame(fine, scene(2.0f), 0.0);
    CHECK(st.diopters == doctest::Approx(0.5f).epsilon(1e-4));  // the first frame takes it at once
    CHECK(postfxPasses(fine.executed) ==
          std::vector<std::string>{"postfx.dof.focus", "postfx.dof.coc", "postfx.dof.tiles", "postfx.dof.dilate",
                                   "postfx.dof.gather", "postfx.encode"});
    frame(coarse, scene(2.0f), 0.0);
    // Focus pulls from 2 m to 20 m: 0.5 -> 0.05 diopters, in 30 frames of 1/30 s.
    const std::vector<float> far = scene(20.0f);
    const double dt = 1.0 / 30.0;
    float previous = st.diopters;
    for (int i = 1; i <= 30; ++i) {
        st = frame(fine, far, i * dt);
        const float gap = previous - 0.05f;
        const float step = previous - st.diopters;
        CHECK(step > 0.0f);                                         // moves towards the target, never past it
        CHECK(step <= gap * s.dof.autofocus_rate * dt * 1.0001 + 1e-6);  // no step larger than rate * dt allows
        CHECK(st.target == doctest::Approx(0.05f).epsilon(1e-4));
        previous = st.diopters;
    }
    // After 1 s the gap has fallen by e^-2, whatever the frame rate.
    CHECK(st.diopters - 0.05f == doctest::Approx(0.45 * std::exp(-2.0)).epsilon(1e-3));
    const postfx::DofFocusState one = frame(coarse, far, 1.0);
    CHECK(one.diopters == doctest::Approx(st.diopters).epsilon(1e-4));
    for (int i = 31; i <= 150; ++i) st = frame(fine, far, i * dt);
    CHECK(st.diopters == doctest::Approx(0.05f).epsilon(1e-3));  // converged after 5 s

    // One odd sample of the five (a NaN, or a near object at a side sample) does not move it.
    std::vector<float> odd = far;
    odd[std::size_t((h / 2) * w + w / 2)] = std::numeric_limits<float>::quiet_NaN();
    CHECK(frame(fine, odd, 6.0).target == doctest::Approx(0.05f).epsilon(1e-4));
    s.dof.enabled = false;
    Bench off;
    off.chainRun(image, w, h, s);
    CHECK(off.chain.dof() == nullptr);
    CHECK_FALSE(has(off.executed, "postfx.dof"));
}

TEST_CASE("gl: depth of field: sharp where in focus, the foreground bleeds over a sharp background, the background does not, NaN stays local") {
    test::glContext();
    const int w = 96, h = 48;
    Settings s = dofOnly();
    s.dof.autofocus = false;
    s.dof.focus_distance_m = 10.0f;
    s.dof.f_stop = 1.4f;
    s.dof.focal_length_mm = 300.0f;  // the sky's radius: 6.6 px
    s.dof.max_coc_px = 8.0f;
    s.postfx.order = {PostEffect::Dof};
    std::vector<float> image(std::size_t(w * h * 4), 1.0f);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) setPixel(image, w, x, y, float((x * 7 + y * 3) % 11) / 10.0f);  // texture
    const auto run = [&](const std::vector<float>& rgba, const std::vector<float>& distances) {
        Bench bench;
        bench.sky = s.sky;
        return runWithDepth(bench, rgba, depthFromDistances(distances), w, h, 0.0,
            [&](FrameGraph& g, const RenderContext& rc, TextureHandle in, TextureHandle dh) {
                s.postfx.order = {PostEffect::Dof};
                return bench.chain.addPasses(g, rc, in, s, dh);
            });
    };
    std::vector<float> focused(std::size_t(w * h), 10.0f);
    std::vector<float> out = run(image, focused);
    // In focus: the encode of the input (same texture, sRGB), nothing moved.
    Bench plain;
    Settings none;
    none.postfx.order.clear();
    const std::vector<float> reference = plain.chainRun(image, w, h, none);
    float largest = 0.0f;
    for (std::size_t i = 0; i < out.size(); ++i) largest = std::max(largest, std::abs(out[i] - reference[i]));
    CHECK(largest <= 1.0f / 255.0f);

    // Left half near (0.5 m, white), right half in focus (black): the white bleeds into the black.
    std::vector<float> split(image.size(), 0.0f), distances(std::size_t(w * h));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            setPixel(split, w, x, y, x < w / 2 ? 1.0f : 0.0f);
            split[(std::size_t(y * w + x)) * 4 + 3] = 1.0f;
            distances[std::size_t(y * w + x)] = x < w / 2 ? 0.5f : 10.0f;
        }
    out = run(split, distances);
    REQUIRE(allFinite(out));
    CHECK(pixel(out, w, w / 2 + 1, h / 2) > 0.2f);   // the blurred foreground edge covers the background
    CHECK(pixel(out, w, w / 2 + 4, h / 2) > 0.0f);
    CHECK(pixel(out, w, w / 2 + 10, h / 2) == 0.0f);  // beyond max_coc_px: untouched
    CHECK(pixel(out, w, w / 2 - 1, h / 2) < 1.0f);    // and the foreground's own edge softens

    // Left half in focus (black), right half far (1 km, white): the blurred background stays
    // behind the sharp object.
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            setPixel(split, w, x, y, x < w / 2 ? 0.0f : 1.0f);
            distances[std::size_t(y * w + x)] = x < w / 2 ? 10.0f : 1000.0f;
        }
    out = run(split, distances);
    for (int x = 0; x < w / 2; ++x) CHECK(pixel(out, w, x, h / 2) == 0.0f);
    CHECK(pixel(out, w, w / 2, h / 2) > 0.9f);

    // Everything blurred (the sky at infinity), one NaN, one Inf and one 1e30 pixel: finite,
    // and nothing changes beyond max_coc_px + 1 of them.
    std::vector<float> sky(std::size_t(w * h), INFINITY);
    const std::vector<float> clean = run(image, sky);
    std::vector<float> dirty = image;
    setPixel(dirty, w, 20, 20, std::numeric_limits<float>::quiet_NaN());
    setPixel(dirty, w, 50, 20, std::numeric_limits<float>::infinity());
    setPixel(dirty, w, 80, 30, 1e30f);
    out = run(dirty, sky);
    REQUIRE(allFinite(out));
    int changed_far = 0, changed_near = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const float d = std::min({std::hypot(float(x - 20), float(y - 20)), std::hypot(float(x - 50), float(y - 20)),
                                      std::hypot(float(x - 80), float(y - 30))});
            const bool differs = std::abs(pixel(out, w, x, y) - pixel(clean, w, x, y)) > 0.0f;
            if (d > s.dof.max_coc_px + 1.5f) changed_far += differs;
            else changed_near += differs;
        }
    CHECK(changed_far == 0);
    CHECK(changed_near > 0);
}

TEST_CASE("gl: motion blur reprojection: camera-relative in double, exact far from the origin") {
    ViewParams a{{1.0e7, 50.0, -3.0e6}, 30.0, -5.0, 60.0, 0.1, 64, 36};
    ViewParams b = a;
    b.position.x += 0.25;  // a quarter metre, 10,000 km from the origin
    const glm::dmat4 m = reprojectionMatrix(a, b);
    // A point 10 m ahead of b on its axis: in a's clip space it sits 0.25 m to the left.
    const ViewMatrices vb = viewMatrices(b);
    const glm::dvec3 p = 10.0 * vb.forward;  // camera-relative to b
    const glm::dvec4 clip_b = glm::dmat4(vb.view_proj) * glm::dvec4(p, 1.0);
    const glm::dvec4 ndc_b = clip_b / clip_b.w;
    const glm::dvec4 prev = m * glm::dvec4(ndc_b.x, ndc_b.y, ndc_b.z, 1.0);
    const glm::dvec4 expect = glm::dmat4(viewMatrices(a).view_proj) * glm::dvec4(p + glm::dvec3(0.25, 0.0, 0.0), 1.0);
    CHECK(prev.x / prev.w == doctest::Approx(expect.x / expect.w).epsilon(1e-5));
    CHECK(prev.y / prev.w == doctest::Approx(expect.y / expect.w).epsilon(1e-5));
    CHECK(std::abs(prev.x / prev.w - ndc_b.x) > 0.01);  // it did move
    const glm::dmat4 still = reprojectionMatrix(a, a);
    const glm::dvec4 same = still * glm::dvec4(0.3, -0.2, 0.01, 1.0);
    CHECK(same.x / same.w == doctest::Approx(0.3).epsilon(1e-6));
    CHECK(same.y / same.w == doctest::Approx(-0.2).epsilon(1e-6));
}

TEST_CASE("gl: motion blur: a still camera leaves the image, a moving one blurs along the motion, a NaN stays local") {
    test::glContext();
    const int w = 96, h = 48;
    Settings s;
    s.postfx.order = {PostEffect::MotionBlur};
    s.motion_blur.enabled = true;
    s.motion_blur.max_blur_px = 16.0f;
    const std::vector<float> plane(std::size_t(w * h), 0.1f / 20.0f);  // a wall 20 m ahead
    std::vector<float> image = uniform(w, h, 0.0f);
    setPixel(image, w, 48, 24, 1.0f);
    const auto frames = [&](const std::vector<float>& rgba, double dx_m, double dt) {
        Bench bench;
        bench.camera = ViewParams{{1.0e6, 10.0, 0.0}, 0.0, 0.0, 60.0, 0.1, w, h};
        bench.sky = s.sky;
        const auto add = [&](FrameGraph& g, const RenderContext& rc, TextureHandle in, TextureHandle d) {
            return bench.chain.addPasses(g, rc, in, s, d);
        };
        runWithDepth(bench, rgba, plane, w, h, 0.0, add);
        CHECK_FALSE(has(bench.executed, "postfx.motion_blur"));  // no previous frame
        bench.camera.position.x += dx_m;
        std::vector<float> out = runWithDepth(bench, rgba, plane, w, h, dt, add);
        return std::make_pair(out, postfxPasses(bench.executed));
    };
    Bench plain;
    Settings none;
    none.postfx.order.clear();
    const std::vector<float> reference = plain.chainRun(image, w, h, none);

    auto [still, still_passes] = frames(image, 0.0, 1.0 / 30.0);
    CHECK(still_passes == std::vector<std::string>{"postfx.encode"});  // nothing moved: no pass
    CHECK(still == reference);

    // 8 m to the right in 1/30 s: a point 20 m ahead moves 8 / 20 * 24 / tan(30 deg) = 16.6 px;
    // at 180 deg and 30 fps half a frame is exposed: an 8.3 px streak, 4.2 px each side.
    auto [moved, moved_passes] = frames(image, 8.0, 1.0 / 30.0);
    CHECK(moved_passes == std::vector<std::string>{"postfx.motion_blur.velocity", "postfx.motion_blur.tiles",
                                                   "postfx.motion_blur.neighbors", "postfx.motion_blur.gather",
                                                   "postfx.encode"});
    REQUIRE(allFinite(moved));
    CHECK(pixel(moved, w, 48, 24) < pixel(reference, w, 48, 24));  // the dot's energy spread out
    CHECK(pixel(moved, w, 51, 24) > 0.0f);                            // along x
    CHECK(pixel(moved, w, 45, 24) > 0.0f);
    CHECK(pixel(moved, w, 54, 24) == 0.0f);                           // no further than the blur
    for (int dy : {-3, -2, -1, 1, 2, 3}) CHECK(pixel(moved, w, 48, 24 + dy) == 0.0f);  // not across it

    // The same motion at twice the frame rate (half the displacement in half the time) blurs
    // as far: the blur length does not depend on the render rate.
    auto [fast, fast_passes] = frames(image, 4.0, 1.0 / 60.0);
    float largest = 0.0f;
    for (std::size_t i = 0; i < fast.size(); ++i) largest = std::max(largest, std::abs(fast[i] - moved[i]));
    CHECK(largest <= 2.0f / 255.0f);

    // NaN, Inf and 1e30 pixels: finite, nothing changes beyond the blur (4.2 px, k = 8 px) around them.
    std::vector<float> textured = uniform(w, h, 0.0f);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) setPixel(textured, w, x, y, float((x * 7 + y * 3) % 11) / 10.0f);
    const std::vector<float> clean = frames(textured, 8.0, 1.0 / 30.0).first;
    std::vector<float> dirty = textured;
    setPixel(dirty, w, 20, 20, std::numeric_limits<float>::quiet_NaN());
    setPixel(dirty, w, 50, 10, std::numeric_limits<float>::infinity());
    setPixel(dirty, w, 80, 30, 1e30f);
    const std::vector<float> out = frames(dirty, 8.0, 1.0 / 30.0).first;
    REQUIRE(allFinite(out));
    int changed_far = 0, changed_near = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const bool near = (std::abs(y - 20) <= 1 && std::abs(x - 20) <= 9) || (std::abs(y - 10) <= 1 && std::abs(x - 50) <= 9) ||
                              (std::abs(y - 30) <= 1 && std::abs(x - 80) <= 9);
            const bool differs = pixel(out, w, x, y) != pixel(clean, w, x, y);
            (near ? changed_near : changed_far) += differs;
        }
    CHECK(changed_far == 0);
    CHECK(changed_near > 0);

    s.motion_blur.enabled = false;
    auto [off, off_passes] = frames(image, 8.0, 1.0 / 30.0);
    CHECK(off_passes == std::vector<std::string>{"postfx.encode"});
}

TEST_CASE("gl: lens flare: none for a sun off screen or below the horizon, visibility is the sky share of the samples, smoothed") {
    test::glContext();
    const int w = 96, h = 64;
    Settings s;
    s.postfx.order = {PostEffect::LensFlare};
    s.lens_flare.enabled = true;
    s.lens_flare.visibility_radius_deg = 3.0f;
    s.lens_flare.intensity = 0.1f;  // 0.3 at the sun over a 0.2 image
    s.lens_flare.visibility_rate = 8.0f;
    s.sky.sun_mode = SunMode::Angles;
    s.sky.sun_azimuth_deg = 0.0f;  // north: straight ahead of a camera with yaw 0
    s.sky.sun_elevation_deg = 10.0f;
    const ViewParams camera{{0.0, 10.0, 0.0}, 5.0, 6.0, 60.0, 0.1, w, h};
    const std::optional<glm::vec2> sun = sunScreenPosition(camera, sunDirection(s.sky));
    REQUIRE(sun);
    CHECK(sun->x < 0.5f);  // the camera turned right: the sun is left of the centre, above it
    CHECK(sun->y > 0.5f);
    const int cx = int(std::floor(sun->x * w)), cy = int(std::floor(sun->y * h));
    const std::vector<float> image = uniform(w, h, 0.2f);
    Bench plain;
    Settings none;
    none.postfx.order.clear();
    const std::vector<float> reference = plain.chainRun(image, w, h, none);
    const auto depthImage = [&](auto sky) {
        std::vector<float> d(std::size_t(w * h));
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) d[std::size_t(y * w + x)] = sky(x, y) ? 0.0f : 0.01f;
        return d;
    };
    const auto frame = [&](Bench& bench, const std::vector<float>& depth, double t) {
        bench.camera = camera;
        bench.sky = s.sky;
        return runWithDepth(bench, image, depth, w, h, t, [&](FrameGraph& g, const RenderContext& rc, TextureHandle in, TextureHandle d) {
            return bench.chain.addPasses(g, rc, in, s, d);
        });
    };
    // Samples 1 px and 2.9 px each side of the sun (3 deg at 55.4 px per radian): a sky edge
    // through the sun leaves half of them in the sky, a corner a quarter.
    const std::vector<std::pair<std::vector<float>, float>> cases = {
        {depthImage([](int, int) { return true; }), 1.0f},
        {depthImage([&](int x, int) { return x < cx; }), 0.5f},
        {depthImage([&](int x, int y) { return x < cx && y < cy; }), 0.25f},
        {depthImage([](int, int) { return false; }), 0.0f},
    };
    for (const auto& [depth, share] : cases) {
        Bench bench;
        std::vector<float> out = frame(bench, depth, 0.0);
        REQUIRE(bench.chain.lensFlare());
        CHECK(postfxPasses(bench.executed) == std::vector<std::string>{"postfx.lens_flare.visibility", "postfx.lens_flare", "postfx.encode"});
        const postfx::FlareVisibility v = bench.chain.lensFlare()->read();
        CHECK(v.target == doctest::Approx(share));
        CHECK(v.visibility == doctest::Approx(share));  // the first frame takes it at once
        REQUIRE(allFinite(out));
        if (share == 0.0f) CHECK(out == reference);  // hidden: nothing added
        else CHECK(pixel(out, w, cx, cy) > pixel(reference, w, cx, cy) + 0.02f);
    }

    // The sun sinks behind a ridge: the visibility falls by exp(-rate * dt) per frame, no jump.
    Bench fading;
    frame(fading, cases[0].first, 0.0);
    float previous = 1.0f;
    for (int i = 1; i <= 10; ++i) {
        frame(fading, cases[3].first, 0.05 * i);
        const float v = fading.chain.lensFlare()->read().visibility;
        CHECK(v == doctest::Approx(previous * std::exp(-8.0f * 0.05f)).epsilon(1e-4));
        previous = v;
    }

    // Behind the camera, or below the horizon: no pass, the image unchanged.
    s.sky.sun_azimuth_deg = 180.0f;
    Bench behind;
    CHECK(frame(behind, cases[0].first, 0.0) == reference);
    CHECK_FALSE(has(behind.executed, "postfx.lens_flare"));
    s.sky.sun_azimuth_deg = 0.0f;
    s.sky.sun_elevation_deg = -2.0f;
    CHECK_FALSE(sunScreenPosition(ViewParams{{0.0, 10.0, 0.0}, 0.0, -2.0, 60.0, 0.1, w, h}, sunDirection(s.sky)));
    Bench below;
    below.camera = ViewParams{{0.0, 10.0, 0.0}, 0.0, -2.0, 60.0, 0.1, w, h};
    CHECK(frame(below, cases[0].first, 0.0) == reference);
    CHECK_FALSE(has(below.executed, "postfx.lens_flare"));
    s.lens_flare.enabled = false;
    Bench off;
    off.chainRun(image, w, h, s);
    CHECK(off.chain.lensFlare() == nullptr);
}

TEST_CASE("gl: film grain: zero-mean, strongest at mid-grey, none at black and white, the same for the same time") {
    test::glContext();
    const int w = 64, h = 32;
    std::vector<float> image = uniform(w, h, 0.5f);
    for (int y = 0; y < h; ++y) setPixel(image, w, 0, y, 0.0f), setPixel(image, w, 1, y, 1.0f);
    GradeSettings g;
    g.grain = 0.2f;
    const auto grade = [&](double t) {
        Bench bench;
        return bench.run(image, w, h, t, [&](FrameGraph& graph, const RenderContext& rc, TextureHandle in) {
            return addGradePass(graph, rc, in, g);
        });
    };
    const std::vector<float> a = grade(1.0), same = grade(1.01), later = grade(1.5);
    CHECK(a == same);  // the same pattern within 1/24 s
    CHECK(a != later);
    double sum = 0.0, largest = 0.0;
    int n = 0;
    for (int y = 0; y < h; ++y) {
        CHECK(pixel(a, w, 0, y) == 0.0f);
        CHECK(pixel(a, w, 1, y) == doctest::Approx(1.0f).epsilon(1e-6));
        for (int x = 2; x < w; ++x) {
            const double d = pixel(a, w, x, y) - 0.5;
            sum += d, largest = std::max(largest, std::abs(d)), ++n;
            CHECK(pixel(a, w, x, y, 0) == pixel(a, w, x, y, 1));  // grain in luminance, not colour
        }
    }
    CHECK(std::abs(sum / n) < 0.005);   // zero mean (uniform in +-0.1)
    CHECK(largest > 0.08);              // amplitude grain * 4 * 0.25 / 2 = 0.1 at mid-grey
    CHECK(largest <= 0.1 + 1e-6);
    CHECK(allFinite(a));
}

TEST_CASE("gl: night vision amplifies luminance into a green tint, darkens outside the scope, stays finite") {
    test::glContext();
    const int w = 64, h = 32;
    std::vector<float> image = uniform(w, h, 0.02f);
    setPixel(image, w, 28, 14, std::numeric_limits<float>::quiet_NaN());
    Settings s;
    s.postfx.order = {PostEffect::NightVision};
    s.night_vision.enabled = true;
    s.night_vision.noise = 0.0f;
    Bench bench;
    std::vector<float> out = bench.chainRun(image, w, h, s);
    CHECK(postfxPasses(bench.executed) == std::vector<std::string>{"postfx.night_vision", "postfx.encode"});
    REQUIRE(allFinite(out));
    const float centre_g = pixel(out, w, w / 2, h / 2, 1);
    CHECK(centre_g == doctest::Approx(srgb(0.02f * 6.0f)).epsilon(0.02));  // gain 6, green tint 1
    CHECK(pixel(out, w, w / 2, h / 2, 0) < centre_g);
    CHECK(pixel(out, w, w / 2, h / 2, 2) < centre_g);
    CHECK(pixel(out, w, 0, 0, 1) == 0.0f);  // outside the scope circle
    CHECK(pixel(out, w, 28, 14, 1) == 0.0f);  // NaN: black, and only there
    CHECK(pixel(out, w, 29, 14, 1) == doctest::Approx(centre_g));
    s.night_vision.noise = 0.2f;
    Bench noisy;
    out = noisy.chainRun(image, w, h, s, 2.0);
    REQUIRE(allFinite(out));
    CHECK(pixel(out, w, w / 2, h / 2, 1) != pixel(out, w, w / 2 + 1, h / 2, 1));
    s.night_vision.enabled = false;
    Bench off;
    off.chainRun(image, w, h, s);
    CHECK_FALSE(has(off.executed, "postfx.night_vision"));
}

TEST_CASE("gl: an identity 3D LUT changes nothing, an inverting one inverts") {
    test::glContext();
    const int w = 64, h = 36;
    std::vector<float> image = uniform(w, h, 0.0f);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::size_t i = (std::size_t(y) * w + std::size_t(x)) * 4;
            image[i] = float(x) / float(w - 1), image[i + 1] = float(y) / float(h - 1), image[i + 2] = 0.3f;
        }
    const auto lutOf = [](int n, bool invert) {
        CubeLut lut;
        lut.size = n;
        for (int b = 0; b < n; ++b)
            for (int g = 0; g < n; ++g)
                for (int r = 0; r < n; ++r) {
                    const glm::vec3 c = glm::vec3(r, g, b) / float(n - 1);
                    lut.table.push_back(invert ? 1.0f - c : c);
                }
        return lut;
    };
    GradeSettings g;
    const auto grade = [&](const CubeLut* cube) {
        gl::Texture texture;
        GradeLut l;
        if (cube) texture = uploadCube(*cube, "test lut"), l = {texture.id(), cube->size, cube->domain_min, cube->domain_max};
        Bench bench;
        return bench.run(image, w, h, 0.0, [&](FrameGraph& graph, const RenderContext& rc, TextureHandle in) {
            return addGradePass(graph, rc, in, g, cube ? &l : nullptr);
        });
    };
    const std::vector<float> plain = grade(nullptr);
    const CubeLut identity = lutOf(17, false), inverse = lutOf(17, true);
    std::vector<float> out = grade(&identity);
    float largest = 0.0f;
    for (std::size_t i = 0; i < out.size(); ++i) largest = std::max(largest, std::abs(out[i] - plain[i]));
    CHECK(largest < 1e-3f);  // filtering weights have 8 bits on llvmpipe
    out = grade(&inverse);
    CHECK(pixel(out, w, 10, 20, 0) == doctest::Approx(1.0f - 10.0f / 63.0f).epsilon(1e-3));
    CHECK(pixel(out, w, 10, 20, 2) == doctest::Approx(0.7f).epsilon(1e-3));
}

TEST_CASE("gl: camera exposure: a luminance of 1.2 * 2^EV100 cd/m^2 maps to 1 (sunny 16: f/16, 1/100 s, ISO 100)") {
    test::glContext();
    Bench bench;
    Settings s;
    s.postfx.order = {PostEffect::Exposure};  // then the clamp encode: the output is the exposed value, encoded
    s.exposure.mode = ExposureMode::Camera;
    s.dof.f_stop = 16.0f;               // the lens, whether or not depth of field is on
    s.motion_blur.shutter_deg = 180.0f;  // 180 deg at 50 frames a second: 1/100 s
    s.motion_blur.frame_rate = 50.0f;
    s.exposure.iso = 100.0f;
    const double ev = cameraEv100(s);
    CHECK(ev == doctest::Approx(std::log2(16.0 * 16.0 * 100.0)));
    // A value whose luminance is a tenth of the sensor's saturation comes out as 0.1.
    const double cd_per_value = luxPerHdrUnit(s.sky.sun_illuminance);
    const float value = float(0.1 * 1.2 * std::exp2(ev) / cd_per_value);
    std::vector<float> out = bench.chainRun(uniform(16, 9, value), 16, 9, s);
    CHECK(pixel(out, 16, 8, 4) == doctest::Approx(srgb(0.1f)).epsilon(0.01));
    CHECK_FALSE(has(postfxPasses(bench.executed), "postfx.exposure.histogram"));  // nothing metered
    // Two stops more light (ISO 400) double the value twice; compensation (ev) adds to it.
    s.exposure.iso = 400.0f;
    s.exposure.ev = -1.0f;
    out = bench.chainRun(uniform(16, 9, value), 16, 9, s);
    CHECK(pixel(out, 16, 8, 4) == doctest::Approx(srgb(0.2f)).epsilon(0.01));
}
