// Terrain up close (docs/terrain-detail.md): the material relief heights (the detail array's
// alpha); parallax occlusion mapping: pomMarch on the GPU (tests/gl/shaders/pom_probe.glsl)
// against a dense double-precision ray march of the same relief on the CPU, for rays from
// straight down to 85 degrees that cross the texture's repeat borders; tessellation: no crack
// between patches over random views, LOD ranges and morph zones (nothing behind the terrain
// shows through), the patch counter, and no pass variant when off.
#include "app/scene.h"
#include "renderer_fixture.h"
#include "renderer/bindings.h"
#include "renderer/pass_kit.h"
#include "renderer/shader_library.h"
#include "terrain/materials.h"
#include "terrain/tess_displacement.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

using namespace vista;

namespace {

#include "shaders/pom_probe_block.glsl"

ShaderLibrary& shaders() {
    test::glContext();
    static ShaderLibrary library(vistaRoot());
    return library;
}

// The relief of one layer as the GPU samples it at mip 0 (terrain/tess_displacement.h).
struct Relief {
    const MaterialImages* m;
    int layer;
    double operator()(double u, double v) const { return reliefAt(*m, layer, u, v); }
};

// The exact first hit of the ray p0 - t * span (t = 0..1, ray height 1 - t) with the relief: a
// march in 8192 steps, then 40 bisections of the first crossing.
double referenceHit(const Relief& relief, glm::dvec2 p0, glm::dvec2 span) {
    auto d = [&](double t) { glm::dvec2 p = p0 - span * t; return relief(p.x, p.y) - (1.0 - t); };
    if (d(0.0) >= 0.0) return 0.0;
    const int steps = 8192;
    double above = 0.0;
    for (int i = 1; i <= steps; ++i) {
        double t = double(i) / steps;
        if (d(t) >= 0.0) {
            double below = t;
            for (int k = 0; k < 40; ++k) {
                double mid = 0.5 * (above + below);
                (d(mid) >= 0.0 ? below : above) = mid;
            }
            return below;
        }
        above = t;
    }
    return 1.0;
}

struct HitErrors {
    double median = 0.0, p95 = 0.0, max = 0.0;  // hit point error, texels
    double mean_shift = 0.0;                    // mean distance of the reference hit from the start, texels
};

// reference: the CPU hits per probe pixel, filled on the first call for a layer (the dense
// march is most of the test's time).
HitErrors pomErrors(const MaterialImages& m, GLuint texture, int layer, int max_steps, int refine,
                    std::vector<glm::dvec2>& reference) {
    const int w = 64, h = 48;
    const float depth = 0.02f;  // texture units: 5 texels of relief at 256 texels
    gl::Buffer block;  // bound until the probe has drawn
    const std::vector<float> texels = test::drawProbe(shaders(), "tests/gl/shaders/pom_probe.glsl", {}, w, h, [&] {
        glBindTextureUnit(binding::kTex0, texture);
        GLint program = 0;
        glGetIntegerv(GL_CURRENT_PROGRAM, &program);
        block = bindPassBlockOnce(shaders(), GLuint(program), PomProbeBlock{{layer, max_steps, refine, w}, {depth, float(h)}, {}});
    });
    const Relief relief{&m, layer};
    std::vector<double> errors;
    double shift = 0.0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            // The probe's ray, in float as it computes it.
            const float azimuth = 6.2831853f * (float(x) + 0.5f) / float(w);
            const float zenith = glm::radians(85.0f) * float(y) / float(h - 1);
            const glm::dvec3 to_eye(std::sin(zenith) * std::cos(azimuth), std::cos(zenith), std::sin(zenith) * std::sin(azimuth));
            const float fu = float(x) * 0.618034f, fv = float(y) * 0.754878f + float(x) * 0.1f;
            const glm::dvec2 p0(double(fu - std::floor(fu)) * 2.0 - 0.5, double(fv - std::floor(fv)) * 2.0 - 0.5);
            const glm::dvec2 span = glm::dvec2(to_eye.x, to_eye.z) * (double(depth) / std::max(to_eye.y, 0.05));
            const std::size_t k = std::size_t(y) * w + std::size_t(x);
            if (reference.size() <= k) reference.push_back(p0 - span * referenceHit(relief, p0, span));
            const glm::dvec2 hit = reference[k];
            const float* px = &texels[(std::size_t(y) * w + std::size_t(x)) * 4];
            errors.push_back(glm::length(glm::dvec2(px[0], px[1]) - hit) * m.size);
            shift += glm::length(hit - p0) * m.size;
        }
    std::sort(errors.begin(), errors.end());
    HitErrors e;
    e.median = errors[errors.size() / 2];
    e.p95 = errors[errors.size() * 95 / 100];
    e.max = errors.back();
    e.mean_shift = shift / double(errors.size());
    return e;
}

}  // namespace

TEST_CASE("terrain detail: every generated layer has a relief height in the detail array's alpha") {
    const MaterialImages m = generateMaterialImages(64);
    for (int layer = 0; layer < m.layers; ++layer) {
        float lo = 1.0f, hi = 0.0f;
        for (int y = 0; y < m.size; ++y)
            for (int x = 0; x < m.size; ++x) {
                lo = std::min(lo, materialHeight(m, layer, x, y));
                hi = std::max(hi, materialHeight(m, layer, x, y));
            }
        CAPTURE(layer);
        CHECK(lo == 0.0f);  // stretched over the whole 8-bit range
        CHECK(hi == 1.0f);
    }
}

TEST_CASE("gl: parallax occlusion mapping's hit matches a dense CPU ray march of the same relief") {
    test::glContext();
    const MaterialImages m = generateMaterialImages(256);
    GLuint id = 0;
    glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &id);
    glTextureStorage3D(id, 1, GL_RGBA8, m.size, m.size, m.layers);
    glTextureSubImage3D(id, 0, 0, 0, 0, m.size, m.size, m.layers, GL_RGBA, GL_UNSIGNED_BYTE, m.normal.data());
    glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(id, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTextureParameteri(id, GL_TEXTURE_WRAP_T, GL_REPEAT);
    gl::Texture texture = gl::Texture::adopt(id, m.size, m.size, GL_RGBA8);
    for (int layer : {int(MaterialLayer::Rock), int(MaterialLayer::Grass)}) {
        std::vector<glm::dvec2> reference;
        const HitErrors coarse = pomErrors(m, texture.id(), layer, 32, 5, reference);
        const HitErrors fine = pomErrors(m, texture.id(), layer, 256, 8, reference);
        std::printf("POM layer %d: hit error (texels) 32+5 steps median %.3f p95 %.3f max %.2f; 256+8 steps median %.3f p95 %.3f "
                    "max %.2f; mean shift %.2f\n",
                    layer, coarse.median, coarse.p95, coarse.max, fine.median, fine.p95, fine.max, coarse.mean_shift);
        CAPTURE(layer);
        CHECK(coarse.mean_shift > 2.0);  // the rays do move: an offset of 0 would fail the bounds below
        // Measured: median 0.003, p95 0.03 texels at both step counts; the largest errors are thin
        // crests the linear search steps over (up to 18 texels at 32 steps, 4 at 256).
        CHECK(coarse.median < 0.05);
        CHECK(coarse.p95 < 0.25);
        CHECK(fine.median < 0.05);
        CHECK(fine.p95 < 0.25);
        CHECK(fine.max < 8.0);
    }
}

namespace {

FrameRenderer& renderer() { return test::fileRenderer(); }

// Hills, so that CDLOD picks several levels and morphs around a low camera.
void useHills(const Settings& s) {
    static bool adopted = false;
    if (adopted) return;
    test::adoptTerrain(renderer(), s.terrain, 257, [](int x, int z) {
        return 0.4f + 0.2f * std::sin(float(x) * 0.07f) * std::cos(float(z) * 0.05f) + 0.05f * std::sin(float(x + 2 * z) * 0.3f);
    });
    adopted = true;
}

// The terrain alone, unlit (the normals view: every drawn pixel has alpha 1, the background 0),
// with tessellation on and exaggerated (deep relief, fine factors) so any crack would be wide.
Settings crackScene() {
    Settings s;
    s.terrain.size_m = 1024.0f;
    s.terrain.height_scale_m = 120.0f;
    s.terrain.view = TerrainView::Normals;
    s.terrain.tessellation.enabled = true;
    s.terrain.tessellation.range_m = 120.0f;
    s.terrain.tessellation.edge_px = 2.0f;
    s.terrain.tessellation.max_factor = 32.0f;
    s.terrain.tessellation.depth_m = 1.0f;
    test::terrainOnly(s);
    s.sky.enabled = false;
    s.shadows.enabled = false;
    return s;
}

}  // namespace

TEST_CASE("gl: tessellated terrain has no cracks over random views, LOD ranges and morph factors") {
    std::mt19937 rng(27);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int patches = 0, views = 0;
    for (int k = 0; k < 10; ++k) {
        Settings s = crackScene();
        // Small ranges put level changes and morph zones near the camera, inside the tessellated range.
        s.terrain.lod_metric = LodMetric::Distance;
        s.terrain.base_range_m = float(8.0 + 40.0 * unit(rng));
        s.terrain.morph_start = float(0.2 + 0.6 * unit(rng));
        useHills(s);
        const double x = -200.0 + 400.0 * unit(rng), z = -200.0 + 400.0 * unit(rng);
        const double ground = renderer().terrain()->heightAt(x, z);
        // Pitched down by more than half the field of view: every pixel is below the horizon.
        const ViewParams view{{x, ground + 2.0 + 30.0 * unit(rng), z}, 360.0 * unit(rng), -36.0 - 40.0 * unit(rng), 60.0, 0.1, 96, 54};
        renderer().resetHistory();
        test::RenderedFrame f = test::renderFrame(renderer(), s, view);
        int holes = 0;
        for (std::size_t i = 3; i < f.rgba.size(); i += 4) holes += f.rgba[i] == 0.0f;
        CAPTURE(k);
        CHECK(holes == 0);
        patches += int(f.report.counters["terrain.tess_patches"]);
        views += f.report.counters["terrain.tess_patches"] > 0 ? 1 : 0;
    }
    CHECK(views >= 8);  // the test looked at tessellated terrain
    std::printf("crack test: %d of 10 views tessellated, %d patches\n", views, patches);
}

TEST_CASE("gl: tessellation off leaves no patch and no counter, on: only near quadrants are patches") {
    Settings s = crackScene();
    useHills(s);
    const ViewParams view{{0.0, renderer().terrain()->heightAt(0.0, 0.0) + 10.0, 0.0}, 0.0, -10.0, 60.0, 0.1, 96, 54};
    renderer().resetHistory();
    test::RenderedFrame on = test::renderFrame(renderer(), s, view);
    CHECK(on.report.counters["terrain.tess_patches"] > 0);
    CHECK(on.report.counters["terrain.tess_patches"] < on.report.counters["terrain.triangles"]);
    s.terrain.tessellation.enabled = false;
    test::RenderedFrame off = test::renderFrame(renderer(), s, view);
    CHECK(off.report.counters.count("terrain.tess_patches") == 0);
}

TEST_CASE("gl: POM and tessellation off compile and bind none of their programs and hold no memory, on adds exactly theirs") {
    // A renderer of its own: its shader library compiles a program on first use, so the programs
    // it holds after a frame are the ones that frame bound.
    test::glContext();
    FrameRenderer fresh(vistaRoot());
    Settings s;
    s.terrain.size_m = 1024.0f;
    s.terrain.height_scale_m = 120.0f;
    test::terrainOnly(s);  // the sky and the sun cascades stay: their tessellated casters count too
    test::adoptTerrain(fresh, s.terrain, 257, [](int x, int z) {
        return 0.4f + 0.2f * std::sin(float(x) * 0.07f) * std::cos(float(z) * 0.05f);
    });
    // Eye height: near-tier quadrants inside the tessellated range and beyond it (where POM runs).
    const ViewParams view{{0.0, fresh.terrain()->heightAt(0.0, 0.0) + 2.0, 0.0}, 0.0, -10.0, 60.0, 0.1, 96, 54};
    auto frame = [&](const Settings& t) {
        fresh.resetHistory();
        return test::renderFrame(fresh, t, view);
    };
    // How many of the programs used so far are POM variants and tessellated programs.
    auto relief = [&fresh] {
        std::pair<int, int> pom_tess{0, 0};
        for (const std::string& name : fresh.shaders().names()) {
            INFO(name);
            pom_tess.first += name.find("TERRAIN_POM") != std::string::npos;
            pom_tess.second += name.find("terrain_tess.glsl") != std::string::npos;
        }
        return pom_tess;
    };
    const test::RenderedFrame off = frame(s);
    const std::size_t programs_off = fresh.shaders().size();
    CHECK(relief() == std::pair<int, int>{0, 0});
    frame(s);
    CHECK(fresh.shaders().size() == programs_off);  // nothing new on a second frame
    CHECK(off.report.counters.count("terrain.tess_patches") == 0);
    CHECK(off.report.counters.count("terrain.tess_shadow_patches") == 0);

    Settings on = s;
    on.terrain.pom.enabled = true;
    on.terrain.tessellation.enabled = true;
    test::RenderedFrame with = frame(on);
    CHECK(with.report.counters["terrain.tess_patches"] > 0);
    CHECK(with.report.counters["terrain.tess_shadow_patches"] > 0);
    CHECK(with.report.counters["terrain.tier_near"] > 0);
    // The near tier's POM variant, the tessellated G-buffer program and the tessellated shadow
    // program: none of them was compiled (or bound) with both off.
    CHECK(fresh.shaders().size() == programs_off + 3);
    CHECK(relief() == std::pair<int, int>{1, 2});
    // Neither holds memory of its own: the relief is the detail array's alpha, the patches are the
    // grid's own vertices and instances.
    CHECK(with.report.counters["terrain.memory_bytes"] == off.report.counters.at("terrain.memory_bytes"));
}
