// Runs the vista executable (or any command line) as a user would, with no display, and
// collects its exit code and output: the one harness of the CLI tests (cli, bench, robust).
// VISTA_EXECUTABLE is defined for the files that include this (tests/CMakeLists.txt).
#pragma once

#include <doctest/doctest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <string>

namespace vista::test {

struct Run {
    int code = -1;
    std::string output;  // stdout and stderr
};

// Runs a shell command line without DISPLAY (so GLFW never opens a window).
inline Run shell(const std::string& line) {
    const std::string cmd = "env -u DISPLAY -u WAYLAND_DISPLAY " + line + " 2>&1";
    Run r;
    FILE* pipe = popen(cmd.c_str(), "r");
    REQUIRE(pipe);
    std::array<char, 4096> buffer;
    while (std::size_t n = std::fread(buffer.data(), 1, buffer.size(), pipe)) r.output.append(buffer.data(), n);
    const int status = pclose(pipe);
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

#ifdef VISTA_EXECUTABLE
// Runs `vista ARGS`.
inline Run runVista(const std::string& args) { return shell(std::string(VISTA_EXECUTABLE) + " " + args); }
#endif

inline bool has(const Run& r, const std::string& text) { return r.output.find(text) != std::string::npos; }

}  // namespace vista::test
