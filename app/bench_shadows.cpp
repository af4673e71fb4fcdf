// Sun shadow benchmark (see bench_shadows.h). Every figure comes from [debug] view = shadow,
// which leaves the sun's visibility (0..1) in the HDR target where lighting.sun wrote it.
#include "app/bench_shadows.h"

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

}  // namespace

int runBenchShadows(const Settings& scene, const BenchShadowsOptions& o) {
    std::string error;
    auto context = createContext(o.backend, ContextOptions{o.width, o.height, false, false, false, false, "bench"}, error);
    if (!context) {
        std::fprintf(stderr, "vista: %s\n", error.c_str());
        return 1;
    }
    FrameRenderer renderer(vistaRoot());
    Settings base = scene;
    base.debug.grid = false;
    base.debug.view = DebugView::Shadow;
    base.lights = {};
    base.ssao.enabled = false;
    base.clouds.enabled = false;  // the cascades alone (cloud shadows move with the wind)
    base.shadows.enabled = true;
    base.sky.sun_mode = SunMode::Angles;
    if (InputErrors errors = renderer.prepare(base); !errors.empty() || !renderer.terrain()) {
        std::fprintf(stderr, "vista: bench shadows needs the scene's terrain: %s\n", errors.empty() ? "[terrain] is off" : errors.front().str().c_str());
        return 2;
    }
    nlohmann::json out = {{"renderer", context->renderer()}, {"backend", backendName(o.backend)}, {"size", {o.width, o.height}}};
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
    return writeBenchJson(o.json, out.dump(2) + "\n");
}

}  // namespace vista
