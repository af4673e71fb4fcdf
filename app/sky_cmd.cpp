// `vista sky`. The GPU path renders, for each geometry, a 3x3 frame of the sky alone (no
// terrain, water, clouds, moon, stars or height fog) with a 0.1 deg field of view centred on
// the view direction, the sun at azimuth 0, the sun disk's radius set to 0 (the sky pass
// draws no disk then) and [sky] planet_ground set by --ground, and averages its HDR pixels
// (the dither's +-0.2 % averages out); HDR units become cd/m^2 through luxPerHdrUnit() after the frame's pre-exposure is divided out. The reference path builds the
// spectral reference once (about a minute on two cores) and integrates each row.
#include "app/sky_cmd.h"

#include "app/frame.h"
#include "app/scene.h"
#include "app/stats.h"
#include "config/file_io.h"
#include "renderer/camera.h"
#include "sky/atmosphere.h"
#include "sky/night_light.h"

#include <glm/gtc/packing.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace vista {

namespace {

// The reference's psi_ms tables: a quarter of MultipleScatteringTable's default size, which keeps
// the reference's build near a minute on two cores (the colour fit uses the same).
constexpr int kSkyReferenceMsAltitudes = 16, kSkyReferenceMsMuS = 64;

// The sky alone, as the GPU path renders it for one geometry.
Settings skyAlone(const Settings& scene, const SkyGeometry& g, bool ground) {
    Settings s = scene;
    s.terrain.enabled = false;
    s.water.enabled = false;
    s.clouds.enabled = false;
    s.debug.grid = false;
    s.taa.enabled = false;
    s.sky.enabled = true;
    s.sky.moon = false;
    s.sky.stars = false;
    s.sky.height_fog = false;
    s.sky.time_scale = 0.0f;
    s.sky.rebuild_sun_deg = 0.0f;  // the sky-view LUT for this very sun, not the nearest grid line
    s.sky.sun_mode = SunMode::Angles;
    s.sky.sun_azimuth_deg = 0.0f;
    s.sky.sun_elevation_deg = float(90.0 - g.sun_zenith_deg);
    s.sky.sun_angular_radius_deg = 0.0f;  // no disk (below the key's range on purpose: not a scene)
    s.sky.planet_ground = ground;         // the sunlit ground at a ray's end only with --ground
    return s;
}

std::string formatNumber(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", v);
    return text;
}

std::vector<SkyColour> gpuRadiance(const Settings& scene, const SkyCommandOptions& o, std::string& error) {
    std::vector<SkyColour> out;
    constexpr int kSize = 3;
    auto context = createContext(o.backend, ContextOptions{kSize, kSize, false, false, false, false, "sky"}, error);
    if (!context) return out;
    FrameRenderer renderer(vistaRoot());
    for (const ProgramKey& key : skyPrograms())
        if (!renderer.shaders().get(key)) error += renderer.shaders().lastError();
    if (!error.empty()) return out;
    std::vector<std::uint16_t> hdr;
    FrameRequest request;
    request.capture_hdr = &hdr;
    for (const SkyGeometry& g : o.geometries) {
        Settings s = skyAlone(scene, g, o.ground);
        ViewParams view{{0.0, g.altitude_m, 0.0}, g.view_azimuth_deg, 90.0 - g.view_zenith_deg, 0.1, 0.1, kSize, kSize};
        const FrameReport report = renderer.render(s, view, 0.0, request);
        const double pre = report.counters.count("sky.pre_exposure") ? report.counters.at("sky.pre_exposure") : 1.0;
        glm::dvec3 sum(0.0);
        for (int i = 0; i < kSize * kSize; ++i)
            for (int c = 0; c < 3; ++c) sum[c] += glm::unpackHalf1x16(hdr[std::size_t(i) * 4 + std::size_t(c)]);
        glm::dvec3 rgb = sum / double(kSize * kSize) / pre * luxPerHdrUnit(double(s.sky.sun_illuminance));
        out.push_back({rgb, srgbLuminance(rgb)});
    }
    return out;
}

std::vector<SkyColour> referenceRadiance(const Settings& scene, const SkyCommandOptions& o) {
    std::fprintf(stderr, "sky: building the spectral reference...\n");
    const SpectralSkyReference reference(atmosphereParams(scene.sky), 2, IntegrationSteps{}, kSkyReferenceMsAltitudes, kSkyReferenceMsMuS);
    std::vector<SkyColour> out;
    for (const SkyGeometry& g : o.geometries)
        out.push_back(reference.radiance(g.altitude_m, viewDirectionFromAngles(g.view_zenith_deg, g.view_azimuth_deg),
                                         sunDirectionFromZenith(g.sun_zenith_deg), o.ground));
    return out;
}

// A whole cell as a number; "nan" and "inf" parse (checkSkyGeometry then names them).
bool parseNumber(const std::string& text, double& v) {
    const char* begin = text.c_str();
    char* end = nullptr;
    v = std::strtod(begin, &end);
    if (end == begin) return false;
    while (*end == ' ' || *end == '\t') ++end;
    return *end == '\0';
}

}  // namespace

std::string checkSkyGeometry(const SkyGeometry& g, const AtmosphereParams& p) {
    auto range = [](const char* key, double v, double lo, double hi, const char* what) -> std::string {
        if (std::isfinite(v) && v >= lo && v <= hi) return "";
        return std::string(key) + " = " + formatNumber(v) + ": accepted " + what;
    };
    const std::string altitude_range = "a finite number of metres above the planet's centre (> " +
                                       formatNumber(-p.bottom_radius) + ") and at most " + formatNumber(kSkyMaxAltitudeM);
    if (!(std::isfinite(g.altitude_m) && g.altitude_m > -p.bottom_radius && g.altitude_m <= kSkyMaxAltitudeM))
        return "altitude_m = " + formatNumber(g.altitude_m) + ": accepted " + altitude_range;
    for (const std::string& problem :
         {range("sun_zenith_deg", g.sun_zenith_deg, 0.0, 180.0, "0..180 degrees"),
          range("view_zenith_deg", g.view_zenith_deg, 0.0, 180.0, "0..180 degrees"),
          range("view_azimuth_deg", g.view_azimuth_deg, -360.0, 360.0, "-360..360 degrees from the sun's azimuth")})
        if (!problem.empty()) return problem;
    return "";
}

bool parseSkyGeometries(const std::string& text, const std::string& file_name, const AtmosphereParams& p,
                        std::vector<SkyGeometry>& out, std::string& error) {
    static const char* kKeys[4] = {"altitude_m", "sun_zenith_deg", "view_zenith_deg", "view_azimuth_deg"};
    std::istringstream in(text);
    std::string line;
    bool header = false;
    for (int number = 1; std::getline(in, line); ++number) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        std::string where = file_name + ":" + std::to_string(number) + ": ";
        if (line.find_first_not_of(" \t") == std::string::npos || line[line.find_first_not_of(" \t")] == '#') continue;
        if (!header) {
            if (line != kSkyGeometryHeader) {
                error = where + "the first line must be the header '" + std::string(kSkyGeometryHeader) + "'";
                return false;
            }
            header = true;
            continue;
        }
        std::vector<std::string> cells;
        std::istringstream row(line);
        for (std::string cell; std::getline(row, cell, ',');) cells.push_back(cell);
        if (!line.empty() && line.back() == ',') cells.push_back("");
        if (cells.size() != 4) {
            error = where + std::to_string(cells.size()) + " columns: accepted 4 (" + kSkyGeometryHeader + ")";
            return false;
        }
        double v[4];
        for (int k = 0; k < 4; ++k)
            if (!parseNumber(cells[std::size_t(k)], v[k])) {
                error = where + kKeys[k] + ": '" + cells[std::size_t(k)] + "' is not a number";
                return false;
            }
        SkyGeometry g{v[0], v[1], v[2], v[3]};
        if (std::string problem = checkSkyGeometry(g, p); !problem.empty()) {
            error = where + problem;
            return false;
        }
        out.push_back(g);
    }
    if (!header) {
        error = file_name + ": empty: accepted a header '" + std::string(kSkyGeometryHeader) + "' and rows";
        return false;
    }
    return true;
}

std::string skyRadianceCsv(const std::vector<SkyGeometry>& geometries, const std::vector<SkyColour>& radiance) {
    std::string csv = std::string(kSkyGeometryHeader) + "," + kSkyRadianceColumns + "\n";
    for (std::size_t i = 0; i < geometries.size() && i < radiance.size(); ++i) {
        const SkyGeometry& g = geometries[i];
        const SkyColour& c = radiance[i];
        for (double v : {g.altitude_m, g.sun_zenith_deg, g.view_zenith_deg, g.view_azimuth_deg, c.rgb.x, c.rgb.y, c.rgb.z})
            csv += formatNumber(v) + ",";
        csv += formatNumber(c.luminance) + "\n";
    }
    return csv;
}

int runSky(const Settings& scene, const SkyCommandOptions& o) {
    std::string error;
    std::vector<SkyColour> radiance = o.reference ? referenceRadiance(scene, o) : gpuRadiance(scene, o, error);
    if (!error.empty() || radiance.size() != o.geometries.size()) {
        std::fprintf(stderr, "vista: sky: %s\n", error.empty() ? "the GPU returned no radiance" : error.c_str());
        return 1;
    }
    std::string csv = skyRadianceCsv(o.geometries, radiance);
    if (o.out.empty()) {
        std::fputs(csv.c_str(), stdout);
        return 0;
    }
    if (std::string problem = writeFileAtomic(o.out, csv, o.force); !problem.empty()) {
        std::fprintf(stderr, "vista: sky: %s\n", problem.c_str());
        return 1;
    }
    std::fprintf(stderr, "sky: %zu rows written to %s\n", o.geometries.size(), o.out.string().c_str());
    return 0;
}

int runSkyCli(const Settings& scene, const SkyCliArgs& a) {
    const AtmosphereParams p = atmosphereParams(scene.sky);
    SkyCommandOptions o;
    o.reference = a.reference;
    o.ground = a.ground;
    o.force = a.force;
    o.out = a.out;
    o.backend = a.backend == "egl" ? Backend::Egl : Backend::OSMesa;
    const std::string* given[4] = {&a.altitude_m, &a.sun_zenith_deg, &a.view_zenith_deg, &a.view_azimuth_deg};
    static const char* kOptions[4] = {"--altitude-m", "--sun-zenith-deg", "--view-zenith-deg", "--view-azimuth-deg"};
    int count = 0;
    for (const std::string* g : given) count += g->empty() ? 0 : 1;
    if (a.in.empty() == (count == 0) || (count != 0 && count != 4))
        return fail(2, "sky: give either all four of --altitude-m, --sun-zenith-deg, --view-zenith-deg and "
                       "--view-azimuth-deg, or --in geometries.csv");
    if (!a.out.empty())
        if (std::string problem = checkOutputFile(a.out, a.force, "--out"); !problem.empty()) return fail(2, problem);
    if (count == 4) {
        double v[4];
        for (int k = 0; k < 4; ++k)
            if (!parseNumber(*given[k], v[k])) return fail(2, std::string(kOptions[k]) + ": '" + *given[k] + "' is not a number");
        SkyGeometry g{v[0], v[1], v[2], v[3]};
        if (std::string problem = checkSkyGeometry(g, p); !problem.empty()) return fail(2, "sky: " + problem);
        o.geometries.push_back(g);
    } else {
        std::string text, error = checkInputFile(a.in, kMaxTextInputBytes);
        if (error.empty()) error = readInputFile(a.in, kMaxTextInputBytes, text);
        if (!error.empty()) return fail(2, "sky: --in: " + error);
        if (!parseSkyGeometries(text, a.in, p, o.geometries, error)) return fail(2, "sky: " + error);
    }
    return runSky(scene, o);
}

}  // namespace vista
