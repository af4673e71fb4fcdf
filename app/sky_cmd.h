// `vista sky`: the sky's radiance for given geometries (altitude, sun zenith, view zenith and
// azimuth from the sun) in physical units: linear sRGB scaled to cd/m^2 and luminance in
// cd/m^2, from the GPU path (the renderer's LUTs, a tiny frame per geometry) or, with
// --reference, from the spectral CPU reference (sky/atmosphere_spectral.h). The sun disk is
// never included; the sunlit ground at a ray's end only with --ground (both paths; the GPU
// path's sky pass leaves it out through [sky] planet_ground).
#pragma once

#include "app/gl_context.h"
#include "config/settings.h"
#include "sky/atmosphere_spectral.h"

#include <filesystem>
#include <string>
#include <vector>

namespace vista {

struct SkyCommandOptions {
    std::vector<SkyGeometry> geometries;  // the rows to evaluate (from the options or --in)
    std::filesystem::path out;            // empty: print the CSV to stdout
    bool reference = false;               // the spectral CPU reference instead of the GPU
    bool ground = false;                  // add the sunlit ground where a ray meets the planet
    bool force = false;                   // replace an existing --out file
    Backend backend = Backend::OSMesa;
};

// The CSV header of the input (geometries) and of the output (geometries and radiance).
inline constexpr const char* kSkyGeometryHeader = "altitude_m,sun_zenith_deg,view_zenith_deg,view_azimuth_deg";
inline constexpr const char* kSkyRadianceColumns = "r_cd_m2,g_cd_m2,b_cd_m2,luminance_cd_m2";

// "" when the geometry is valid for the atmosphere p, else what is wrong, naming the key and
// what is accepted: finite numbers; altitude above the planet's centre (a camera below the
// ground is lifted onto it) and at most kSkyMaxAltitudeM; zeniths 0..180; azimuth -360..360.
inline constexpr double kSkyMaxAltitudeM = 1.0e8;
std::string checkSkyGeometry(const SkyGeometry& g, const AtmosphereParams& p);

// Parses a geometries CSV (the header line kSkyGeometryHeader first; blank lines and lines
// starting with '#' skipped). On a malformed or invalid row: false, and error names
// file:line, the key and what is accepted.
bool parseSkyGeometries(const std::string& text, const std::string& file_name, const AtmosphereParams& p,
                        std::vector<SkyGeometry>& out, std::string& error);

// The output CSV: the header, then one row a geometry with its radiance.
std::string skyRadianceCsv(const std::vector<SkyGeometry>& geometries, const std::vector<SkyColour>& radiance);

// The command line as given: the four geometry options (all or none) or --in.
struct SkyCliArgs {
    std::string altitude_m, sun_zenith_deg, view_zenith_deg, view_azimuth_deg;  // text, checked here
    std::string in, out, backend = "osmesa";
    bool reference = false, ground = false, force = false;
};
// Checks the arguments (exit 2 naming the option or file:line and what is accepted), reads
// --in, then runSky().
int runSkyCli(const Settings& scene, const SkyCliArgs& args);

// Runs the command on the scene's [sky] (clear air: the height fog is left out); returns the
// exit code (0, 1 on a GL or file failure, 2 on bad input).
int runSky(const Settings& scene, const SkyCommandOptions& options);

}  // namespace vista
