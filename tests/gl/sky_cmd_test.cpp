// `vista sky` as a user runs it: the GPU path against --reference, the units against a closed
// form (the ground's illuminance under a zenith sun: the solar spectrum times the vertical
// transmittance of exponential layers), the --out file, and exit 2 naming the bad row or key.
#include "app/sky_cmd.h"
#include "cli_runner.h"
#include "gl_fixture.h"

#include "sky/atmosphere_model.h"
#include "sky/atmosphere_spectral.h"

#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

namespace {

using vista::test::Run;
Run runSkyCmd(const std::string& args) { return vista::test::runVista("sky " + args); }

// The CSV rows of a run's output (after the header; stderr lines are not numbers).
std::vector<std::vector<double>> csvRows(const std::string& output) {
    std::vector<std::vector<double>> rows;
    std::istringstream in(output);
    bool header = false;
    for (std::string line; std::getline(in, line);) {
        if (line.rfind(vista::kSkyGeometryHeader, 0) == 0) {
            header = true;
            continue;
        }
        if (!header || line.empty() || !(std::isdigit(static_cast<unsigned char>(line[0])) || line[0] == '-')) continue;
        std::vector<double> row;
        std::istringstream cells(line);
        for (std::string cell; std::getline(cells, cell, ',');) row.push_back(std::stod(cell));
        if (row.size() == 8) rows.push_back(row);
    }
    return rows;
}

// Illuminance (lux) on the ground under a zenith sun, in closed form: per wavelength the
// vertical optical depth of exponential layers sigma H (1 - exp(-top / H)) and the ozone tent's
// peak times its half width, then 683 sum(y-bar E exp(-tau) dlambda) at the reference's
// wavelengths.
double zenithSunLux(int stride) {
    const vista::AtmosphereParams base;
    const double top = base.top_radius - base.bottom_radius;
    double lux = 0.0;
    for (int i = 0; i < vista::kSpectralTableSize; i += stride) {
        const vista::SpectralSample& s = vista::spectralTable()[std::size_t(i)];
        vista::AtmosphereParams p = vista::paramsAtWavelengths(base, glm::dvec3(s.wavelength_nm));
        double tau = p.rayleigh_scattering.x * p.rayleigh_scale_height * (1.0 - std::exp(-top / p.rayleigh_scale_height)) +
                     p.mie_extinction.x * p.mie_scale_height * (1.0 - std::exp(-top / p.mie_scale_height)) +
                     p.ozone_absorption.x * p.ozone_half_width;
        lux += vista::kLuminousEfficacy * s.cmf.y * s.solar_irradiance * std::exp(-tau) * vista::kSpectralTableStepNm * stride;
    }
    return lux;
}

}  // namespace

TEST_CASE("gl: vista sky from the GPU agrees with --reference, and the units match a closed form") {
    vista::test::TempDir dir("sky-cmd");
    std::ofstream(dir / "geometries.csv") << vista::kSkyGeometryHeader << "\n"
                                           << "# noon and a low sun, ground and 2 km, sky and sunlit ground\n"
                                           << "0,30,0,0\n0,30,60,90\n0,70,85,0\n0,70,80,180\n2000,45,30,120\n"
                                           << "1,0,180,0\n";
    const std::string in = (dir / "geometries.csv").string();
    Run gpu = runSkyCmd("--in " + in + " --ground");
    Run ref = runSkyCmd("--in " + in + " --ground --reference --out " + (dir / "ref.csv").string());
    CAPTURE(gpu.output);
    CAPTURE(ref.output);
    REQUIRE(gpu.code == 0);
    REQUIRE(ref.code == 0);
    std::ifstream file(dir / "ref.csv");
    std::stringstream ref_csv;
    ref_csv << file.rdbuf();
    std::vector<std::vector<double>> g = csvRows(gpu.output), r = csvRows(ref_csv.str());
    REQUIRE(g.size() == 6);
    REQUIRE(r.size() == 6);
    for (std::size_t i = 0; i < 5; ++i) {  // sky rays: the GPU's LUTs and colour conversion against the spectrum
        INFO("row " << i);
        CHECK(g[i][7] == doctest::Approx(r[i][7]).epsilon(0.04));
        CHECK(g[i][4] / g[i][5] == doctest::Approx(r[i][4] / r[i][5]).epsilon(0.05));
        CHECK(g[i][6] / g[i][5] == doctest::Approx(r[i][6] / r[i][5]).epsilon(0.05));
    }
    // Looking straight down from 1 m under a zenith sun: L = albedo / pi * E, so E = pi L / albedo.
    const double albedo = vista::AtmosphereParams{}.ground_albedo.y;
    const double closed_form = zenithSunLux(2);
    CHECK(closed_form > 90000.0);
    CHECK(closed_form < 120000.0);
    CHECK(std::numbers::pi * r[5][7] / albedo == doctest::Approx(closed_form).epsilon(0.01));
    CHECK(std::numbers::pi * g[5][7] / albedo == doctest::Approx(closed_form).epsilon(0.05));

    // A single geometry on the command line prints the same as its --in row.
    Run one = runSkyCmd("--altitude-m 2000 --sun-zenith-deg 45 --view-zenith-deg 30 --view-azimuth-deg 120");
    REQUIRE(one.code == 0);
    REQUIRE(csvRows(one.output).size() == 1);
    CHECK(csvRows(one.output)[0][7] == doctest::Approx(g[4][7]).epsilon(0.01));
}

TEST_CASE("gl: vista sky leaves the ground out on the GPU path as --reference does") {
    vista::test::TempDir dir("sky-cmd-no-ground");
    // Rays that end on the ground: from 100 m, 2 km and 10 km, a high and a low sun, towards and
    // away from it.
    std::ofstream(dir / "ground.csv") << vista::kSkyGeometryHeader << "\n"
                                      << "100,30,120,0\n2000,70,100,0\n2000,30,95,180\n10000,60,150,90\n";
    const std::string in = (dir / "ground.csv").string();
    Run gpu = runSkyCmd("--in " + in);
    Run with_ground = runSkyCmd("--in " + in + " --ground");
    Run ref = runSkyCmd("--in " + in + " --reference");
    CAPTURE(gpu.output);
    CAPTURE(ref.output);
    REQUIRE(gpu.code == 0);
    REQUIRE(with_ground.code == 0);
    REQUIRE(ref.code == 0);
    std::vector<std::vector<double>> g = csvRows(gpu.output), gg = csvRows(with_ground.output), r = csvRows(ref.output);
    REQUIRE(g.size() == 4);
    REQUIRE(gg.size() == 4);
    REQUIRE(r.size() == 4);
    for (std::size_t i = 0; i < g.size(); ++i) {  // the bounds of the sky rays above
        INFO("row " << i << ": GPU " << g[i][7] << " (with the ground " << gg[i][7] << "), reference " << r[i][7]);
        CHECK(g[i][7] == doctest::Approx(r[i][7]).epsilon(0.04));
        CHECK(g[i][4] / g[i][5] == doctest::Approx(r[i][4] / r[i][5]).epsilon(0.05));
        CHECK(g[i][6] / g[i][5] == doctest::Approx(r[i][6] / r[i][5]).epsilon(0.05));
        // The ground is what the option leaves out: with it these rays are far brighter.
        CHECK(gg[i][7] > 1.2 * g[i][7]);
    }
}

TEST_CASE("gl: vista sky exits 2 naming the bad row or key and what it accepts") {
    vista::test::TempDir dir("sky-cmd-errors");
    auto csv = [&](const std::string& name, const std::string& body) {
        std::ofstream(dir / name) << body;
        return (dir / name).string();
    };
    Run r = runSkyCmd("--altitude-m nan --sun-zenith-deg 30 --view-zenith-deg 0 --view-azimuth-deg 0");
    CHECK(r.code == 2);
    CHECK(vista::test::has(r, "altitude_m = nan: accepted"));
    r = runSkyCmd("--altitude-m -7000000 --sun-zenith-deg 30 --view-zenith-deg 0 --view-azimuth-deg 0");
    CHECK(r.code == 2);
    CHECK(vista::test::has(r, "above the planet's centre"));
    r = runSkyCmd("--altitude-m 0 --sun-zenith-deg 30 --view-zenith-deg 200 --view-azimuth-deg 0");
    CHECK(r.code == 2);
    CHECK(vista::test::has(r, "view_zenith_deg = 200: accepted 0..180"));
    r = runSkyCmd("--altitude-m 0 --sun-zenith-deg thirty --view-zenith-deg 0 --view-azimuth-deg 0");
    CHECK(r.code == 2);
    CHECK(vista::test::has(r, "--sun-zenith-deg: 'thirty' is not a number"));
    r = runSkyCmd("--altitude-m 0 --sun-zenith-deg 30");
    CHECK(r.code == 2);
    CHECK(vista::test::has(r, "either all four"));
    std::string header = std::string(vista::kSkyGeometryHeader) + "\n";
    r = runSkyCmd("--in " + csv("short.csv", header + "0,30,0,0\n0,30,0\n"));
    CHECK(r.code == 2);
    CHECK(vista::test::has(r, "short.csv:3: 3 columns: accepted 4"));
    r = runSkyCmd("--in " + csv("text.csv", header + "0,30,x,0\n"));
    CHECK(r.code == 2);
    CHECK(vista::test::has(r, "text.csv:2: view_zenith_deg: 'x' is not a number"));
    r = runSkyCmd("--in " + csv("range.csv", header + "\n0,181,0,0\n"));
    CHECK(r.code == 2);
    CHECK(vista::test::has(r, "range.csv:3: sun_zenith_deg = 181: accepted 0..180"));
    r = runSkyCmd("--in " + csv("noheader.csv", "0,30,0,0\n"));
    CHECK(r.code == 2);
    CHECK(vista::test::has(r, "noheader.csv:1: the first line must be the header"));
    r = runSkyCmd("--in " + (dir / "missing.csv").string());
    CHECK(r.code == 2);
    CHECK(vista::test::has(r, "missing.csv"));
    // An existing --out is kept without --force, and nothing is rendered.
    std::string out = csv("out.csv", "keep\n");
    r = runSkyCmd("--altitude-m 0 --sun-zenith-deg 30 --view-zenith-deg 0 --view-azimuth-deg 0 --out " + out);
    CHECK(r.code == 2);
    std::ifstream kept(out);
    std::string first;
    std::getline(kept, first);
    CHECK(first == "keep");
}
