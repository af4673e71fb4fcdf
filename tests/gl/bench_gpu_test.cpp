// `make bench-gpu`'s script run as on a GPU machine, but small and on llvmpipe (EGL
// surfaceless), so the one-command GPU suite keeps working while no GPU is at hand.
#include "app/scene.h"
#include "gl_fixture.h"

#include <nlohmann/json.hpp>

#include <cstdlib>
#include <fstream>
#include <string>
#include <sys/wait.h>

TEST_CASE("gl: make bench-gpu's script runs every bench under EGL and writes one report") {
    vista::test::TempDir dir("bench-gpu");
    const std::string cmd = "env -u DISPLAY -u WAYLAND_DISPLAY python3 " + (vista::vistaRoot() / "tools/bench_gpu.py").string() +
                            " --quick --size 48x27 --backend egl --vista " + VISTA_EXECUTABLE + " --out " +
                            dir.path.string() + " > " + (dir.path / "log.txt").string() + " 2>&1";
    const int status = std::system(cmd.c_str());
    std::ifstream log(dir.path / "log.txt");
    const std::string output((std::istreambuf_iterator<char>(log)), std::istreambuf_iterator<char>());
    CAPTURE(output);
    REQUIRE(WIFEXITED(status));
    CHECK(WEXITSTATUS(status) == 0);
    REQUIRE(std::filesystem::exists(dir.path / "report.json"));
    REQUIRE(std::filesystem::exists(dir.path / "report.md"));
    nlohmann::json report = nlohmann::json::parse(std::ifstream(dir.path / "report.json"));
    CHECK(report["backend"] == "egl");
    for (const char* bench : {"frame", "terrain", "lights", "sky", "shadows", "grass"}) {
        CAPTURE(bench);
        REQUIRE(report["benches"].contains(bench));
        CHECK(report["benches"][bench]["exit_code"] == 0);
        CHECK(report["benches"][bench]["result"]["backend"] == "egl");
        CHECK_FALSE(report["benches"][bench]["headline"].get<std::string>().empty());
    }
    CHECK(std::filesystem::exists(dir.path / "lights_classes.png"));
}
