// The quality report without GL: the Pareto front (hand-checked sets, ties, duplicates), the
// gap below the front, and the three outputs written from a made-up report.
#include "app/quality_report.h"

#include <doctest/doctest.h>

#include <OpenImageIO/imagebuf.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace vista;

TEST_CASE("quality: the Pareto front keeps exactly the points no other point beats in cost and error") {
    //             a    b    c    d    e    f
    const std::vector<double> cost{1.0, 2.0, 3.0, 2.5, 4.0, 1.0};
    const std::vector<double> error{5.0, 3.0, 1.0, 3.5, 1.0, 6.0};
    // b beats d (cheaper, smaller error); c beats e (same error, cheaper); a beats f (same cost, smaller error).
    CHECK(paretoFront(cost, error) == std::vector<bool>{true, true, true, false, false, false});
    // Identical points dominate neither: both stay.
    CHECK(paretoFront({1.0, 1.0}, {2.0, 2.0}) == std::vector<bool>{true, true});
    CHECK(paretoFront({}, {}).empty());
    CHECK(paretoFront({3.0}, {-INFINITY}) == std::vector<bool>{true});
}

namespace {

QualityRun run(const std::string& name, const std::string& kind, double ms, double db) {
    QualityRun r;
    r.name = name;
    r.kind = kind;
    r.gpu_ms = ms;
    r.copy_ms = 0.5;
    r.ldr.psnr_db = db;
    r.ldr.ssim = std::isinf(db) ? 1.0 : 0.9;
    r.hdr.psnr_db = db;
    r.passes = {{"terrain.gbuffer", ms / 2, 0.1, 0.0}, {"postfx.tonemap", ms / 4, 0.1, 0.0}};
    if (kind == "knob") {
        r.knob = "shadows.resolution";
        r.value = name.substr(name.find('=') + 1);
    }
    return r;
}

QualityReport sample() {
    QualityReport r;
    r.scene = "config/default.ini";
    r.path = "data/paths/default.path";
    r.renderer = "test";
    r.width = 32;
    r.height = 18;
    r.frames = 2;
    r.runs = {run("reference", "preset", 100.0, INFINITY), run("low", "preset", 10.0, 30.0),
              run("medium", "preset", 20.0, 28.0), run("high", "preset", 30.0, 40.0),
              run("ultra", "preset", 60.0, 45.0), run("shadows.resolution=512", "knob", 90.0, 50.0)};
    r.knob_order = {"shadows.resolution"};
    r.inactive_knobs = {"dof.samples"};
    return r;
}

}  // namespace

TEST_CASE("quality: runs are marked on the front, with the dB gap of those below it") {
    QualityReport r = sample();
    markParetoFront(r);
    CHECK(r.runs[0].pareto);   // the reference: infinite PSNR
    CHECK(r.runs[1].pareto);   // low: the cheapest
    CHECK_FALSE(r.runs[2].pareto);  // medium costs more than low and is worse
    CHECK(r.runs[2].front_gap_db == doctest::Approx(2.0));
    CHECK(r.runs[3].pareto);
    CHECK(r.runs[4].pareto);
    CHECK(r.runs[5].pareto);
    CHECK(r.runs[3].front_gap_db == 0.0);
}

TEST_CASE("quality: the report writes a parseable CSV, Markdown tables and a chart") {
    QualityReport r = sample();
    markParetoFront(r);
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "vista-quality-report-test";
    std::filesystem::remove_all(dir);
    REQUIRE(writeQualityReport(dir, r).empty());
    for (const char* f : {"quality.csv", "quality_passes.csv", "quality.md", "quality.png"})
        CHECK(std::filesystem::exists(dir / f));
    CHECK_FALSE(std::filesystem::exists(dir / "quality.png.part"));

    std::ifstream csv(dir / "quality.csv");
    std::string line;
    std::getline(csv, line);
    CHECK(line.rfind("name,kind,knob,value,psnr_ldr_db,ssim_ldr", 0) == 0);
    const auto columns = [](const std::string& l) { return std::count(l.begin(), l.end(), ',') + 1; };
    const auto header_columns = columns(line);
    int rows = 0;
    while (std::getline(csv, line)) {
        CHECK(columns(line) == header_columns);
        ++rows;
        if (line.rfind("reference,", 0) == 0) CHECK(line.find(",inf,") != std::string::npos);
    }
    CHECK(rows == int(r.runs.size()));

    std::stringstream md;
    md << std::ifstream(dir / "quality.md").rdbuf();
    for (const char* s : {"## Presets", "| low |", "| reference |", "### shadows.resolution", "| 512 |", "`dof.samples`",
                          "terrain.gbuffer", "quality.png"})
        CHECK(md.str().find(s) != std::string::npos);

    OIIO::ImageBuf png((dir / "quality.png").string());
    REQUIRE(png.read());
    CHECK(png.spec().width == 960);
    CHECK(png.spec().height == 600);
    // The low preset's square (blue) is drawn somewhere.
    bool blue = false;
    for (int y = 0; y < png.spec().height && !blue; ++y)
        for (int x = 0; x < png.spec().width && !blue; ++x) {
            float p[3];
            png.getpixel(x, y, p, 3);
            blue = p[2] > 0.8f && p[0] < 0.2f;
        }
    CHECK(blue);
    std::filesystem::remove_all(dir);
}
