// The vista executable as a user runs it: exit codes and messages of check and capture.
#include "app/scene.h"
#include "cli_runner.h"
#include "gl_fixture.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>
#include <sys/wait.h>

namespace {

using vista::test::Run;
Run run(const std::string& args) { return vista::test::runVista(args); }

}  // namespace

TEST_CASE("gl: vista check accepts the default scene and lists every error of a broken one") {
    CHECK(run("check").code == 0);
    vista::test::TempDir dir("cli-check");
    std::ofstream(dir.path / "broken.ini") << "[window]\nwidht = 640\nheight = 0\n[camera]\nfov_deg = wide\n";
    Run r = run("check -c " + (dir.path / "broken.ini").string());
    CAPTURE(r.output);
    CHECK(r.code == 2);
    CHECK(r.output.find("broken.ini:2:") != std::string::npos);
    CHECK(r.output.find("did you mean 'width'") != std::string::npos);
    CHECK(r.output.find("broken.ini:3:") != std::string::npos);
    CHECK(r.output.find("broken.ini:5:") != std::string::npos);
}

TEST_CASE("gl: vista check --reference prints the scene-file reference that docs/scene-file.md holds") {
    Run r = run("check --reference");
    CHECK(r.code == 0);
    std::ifstream in(vista::vistaRoot() / "docs/scene-file.md", std::ios::binary);
    std::stringstream committed;
    committed << in.rdbuf();
    CHECK(r.output == committed.str());
}

TEST_CASE("gl: bad command lines and overrides exit 2 with a message") {
    Run r = run("capture --size 12by4");
    CHECK(r.code == 2);
    CHECK(r.output.find("WxH") != std::string::npos);
    r = run("check --set camera.fov_deg=500");
    CHECK(r.code == 2);
    CHECK(r.output.find("--set") != std::string::npos);
    CHECK(run("capture --format gif").code == 2);
    CHECK(run("frobnicate").code == 2);
}

TEST_CASE("gl: vista without a display captures the default path and says so") {
    vista::test::TempDir dir("cli-nodisplay");
    Run r = run("--help");
    CHECK(r.code == 0);
    // The no-argument fallback writes to [capture] out; point it elsewhere through a scene.
    std::ofstream(dir.path / "scene.ini") << "[capture]\nframes = 1\nwidth = 32\nheight = 18\nout = " << (dir.path / "out").string() << "\n";
    r = run("run -c " + (dir.path / "scene.ini").string());
    CAPTURE(r.output);
    CHECK(r.code == 0);
    CHECK(r.output.find("no display") != std::string::npos);
    CHECK(std::filesystem::exists(dir.path / "out" / "frame_0000.png"));
}

TEST_CASE("gl: the EGL backend renders the same image as OSMesa") {
    vista::test::TempDir dir("cli-egl");
    std::string common = " capture --frames 1 --size 64x36 --stats " + (dir.path / "stats.json").string() + " --out ";
    Run osmesa = run(common.substr(1) + (dir.path / "osmesa").string() + " --backend osmesa");
    REQUIRE_MESSAGE(osmesa.code == 0, osmesa.output);
    Run egl = run(common.substr(1) + (dir.path / "egl").string() + " --backend egl --force");
    REQUIRE_MESSAGE(egl.code == 0, egl.output);
    auto read = [](const std::filesystem::path& file) {
        std::ifstream in(file, std::ios::binary);
        return std::string(std::istreambuf_iterator<char>(in), {});
    };
    std::string a = read(dir.path / "osmesa" / "frame_0000.png"), b = read(dir.path / "egl" / "frame_0000.png");
    CHECK(!a.empty());
    CHECK(a == b);  // same llvmpipe, same pixels, same encoder
    CHECK(read(dir.path / "stats.json").find("\"backend\": \"egl\"") != std::string::npos);
}

TEST_CASE("gl: vista quality writes the CSV, Markdown and chart with every preset and the chosen knobs") {
    vista::test::TempDir dir("cli-quality");
    // A small island keeps the full-resolution reference terrain cheap.
    const std::string map = (dir.path / "island.png").string();
    REQUIRE(run("gen-heightmap --size 129 --out " + map).code == 0);
    const std::filesystem::path out = dir.path / "q";
    // Two one-value knobs and one frame per run keep it short: no converged reference and no cut
    // sequence (the reference's 128 POM steps at 16x anisotropy over the whole terrain cost
    // seconds a frame on llvmpipe even at 48x27).
    Run r = run("quality --size 48x27 --frames 1 --warmup 0 --converge-frames 0 --cut-frames 0 --knobs ssao.half_resolution,clouds.half_resolution "
                "--set terrain.heightmap=" + map + " --out " + out.string());
    REQUIRE_MESSAGE(r.code == 0, r.output);
    for (const char* f : {"quality.csv", "quality_passes.csv", "quality.md", "quality.png"})
        CHECK(std::filesystem::exists(out / f));

    std::ifstream csv(out / "quality.csv");
    std::string line;
    REQUIRE(std::getline(csv, line));
    std::vector<std::string> header;
    {
        std::stringstream cells(line);
        for (std::string cell; std::getline(cells, cell, ',');) header.push_back(cell);
    }
    const auto column = [&](const char* name) { return std::size_t(std::find(header.begin(), header.end(), name) - header.begin()); };
    REQUIRE(column("psnr_ldr_db") < header.size());
    REQUIRE(column("gpu_ms_median") < header.size());
    std::map<std::string, std::vector<std::string>> rows;
    while (std::getline(csv, line)) {
        std::vector<std::string> cells;
        std::stringstream s(line);
        for (std::string cell; std::getline(s, cell, ',');) cells.push_back(cell);
        REQUIRE(cells.size() == header.size());
        rows[cells[0]] = cells;
    }
    // Five presets, SSAO and clouds at half resolution (on; the reference has them off).
    CHECK(rows.size() == 7);
    for (const char* name : {"low", "medium", "high", "ultra", "reference", "ssao.half_resolution=on", "clouds.half_resolution=on"})
        CHECK_MESSAGE(rows.count(name), name);
    CHECK(rows["reference"][column("psnr_ldr_db")] == "inf");
    CHECK(rows["reference"][column("ssim_ldr")] == "1.000000");
    for (const auto& [name, cells] : rows) {
        INFO(name);
        CHECK(std::stod(cells[column("gpu_ms_median")]) > 0.0);
        if (name != "reference") {
            const double db = cells[column("psnr_ldr_db")] == "inf" ? INFINITY : std::stod(cells[column("psnr_ldr_db")]);
            CHECK(db > 10.0);  // the same frames, only a knob apart
        }
    }
    CHECK(std::isfinite(std::stod(rows["low"][column("psnr_ldr_db")])));  // low differs from the reference

    std::stringstream md;
    md << std::ifstream(out / "quality.md").rdbuf();
    CHECK(md.str().find("## Presets") != std::string::npos);
    CHECK(md.str().find("### ssao.half_resolution") != std::string::npos);
    CHECK(run("quality --knobs bloom.levls --out " + out.string()).code == 2);
}
