// Sky benchmark: quality presets of the atmosphere LUTs, each measured in one run: PSNR of the
// sky against the double-precision reference for noon, sunset and twilight views (at 128x72,
// the reference costs ~0.1 ms a pixel), the GPU time of rebuilding every LUT, and the
// per-frame cost (sky pass alone, and with the sky-view LUT rebuilt as when the sun moves).
#include "app/bench_sky.h"

#include "app/frame.h"
#include "app/scene.h"
#include "app/stats.h"
#include "sky/atmosphere.h"
#include "sky/clouds/cloud_model.h"
#include "sky/sky_reference_image.h"

#include <glm/gtc/packing.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <string>

namespace vista {
namespace {

struct Preset {
    const char* name;
    int t_w, t_h, t_steps, ms_size, ms_steps, v_w, v_h, v_steps;
};

// "default" is SkySettings' defaults; the others bracket it.
constexpr Preset kPresets[] = {
    {"low", 64, 16, 12, 16, 8, 64, 36, 12},
    {"medium", 128, 32, 24, 24, 12, 128, 72, 20},
    {"default", 256, 64, 40, 32, 20, 192, 108, 32},
    {"high", 512, 128, 80, 64, 40, 384, 216, 64},
};

void apply(const Preset& p, SkySettings& s) {
    s.transmittance_width = p.t_w;
    s.transmittance_height = p.t_h;
    s.transmittance_steps = p.t_steps;
    s.multiscatter_size = p.ms_size;
    s.multiscatter_steps = p.ms_steps;
    s.sky_view_width = p.v_w;
    s.sky_view_height = p.v_h;
    s.sky_view_steps = p.v_steps;
}

struct View {
    const char* name;
    float sun_elevation;
    double altitude, yaw, pitch;
};

constexpr View kViews[] = {
    {"noon", 60.0f, 2.0, 0.0, 10.0},
    {"sunset", 2.0f, 2.0, 180.0, 5.0},
    {"twilight", -6.0f, 2.0, 180.0, 10.0},
};

}  // namespace

std::vector<std::string> benchSkyPresetNames() {
    std::vector<std::string> names;
    for (const Preset& p : kPresets) names.push_back(p.name);
    return names;
}

int runBenchSky(const BenchScene& isolated, const BenchSkyOptions& o) {
    const Settings& scene = isolated.settings;
    std::printf("%s", isolated.summary().c_str());
    std::string error;
    auto context = createContext(o.backend, ContextOptions{o.width, o.height, false, false, false, false, "bench"}, error);
    if (!context) {
        std::fprintf(stderr, "vista: %s\n", error.c_str());
        return 1;
    }
    FrameRenderer renderer(vistaRoot());
    // What this bench measures: the sky and the copy that sets the cost unit (the rest of the
    // frame compiles on first use).
    ProgramList programs = skyPrograms();
    programs.push_back({"renderer/shaders/copy.glsl", {}});
    for (const ProgramKey& key : programs)
        if (!renderer.shaders().get(key)) error += renderer.shaders().lastError();
    if (!error.empty()) {
        std::fprintf(stderr, "vista: shader compilation failed:\n%s", error.c_str());
        return 1;
    }
    Settings base = scene;
    base.terrain.enabled = false;  // the sky alone covers the frame
    base.debug.grid = false;
    base.sky.enabled = true;
    base.sky.sun_mode = SunMode::Angles;
    base.sky.sun_azimuth_deg = 180.0f;
    base.sky.moon = false;  // the reference has neither moon nor stars
    base.sky.stars = false;
    base.clouds.enabled = false;  // nor clouds

    std::fprintf(stderr, "bench sky: building the CPU reference...\n");
    const MultipleScatteringTable table(atmosphereParams(base.sky));
    const int ref_w = o.psnr_width, ref_h = o.psnr_height;
    std::vector<std::vector<glm::vec3>> references;
    for (const View& v : kViews) {
        Settings s = base;
        s.sky.sun_elevation_deg = v.sun_elevation;
        references.push_back(
            referenceSkyImage(s.sky, ViewParams{{0.0, v.altitude, 0.0}, v.yaw, v.pitch, 60.0, 0.5, ref_w, ref_h}, table));
    }

    const double copy_ms = renderer.measureReferenceCopy(o.width, o.height);
    nlohmann::json presets = nlohmann::json::array();
    std::printf("%-8s %-26s %9s %9s %9s %9s %12s %12s %12s\n", "preset", "T / MS / view (steps)", "noon_dB", "sunset_dB",
                "twil_dB", "psnr_min", "lut_build_ms", "sky_copies", "+view_copies");
    for (const Preset& preset : kPresets) {
        if (!o.presets.empty() && std::find(o.presets.begin(), o.presets.end(), preset.name) == o.presets.end()) continue;
        Settings s = base;
        apply(preset, s.sky);
        nlohmann::json psnr = nlohmann::json::object();
        double psnr_min = 1e9;
        std::vector<std::uint16_t> hdr;
        FrameRequest request;
        request.capture_hdr = &hdr;
        for (std::size_t i = 0; i < std::size(kViews); ++i) {
            const View& v = kViews[i];
            s.sky.sun_elevation_deg = v.sun_elevation;
            const FrameReport report =
                renderer.render(s, ViewParams{{0.0, v.altitude, 0.0}, v.yaw, v.pitch, 60.0, 0.5, ref_w, ref_h}, 0.0, request);
            // The target holds radiance times the frame's pre-exposure (sky/night_light.h); the
            // reference is the radiance itself.
            if (const double pre = report.counters.at("sky.pre_exposure"); pre != 1.0)
                for (std::uint16_t& h : hdr) h = std::uint16_t(glm::packHalf1x16(float(glm::unpackHalf1x16(h) / pre)));
            double db = skyPsnrDb(hdr, references[i]);
            psnr[v.name] = db;
            psnr_min = std::min(psnr_min, db);
        }
        renderer.timers().collect(true);

        // Timings at the bench size, sunset: every LUT rebuilt, then steady frames.
        s.sky.sun_elevation_deg = 2.0f;
        ViewParams view{{0.0, 2.0, 0.0}, 150.0, 10.0, 60.0, 0.5, o.width, o.height};
        // A readback roots the frame: without one the graph culls every pass and times nothing.
        std::vector<std::uint16_t> scratch;
        FrameRequest timed;
        timed.capture_hdr = &scratch;
        std::vector<double> build, view_ms, sky_ms;
        for (int r = 0; r < 4; ++r) {
            renderer.sky()->invalidate();
            renderer.render(s, view, 0.0, timed);
            FrameTiming t = renderer.timers().collect(true).back();
            if (r == 0) continue;  // first use of a program (JIT on llvmpipe)
            build.push_back(passMs(t, "sky.transmittance") + passMs(t, "sky.multiscatter") + passMs(t, "sky.view"));
            view_ms.push_back(passMs(t, "sky.view"));
        }
        for (int r = 0; r < 5; ++r) {
            renderer.render(s, view, 0.0, timed);
            sky_ms.push_back(passMs(renderer.timers().collect(true).back(), "sky.atmosphere"));
        }
        double lut_build = median(build), sky = median(sky_ms), with_view = sky + median(view_ms);
        char label[64];
        std::snprintf(label, sizeof label, "%dx%d/%d %d/%d %dx%d/%d", preset.t_w, preset.t_h, preset.t_steps,
                      preset.ms_size, preset.ms_steps, preset.v_w, preset.v_h, preset.v_steps);
        std::printf("%-8s %-26s %9.1f %9.1f %9.1f %9.1f %12.3f %12.2f %12.2f\n", preset.name, label,
                    psnr["noon"].get<double>(), psnr["sunset"].get<double>(), psnr["twilight"].get<double>(), psnr_min,
                    lut_build, copy_ms > 0 ? sky / copy_ms : 0.0, copy_ms > 0 ? with_view / copy_ms : 0.0);
        presets.push_back({
            {"name", preset.name},
            {"transmittance", {preset.t_w, preset.t_h, preset.t_steps}},
            {"multiscatter", {preset.ms_size, preset.ms_steps}},
            {"sky_view", {preset.v_w, preset.v_h, preset.v_steps}},
            {"psnr_db", psnr},
            {"psnr_db_min", psnr_min},
            {"lut_build_ms", lut_build},
            {"sky_view_ms", median(view_ms)},
            {"sky_pass_ms", sky},
            {"sky_copies", copy_ms > 0 ? sky / copy_ms : 0.0},
            {"sky_with_view_copies", copy_ms > 0 ? with_view / copy_ms : 0.0},
        });
    }
    // Clouds: the cost of clouds.shell and its error against a fine setting (lower layer 6
    // octaves, 32 steps; 8 light samples) for the lower layer's octaves and steps, looking up
    // with the sun behind the camera. The error includes the jitter's grain.
    nlohmann::json cloud_rows = nlohmann::json::array();
    Settings clouds = scene;
    clouds.terrain.enabled = false;
    clouds.debug.grid = false;
    clouds.sky.enabled = true;
    clouds.sky.sun_mode = SunMode::Angles;
    clouds.sky.sun_azimuth_deg = 180.0f;
    clouds.sky.sun_elevation_deg = 25.0f;
    clouds.clouds.enabled = true;
    if (o.clouds && cloudsActive(clouds.clouds)) {
        const ViewParams up{{0.0, 2.0, 0.0}, 0.0, 25.0, 60.0, 0.5, o.width, o.height};
        std::vector<std::uint16_t> hdr;
        FrameRequest request;
        request.capture_hdr = &hdr;
        Settings fine = clouds;
        fine.clouds.low.octaves = 6;
        fine.clouds.low.steps = 32;
        fine.clouds.light_samples = 8;
        renderer.render(fine, up, 0.0, request);
        std::vector<glm::vec3> reference(hdr.size() / 4);
        for (std::size_t i = 0; i < reference.size(); ++i)
            for (int c = 0; c < 3; ++c) reference[i][c] = glm::unpackHalf1x16(hdr[i * 4 + std::size_t(c)]);
        std::printf("%-8s %-8s %9s %12s\n", "octaves", "steps", "psnr_dB", "shell_copies");
        for (int octaves : {2, 3, 4, 6})
            for (int steps : {4, 8, 16}) {
                Settings c = clouds;
                c.clouds.low.octaves = octaves;
                c.clouds.low.steps = steps;
                std::vector<double> shell_ms;
                for (int r = 0; r < 4; ++r) {
                    renderer.render(c, up, 0.0, request);
                    const double ms = passMs(renderer.timers().collect(true).back(), "clouds.shell");
                    if (r > 0) shell_ms.push_back(ms);  // the first frame compiles (JIT on llvmpipe)
                }
                const double db = skyPsnrDb(hdr, reference), copies = copy_ms > 0 ? median(shell_ms) / copy_ms : 0.0;
                std::printf("%-8d %-8d %9.1f %12.2f\n", octaves, steps, db, copies);
                cloud_rows.push_back({{"octaves", octaves}, {"steps", steps}, {"psnr_db", db}, {"shell_copies", copies}});
            }
    }
    nlohmann::json out = {
        {"renderer", context->renderer()},
        {"backend", backendName(o.backend)},
        {"size", {o.width, o.height}},
        {"psnr_size", {ref_w, ref_h}},
        {"psnr_definition", "10 log10(1 / mean(((gpu - ref) / max(ref))^2)), linear radiance, RGB, sun disk masked"},
        {"reference_copy_ms", copy_ms},
        {"presets", presets},
        {"clouds", cloud_rows},
    };
    std::printf("reference_copy_ms %.4f\n", copy_ms);
    out["scene"] = isolated.json();
    return writeBenchJson(o.json, out.dump(2) + "\n", o.force);
}

}  // namespace vista
