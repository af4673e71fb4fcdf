// The vista executable as a user runs it: exit codes and messages of check and capture.
#include "gl_fixture.h"

#include <array>
#include <cstdio>
#include <fstream>
#include <sys/wait.h>

namespace {

struct Run {
    int code;
    std::string output;  // stdout and stderr
};

Run run(const std::string& args) {
    std::string cmd = std::string("env -u DISPLAY -u WAYLAND_DISPLAY ") + VISTA_EXECUTABLE + " " + args + " 2>&1";
    Run r{-1, {}};
    FILE* pipe = popen(cmd.c_str(), "r");
    REQUIRE(pipe);
    std::array<char, 4096> buffer;
    while (std::size_t n = std::fread(buffer.data(), 1, buffer.size(), pipe)) r.output.append(buffer.data(), n);
    int status = pclose(pipe);
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

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
