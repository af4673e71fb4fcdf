// Each bench run as a user runs it, at test size, on the default scene (which has the sea,
// grass, clouds and lights on): its key figure is pinned, so a feature that leaks into a bench
// or a regression in what it measures fails here, not in a reader's hands months later.
#include "cli_runner.h"
#include "gl_fixture.h"

#include <nlohmann/json.hpp>

#include <array>
#include <map>
#include <cstdio>
#include <fstream>
#include <string>
#include <sstream>
#include <vector>
#include <sys/wait.h>

namespace {

struct Run : vista::test::Run {
    nlohmann::json json;
};

// Runs `vista bench ARGS --json FILE` and parses FILE.
Run bench(const std::string& args, const vista::test::TempDir& dir) {
    const std::filesystem::path file = dir.path / "bench.json";
    Run r{vista::test::runVista("bench " + args + " --json " + file.string()), {}};
    if (r.code == 0) r.json = nlohmann::json::parse(std::ifstream(file));
    return r;
}

bool contains(const nlohmann::json& list, const std::string& item) {
    for (const auto& i : list)
        if (i == item) return true;
    return false;
}

}  // namespace

TEST_CASE("gl: bench sky measures the sky alone, 55 dB or more at the default LUTs") {
    vista::test::TempDir dir("bench-sky");
    // The default scene has the sea on: it took the bench to 16.3 dB before the bench isolated its scene.
    Run r = bench("sky --size 64x36 --psnr-size 64x36 --presets default --no-clouds", dir);
    REQUIRE_MESSAGE(r.code == 0, r.output);
    CAPTURE(r.output);
    CHECK(r.output.find("scene isolated") != std::string::npos);
    CHECK(contains(r.json["scene"]["disabled"], "water.enabled=false"));
    CHECK(contains(r.json["scene"]["disabled"], "terrain.enabled=false"));
    REQUIRE(r.json["presets"].size() == 1);
    CHECK(r.json["presets"][0]["name"] == "default");
    CHECK(r.json["presets"][0]["psnr_db_min"].get<double>() >= 55.0);
}

TEST_CASE("gl: bench shadows, stabilised cascades do not shimmer and no slope shows acne") {
    vista::test::TempDir dir("bench-shadows");
    Run r = bench("shadows --size 64x36 --no-reference", dir);
    REQUIRE_MESSAGE(r.code == 0, r.output);
    CAPTURE(r.output);
    CHECK(contains(r.json["scene"]["disabled"], "water.enabled=false"));
    CHECK(contains(r.json["scene"]["disabled"], "grass.enabled=false"));
    CHECK(r.json["shimmer_fraction"]["stabilised"].get<double>() == 0.0);
    CHECK(r.json["shimmer_fraction"]["unstabilised"].get<double>() > 0.0);  // the measure sees shimmer when there is some
    CHECK(r.json["acne_fraction_max"].get<double>() == 0.0);
}

TEST_CASE("gl: bench terrain keeps the screen error within its bound, and the user's --set wins over isolation") {
    vista::test::TempDir dir("bench-terrain");
    Run r = bench("terrain --size 129 --poses 3 --frame-size 160x90 --set clouds.enabled=true", dir);
    REQUIRE_MESSAGE(r.code == 0, r.output);
    CAPTURE(r.output);
    CHECK(contains(r.json["scene"]["disabled"], "water.enabled=false"));
    CHECK_FALSE(contains(r.json["scene"]["disabled"], "clouds.enabled=false"));
    CHECK(contains(r.json["scene"]["user_overrides"], "clouds.enabled=true"));
    CHECK(r.json["triangles_median"].get<double>() > 0.0);
    CHECK(r.json["max_error_px"].get<double>() <= r.json["error_bound_px"].get<double>());
}

TEST_CASE("gl: bench grass draws blades in proportion to the density") {
    vista::test::TempDir dir("bench-grass");
    Run r = bench("grass --size 96x54 --frames 1 --densities 4,8", dir);
    REQUIRE_MESSAGE(r.code == 0, r.output);
    CAPTURE(r.output);
    CHECK(contains(r.json["scene"]["disabled"], "water.enabled=false"));
    REQUIRE(r.json["rows"].size() == 2);
    const double b4 = r.json["rows"][0]["blades"], b8 = r.json["rows"][1]["blades"];
    CHECK(b4 > 0.0);
    CHECK(b8 / b4 == doctest::Approx(2.0).epsilon(0.2));
    CHECK(b8 <= r.json["rows"][1]["considered"].get<double>());
}

TEST_CASE("gl: bench objects places the trees asked for, draws some (the far ones as impostors), keeps 32 bytes + 5 slots an instance") {
    vista::test::TempDir dir("bench-objects");
    Run r = bench("objects --size 96x54 --frames 1 --trees 1000,10000", dir);
    REQUIRE_MESSAGE(r.code == 0, r.output);
    CAPTURE(r.output);
    CHECK(contains(r.json["scene"]["disabled"], "grass.enabled=false"));
    REQUIRE(r.json["rows"].size() == 2);
    for (const auto& row : r.json["rows"]) {
        const double trees = row["trees"], placed = row["placed"], drawn = row["drawn"];
        CHECK(placed == doctest::Approx(trees).epsilon(0.05));  // density x area, every ground accepted
        CHECK(drawn > 0.0);
        CHECK(drawn < placed);  // culled on the GPU
        CHECK(row["triangles"].get<double>() > drawn);
        CHECK(row["impostors"].get<double>() > 0.0);  // the meadow view reaches past impostor_distance_m
        CHECK(row["impostors"].get<double>() <= drawn);
        CHECK(row["instance_bytes"].get<double>() == placed * 52.0);
    }
    // 100,000 trees would hold 5.2 MB of instances and lists, inside the 16 MB.
    CHECK(100000.0 * 52.0 <= 16.0e6);
}

TEST_CASE("gl: bench lights, every culling method shades every pair that needs it, and culls") {
    vista::test::TempDir dir("bench-lights");
    Run r = bench("lights --size 64x36 --frames 1 --lights 64", dir);
    REQUIRE_MESSAGE(r.code == 0, r.output);
    CAPTURE(r.output);
    std::map<std::string, nlohmann::json> rows;
    for (const auto& row : r.json["rows"]) rows[row["method"]] = row;
    REQUIRE(rows.size() == 4);
    const double exact = rows["naive"]["exact"];
    CHECK(exact > 0.0);
    for (const auto& [method, row] : rows) {
        CAPTURE(method);
        CHECK(row["exact"].get<double>() == exact);  // no method loses a light that reaches a pixel
        CHECK(row["evaluations"].get<double>() >= exact);
        CHECK(row["overflow"].get<double>() == 0.0);
    }
    CHECK(rows["tiled"]["evaluations"].get<double>() < rows["naive"]["evaluations"].get<double>());
    CHECK(rows["clustered"]["evaluations"].get<double>() < rows["tiled"]["evaluations"].get<double>());
}

TEST_CASE("gl: bench frame records the measured frames only and prints the total in copies") {
    vista::test::TempDir dir("bench-frame");
    Run r = bench("frame --size 64x36 --frames 2 --warmup 3", dir);
    REQUIRE_MESSAGE(r.code == 0, r.output);
    CAPTURE(r.output);
    CHECK(r.output.find("frame total") != std::string::npos);
    CHECK(r.output.find("copies") != std::string::npos);
    REQUIRE(r.json["frames"].size() == 2);  // not 2 + the warm-up frames' late counter readbacks
    for (const auto& f : r.json["frames"]) {
        CHECK(f["cpu_ms"].get<double>() > 0.0);
        CHECK_FALSE(f["passes"].empty());
    }
    CHECK(r.json["scene"]["file"] == "config/default.ini");
}

TEST_CASE("gl: bench lights sweeps, tiles 8 to 64 and hash nodes trade evaluations as 002 says, with charts") {
    vista::test::TempDir dir("bench-lights-sweeps");
    Run r = bench("lights --size 64x36 --frames 1 --sweep tiles,nodes,classes --sweep-lights 64 --methods tiled,clustered,hashed",
                  dir);
    REQUIRE_MESSAGE(r.code == 0, r.output);
    CAPTURE(r.output);
    std::map<std::string, std::vector<nlohmann::json>> tiles;
    std::vector<nlohmann::json> nodes;
    for (const auto& row : r.json["rows"]) {
        if (row["sweep"] == "tiles") tiles[row["method"]].push_back(row);
        if (row["sweep"] == "nodes") nodes.push_back(row);
    }
    for (const char* method : {"tiled", "clustered"}) {
        CAPTURE(method);
        REQUIRE(tiles[method].size() == 4);
        for (std::size_t i = 0; i < 4; ++i) {
            CHECK(tiles[method][i]["tile_px"] == (8 << i));
            CHECK(tiles[method][i]["exact"] == tiles[method][0]["exact"]);  // every tile size finds every pair
            if (i > 0) CHECK(tiles[method][i]["evaluations"].get<double>() >= tiles[method][i - 1]["evaluations"].get<double>());
        }
    }
    REQUIRE(nodes.size() == 4);  // 0.25 r .. 2 r: smaller nodes, fewer evaluations, more memory
    for (std::size_t i = 1; i < 4; ++i) {
        CHECK(nodes[i]["evaluations"].get<double>() >= nodes[i - 1]["evaluations"].get<double>());
        CHECK(nodes[i]["hash"]["gpu_bytes"].get<double>() <= nodes[i - 1]["hash"]["gpu_bytes"].get<double>());
    }
    REQUIRE(r.json["sweeps"]["classes"].size() == 3);
    for (const auto& c : r.json["sweeps"]["classes"]) {
        double pixels = 0.0;
        for (const char* band : {"<50m", "50-150m", "150-400m", "400-1000m", ">1000m", "sky"}) pixels += c[band]["pixels"].get<double>();
        CHECK(pixels == 64.0 * 36.0);
        CHECK(c["sky"]["evaluations"] == 0.0);
    }
    for (const char* chart : {"lights_tiles.png", "lights_nodes.png", "lights_classes.png"})
        CHECK(std::filesystem::exists(dir.path / chart));
}

TEST_CASE("gl: bench temporal reports 1-frame PSNR, flicker and frames after a cut, TAA flickering less than FXAA") {
    vista::test::TempDir dir("bench-temporal");
    const std::string map = (dir.path / "island.png").string();
    REQUIRE(vista::test::runVista("gen-heightmap --size 129 --out " + map).code == 0);
    // The low preset as the reference (FXAA, no TAA, no cloud history) keeps the run short and
    // is what the scene's TAA is measured against; objects and grass off keep the frames cheap.
    const std::filesystem::path out = dir.path / "t";
    const vista::test::Run r = vista::test::runVista(
        "bench temporal --reference-preset low --size 48x27 --frames 3 --warmup 2 --converge-frames 2 --cut-frames 3 "
        "--set grass.enabled=false --set objects.enabled=false --set terrain.heightmap=" + map + " --out " + out.string());
    REQUIRE_MESSAGE(r.code == 0, r.output);
    CHECK(r.output.find("1-frame") != std::string::npos);
    std::ifstream csv(out / "quality.csv");
    std::string line;
    REQUIRE(std::getline(csv, line));
    std::vector<std::string> header;
    std::stringstream head(line);
    for (std::string cell; std::getline(head, cell, ',');) header.push_back(cell);
    std::map<std::string, std::map<std::string, std::string>> rows;
    while (std::getline(csv, line)) {
        std::stringstream s(line);
        std::vector<std::string> cells;
        for (std::string cell; std::getline(s, cell, ',');) cells.push_back(cell);
        REQUIRE(cells.size() == header.size());
        for (std::size_t i = 0; i < cells.size(); ++i) rows[cells[0]][header[i]] = cells[i];
    }
    REQUIRE(rows.size() == 2);
    for (const char* name : {"reference", "scene"}) {
        INFO(name);
        auto& row = rows[name];
        REQUIRE(row.count("single_frame_psnr_db"));
        CHECK(std::stod(row["single_frame_psnr_db"]) > 15.0);  // a frame of the same view, not of another
        CHECK(std::stod(row["converged_psnr_db"]) > 15.0);
        const int ghost = std::stoi(row["ghost_frames"]);
        CHECK(ghost >= 0);
        CHECK(ghost < 3);
    }
    // Measured 1.4 against 3.2 levels: TAA's history steadies the image; a broken reprojection
    // (here or in TAA) raises it to FXAA's or beyond.
    const double taa = std::stod(rows["scene"]["flicker_mean"]), fxaa = std::stod(rows["reference"]["flicker_mean"]);
    CHECK(taa > 0.0);
    CHECK(taa < 0.7 * fxaa);
    CHECK(std::stod(rows["scene"]["flicker_ratio"]) == doctest::Approx(taa / fxaa).epsilon(0.01));
}
