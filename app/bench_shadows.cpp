// Sun and spot shadow benchmark (see bench_shadows.h). Every figure comes from [debug] view = shadow,
// which leaves the sun's visibility (0..1) in the HDR target where lighting.sun wrote it.
#include "app/bench_shadows.h"

#include "app/bench_start.h"
#include "app/frame.h"
#include "app/scene.h"
#include "app/stats.h"
#include "renderer/half.h"
#include "terrain/terrain.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace vista {
namespace {

// The sun's visibility per pixel, and which pixels show terrain (HDR alpha > 0).
struct Term {
    std::vector<float> value;
    std::vector<bool> terrain;
    FrameTiming timing;
};

Term shadowTerm(FrameRenderer& r, const Settings& s, const ViewParams& view, const ViewParams* fit = nullptr) {
    std::vector<std::uint16_t> hdr;
    FrameRequest request;
    request.capture_hdr = &hdr;
    request.shadow_fit_view = fit;
    r.render(s, view, 0.0, request);
    Term t;
    t.timing = r.timers().collect(true).back();
    for (std::size_t i = 0; i < hdr.size(); i += 4) {
        t.value.push_back(halfToFloat(hdr[i]));
        t.terrain.push_back(hdr[i + 3] != 0);
    }
    return t;
}

double shadowMs(const FrameTiming& t) {
    double ms = 0.0;
    for (const auto& p : t.passes)
        if (p.name.rfind("shadows.cascade", 0) == 0 || p.name == "lighting.sun") ms += p.gpu_ms;
    return ms;
}

// Share of terrain pixels whose visibility changes by more than 0.05 between steps of the
// cascades' camera (the view stays put, so every change is the shadow map's own).
double shimmer(FrameRenderer& r, Settings s, const ViewParams& view, bool stabilize) {
    s.shadows.stabilize = stabilize;
    Term previous = shadowTerm(r, s, view, &view);
    double changed = 0.0, pixels = 0.0;
    for (int k = 1; k <= 16; ++k) {
        ViewParams fit = view;
        fit.position += glm::dvec3(0.21, 0.03, -0.13) * double(k);  // under a texel of the cascades past the first ~20 m
        fit.yaw_deg += 0.05 * k;
        fit.pitch_deg += 0.02 * k;
        Term t = shadowTerm(r, s, view, &fit);
        for (std::size_t i = 0; i < t.value.size(); ++i) {
            if (!t.terrain[i]) continue;
            pixels += 1.0;
            changed += std::abs(t.value[i] - previous.value[i]) > 0.05f;
        }
        previous = std::move(t);
    }
    return pixels > 0 ? changed / pixels : 0.0;
}

// Median GPU ms of the passes whose names start with each prefix, over `frames` frames after one warm-up.
std::vector<double> passCosts(FrameRenderer& r, const Settings& s, const ViewParams& view,
                              const std::vector<std::string>& prefixes, int frames, std::vector<std::uint16_t>* hdr = nullptr) {
    std::vector<std::uint16_t> image;
    FrameRequest request;
    request.capture_hdr = hdr ? hdr : &image;
    std::vector<std::vector<double>> ms(prefixes.size());
    for (int k = 0; k <= frames; ++k) {
        r.render(s, view, 0.0, request);
        FrameTiming t = r.timers().collect(true).back();
        if (k == 0) continue;
        for (std::size_t i = 0; i < prefixes.size(); ++i) {
            double sum = 0.0;
            for (const auto& p : t.passes)
                if (p.name.rfind(prefixes[i], 0) == 0) sum += p.gpu_ms;
            ms[i].push_back(sum);
        }
    }
    std::vector<double> out;
    for (auto& v : ms) out.push_back(median(v));
    return out;
}

// Shadowed spot lights at night: a 512 m field with a 4x4 grid of 20 m pillars, a street light
// 12 m up beside each, pointing down and away from it, so every light casts a pillar's shadow.
// Costs of the atlas pass and of lights.shade with and without spot shadows per number of
// shadowed lights, and per filter and atlas size the error of the lit image (relative RMSE of
// 3x3-box luminance) against a 8192-texel, 64-tap atlas.
nlohmann::json spotBench(FrameRenderer& r, const Settings& base, int width, int height, double copy_ms, bool reference) {
    Settings s = base;
    s.debug.view = DebugView::Final;
    s.sky.sun_elevation_deg = -20.0f;
    s.grass.enabled = false;
    s.lights.enabled = true;
    s.terrain.size_m = 512.0f;
    s.terrain.height_scale_m = 20.0f;
    s.terrain.height_offset_m = 0.0f;
    s.terrain.origin = glm::dvec3(0.0);
    const int n = 257;  // 2 m texels
    Heightmap map{n, n, std::vector<float>(std::size_t(n) * n, 0.0f)};
    for (int i = 0; i < 16; ++i) {
        const double px = -120.0 + 80.0 * (i % 4), pz = -120.0 + 80.0 * (i / 4);
        const int tx = int((px + 256.0) / 2.0), tz = int((pz + 256.0) / 2.0);
        for (int z = tz - 1; z <= tz + 1; ++z)
            for (int x = tx - 1; x <= tx + 1; ++x) map.samples[std::size_t(z * n + x)] = 1.0f;
        Light l;
        l.type = LightType::Spot;
        l.position = {px + 8.0, 12.0, pz};
        l.direction = {-0.6f, -1.0f, 0.0f};  // towards the pillar: its shadow falls across the lit ground behind it
        l.radius_m = 50.0f;
        l.intensity = 300.0f;
        l.inner_deg = 45.0f;
        l.outer_deg = 60.0f;
        s.lights.lights.push_back({"spot" + std::to_string(i), l});
    }
    InputErrors errors;
    std::unique_ptr<Terrain> field = Terrain::create(std::move(map), s.terrain, r.shaders(), errors);
    std::unique_ptr<Terrain> island = r.releaseTerrain();
    r.adoptTerrain(std::move(field));
    const ViewParams view{{0.0, 260.0, 260.0}, 0.0, -45.0, 60.0, 0.1, width, height};
    nlohmann::json out = nlohmann::json::object();
    nlohmann::json counts = nlohmann::json::array();
    std::printf("spot lights: 16 street lights beside 20 m pillars, night; cost in copies\n%-10s %12s %12s %14s\n", "shadowed", "spot_atlas",
                "lights.shade", "shade_unshadowed");
    Settings off = s;
    off.shadows.spot_enabled = false;
    const double shade_off = passCosts(r, off, view, {"lights.shade"}, 3)[0] / copy_ms;
    for (int n : {1, 4, 16}) {
        s.shadows.spot_max_lights = n;
        const auto c = passCosts(r, s, view, {"shadows.spot_atlas", "lights.shade"}, 3);
        std::printf("%-10d %12.1f %12.1f %14.1f\n", n, c[0] / copy_ms, c[1] / copy_ms, shade_off);
        counts.push_back({{"shadowed", n}, {"spot_atlas_copies", c[0] / copy_ms}, {"lights_shade_copies", c[1] / copy_ms},
                          {"lights_shade_unshadowed_copies", shade_off}});
    }
    out["cost"] = counts;
    if (!reference) {
        r.adoptTerrain(std::move(island));
        return out;
    }
    // Luminance averaged over 3x3 pixels: the kernels' per-pixel rotation is noise meant to be
    // averaged by the eye, and a 64-tap kernel 16 texels wide (the reference) is itself such
    // noise; without the box the figure would measure the noise, not the shadow.
    auto luminance = [width, height](const std::vector<std::uint16_t>& hdr) {
        std::vector<double> y, box(std::size_t(width) * std::size_t(height), 0.0);
        for (std::size_t i = 0; i < hdr.size(); i += 4)
            y.push_back(0.2126 * halfToFloat(hdr[i]) + 0.7152 * halfToFloat(hdr[i + 1]) + 0.0722 * halfToFloat(hdr[i + 2]));
        for (int py = 0; py < height; ++py)
            for (int px = 0; px < width; ++px) {
                double sum = 0.0;
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx)
                        sum += y[std::size_t(std::clamp(py + dy, 0, height - 1)) * std::size_t(width) +
                                 std::size_t(std::clamp(px + dx, 0, width - 1))];
                box[std::size_t(py) * std::size_t(width) + std::size_t(px)] = sum / 9.0;
            }
        return box;
    };
    const char* names[] = {"hard", "pcf", "pcss"};
    nlohmann::json rows = nlohmann::json::array();
    std::printf("%-6s %10s %12s %12s\n", "filter", "atlas", "rel_rmse", "atlas_copies");
    for (ShadowFilter filter : {ShadowFilter::Hard, ShadowFilter::Pcf, ShadowFilter::Pcss}) {
        auto configure = [&](Settings& c, int resolution, int taps) {  // kernels keep their size in metres
            c.shadows.spot_filter = filter;
            c.shadows.spot_atlas_resolution = resolution;
            c.shadows.spot_taps = taps;
            c.shadows.spot_filter_radius_texels = std::min(base.shadows.spot_filter_radius_texels * float(resolution) / 2048.0f, 16.0f);
            c.shadows.spot_max_penumbra_texels = std::min(base.shadows.spot_max_penumbra_texels * float(resolution) / 2048.0f, 64.0f);
        };
        Settings ref = s;
        configure(ref, 8192, 64);
        std::vector<std::uint16_t> hdr;
        passCosts(r, ref, view, {}, 1, &hdr);
        const std::vector<double> want = luminance(hdr);
        double mean = 0.0;
        for (double v : want) mean += v / double(want.size());
        for (int resolution : {1024, 2048, 4096}) {
            Settings c = s;
            configure(c, resolution, base.shadows.spot_taps);
            const double ms = passCosts(r, c, view, {"shadows.spot_atlas"}, 3, &hdr)[0];
            const std::vector<double> got = luminance(hdr);
            double sum = 0.0;
            for (std::size_t i = 0; i < got.size(); ++i) sum += (got[i] - want[i]) * (got[i] - want[i]);
            const double rel = mean > 0.0 ? std::sqrt(sum / double(got.size())) / mean : 0.0;
            std::printf("%-6s %10d %12.4f %12.1f\n", names[int(filter)], resolution, rel, ms / copy_ms);
            rows.push_back({{"filter", names[int(filter)]}, {"atlas", resolution}, {"relative_rmse", rel},
                            {"atlas_copies", ms / copy_ms}});
        }
    }
    out["error_vs_reference"] = rows;
    out["reference"] = "same filter, 8192-texel atlas, 64 taps, same kernel size in metres; error of the lit image's luminance (3x3 box) over its mean";
    r.adoptTerrain(std::move(island));
    return out;
}

}  // namespace

int runBenchShadows(const BenchScene& isolated, const BenchShadowsOptions& o) {
    const Settings& scene = isolated.settings;
    BenchRenderer bench;
    if (const int failed = startBench(isolated, o.backend, o.width, o.height, bench, /*compile_all=*/false)) return failed;
    FrameRenderer& renderer = *bench.renderer;
    const GlContext& context = *bench.context;
    Settings base = scene;
    base.debug.grid = false;
    base.debug.view = DebugView::Shadow;
    base.lights = {};
    base.ssao.enabled = false;
    base.clouds.enabled = false;  // the cascades alone (cloud shadows move with the wind)
    base.shadows.enabled = true;
    base.sky.sun_mode = SunMode::Angles;
    base.shadows.cache_frames = 1;  // every cascade drawn every frame: the figures are of drawing them
    if (InputErrors errors = renderer.prepare(base); !errors.empty() || !renderer.terrain()) {
        std::fprintf(stderr, "vista: bench shadows needs the scene's terrain: %s\n", errors.empty() ? "[terrain] is off" : errors.front().str().c_str());
        return 2;
    }
    nlohmann::json out = {{"renderer", context.renderer()}, {"backend", backendName(o.backend)}, {"size", {o.width, o.height}}};
    const double copy_ms = renderer.measureReferenceCopy(o.width, o.height);
    out["reference_copy_ms"] = copy_ms;

    // Over the default island's mountains, looking across them, sun 12 deg up: long shadows.
    const double x = 0.0, z = -900.0;
    ViewParams view{{x, std::max(renderer.terrain()->heightAt(x, z), 0.0) + 250.0, z}, 150.0, -18.0, 60.0, 0.1, o.width, o.height};
    base.sky.sun_azimuth_deg = 135.0f;
    base.sky.sun_elevation_deg = 12.0f;
    std::printf("view: camera %.1f %.1f %.1f yaw %.0f pitch %.0f, sun azimuth %.0f elevation %.0f deg, %dx%d\n", view.position.x,
                view.position.y, view.position.z, view.yaw_deg, view.pitch_deg, double(base.sky.sun_azimuth_deg),
                double(base.sky.sun_elevation_deg), o.width, o.height);

    // Shimmer: stabilised against tight unsnapped boxes.
    shadowTerm(renderer, base, view);  // programs compile, LUTs build
    const double shimmer_stable = shimmer(renderer, base, view, true);
    const double shimmer_unstable = shimmer(renderer, base, view, false);
    std::printf("shimmer_fraction  stabilised %.5f   unstabilised %.5f   (terrain pixels changing by > 0.05 per sub-texel step)\n",
                shimmer_stable, shimmer_unstable);
    out["shimmer_fraction"] = {{"stabilised", shimmer_stable}, {"unstabilised", shimmer_unstable}};

    // Acne: a flat plane (2049 texels, 4 km) under suns from 2 to 90 deg; nothing can shadow it.
    {
        Settings flat = base;
        flat.terrain.size_m = 4096.0f;
        Heightmap map{257, 257, std::vector<float>(257u * 257u, 0.5f)};
        InputErrors errors;
        std::unique_ptr<Terrain> plane = Terrain::create(std::move(map), flat.terrain, renderer.shaders(), errors);
        std::unique_ptr<Terrain> island = renderer.releaseTerrain();
        renderer.adoptTerrain(std::move(plane));
        ViewParams over{{0.0, 300.0 + 25.0, 0.0}, 20.0, -25.0, 60.0, 0.1, o.width, o.height};
        nlohmann::json acne = nlohmann::json::object();
        std::printf("acne_fraction     ");
        double worst = 0.0;
        for (float elevation : {2.0f, 5.0f, 10.0f, 20.0f, 45.0f, 70.0f, 90.0f}) {
            flat.sky.sun_elevation_deg = elevation;
            Term t = shadowTerm(renderer, flat, over);
            double wrong = 0.0, pixels = 0.0;
            for (std::size_t i = 0; i < t.value.size(); ++i)
                if (t.terrain[i]) {
                    pixels += 1.0;
                    wrong += t.value[i] < 0.9f;
                }
            double f = pixels > 0 ? wrong / pixels : 0.0;
            worst = std::max(worst, f);
            acne[std::to_string(int(elevation))] = f;
            std::printf("%g deg %.5f  ", double(elevation), f);
        }
        std::printf("\n");
        out["acne_fraction"] = acne;
        out["acne_fraction_max"] = worst;
        renderer.adoptTerrain(std::move(island));
    }

    // Error against the reference: per filter, the shadow term at 512..4096 texels against the
    // same filter at 8192 texels with 64 taps; kernels keep their world size (radius in texels
    // of cascade 0 scales with the resolution).
    if (o.reference) {
        const char* names[] = {"hard", "pcf", "pcss"};
        nlohmann::json rows = nlohmann::json::array();
        std::printf("%-6s %10s %10s %10s %12s %12s\n", "filter", "resolution", "taps", "rmse", "shadow_ms", "copies");
        for (ShadowFilter filter : {ShadowFilter::Hard, ShadowFilter::Pcf, ShadowFilter::Pcss}) {
            auto configure = [&](Settings& s, int resolution, int taps) {
                s.shadows.filter = filter;
                s.shadows.resolution = resolution;
                s.shadows.pcf_taps = taps;
                s.shadows.filter_radius_texels = std::min(base.shadows.filter_radius_texels * float(resolution) / 1024.0f, 16.0f);
                s.shadows.max_penumbra_texels = std::min(base.shadows.max_penumbra_texels * float(resolution) / 1024.0f, 64.0f);
            };
            Settings ref = base;
            configure(ref, 8192, 64);
            std::fprintf(stderr, "bench shadows: %s reference at 8192 texels...\n", names[int(filter)]);
            const Term reference = shadowTerm(renderer, ref, view);
            for (int resolution : {512, 1024, 2048, 4096}) {
                Settings s = base;
                configure(s, resolution, base.shadows.pcf_taps);
                shadowTerm(renderer, s, view);  // allocation, first use
                std::vector<double> ms;
                Term t;
                for (int k = 0; k < 3; ++k) {
                    t = shadowTerm(renderer, s, view);
                    ms.push_back(shadowMs(t.timing));
                }
                double sum = 0.0, pixels = 0.0;
                for (std::size_t i = 0; i < t.value.size(); ++i)
                    if (t.terrain[i] && reference.terrain[i]) {
                        double d = double(t.value[i]) - double(reference.value[i]);
                        sum += d * d;
                        pixels += 1.0;
                    }
                double rmse = pixels > 0 ? std::sqrt(sum / pixels) : 0.0, gpu = median(ms);
                std::printf("%-6s %10d %10d %10.4f %12.3f %12.2f\n", names[int(filter)], resolution, s.shadows.pcf_taps, rmse,
                            gpu, copy_ms > 0 ? gpu / copy_ms : 0.0);
                rows.push_back({{"filter", names[int(filter)]}, {"resolution", resolution}, {"taps", s.shadows.pcf_taps},
                                {"rmse", rmse}, {"gpu_ms", gpu}, {"copies", copy_ms > 0 ? gpu / copy_ms : 0.0}});
            }
        }
        out["error_vs_reference"] = rows;
        out["reference"] = "same filter at 8192 texels per cascade, 64 taps, same kernel world size";
    }

    out["spot"] = spotBench(renderer, base, o.width, o.height, copy_ms, o.reference);

    // Whole frames, final image, shadows on and off (the default scene's settings otherwise).
    {
        Settings s = scene;
        s.sky.sun_mode = SunMode::Angles;
        s.sky.sun_azimuth_deg = base.sky.sun_azimuth_deg;
        s.sky.sun_elevation_deg = base.sky.sun_elevation_deg;
        std::vector<std::uint16_t> hdr;
        FrameRequest request;
        request.capture_hdr = &hdr;
        nlohmann::json costs = nlohmann::json::object();
        std::printf("frame cost in copies: ");
        for (bool on : {true, false}) {
            s.shadows.enabled = on;
            std::vector<double> frame, shadow;
            for (int k = 0; k < 4; ++k) {
                renderer.render(s, view, 0.0, request);
                FrameTiming t = renderer.timers().collect(true).back();
                if (k == 0) continue;
                frame.push_back(t.gpu_ms);
                double cascades = 0.0;
                for (const auto& p : t.passes)
                    if (p.name.rfind("shadows.", 0) == 0) cascades += p.gpu_ms;
                shadow.push_back(cascades);
            }
            const char* key = on ? "shadows_on" : "shadows_off";
            double f = median(frame) / copy_ms, c = median(shadow) / copy_ms;
            costs[key] = {{"frame_copies", f}, {"cascade_passes_copies", c}};
            std::printf("%s frame %.1f (cascade passes %.1f)   ", key, f, c);
        }
        std::printf("\n");
        out["frame_cost"] = costs;
    }
    std::printf("reference_copy_ms %.4f\n", copy_ms);
    out["scene"] = isolated.json();
    return writeBenchJson(o.json, out.dump(2) + "\n", o.force);
}

}  // namespace vista
