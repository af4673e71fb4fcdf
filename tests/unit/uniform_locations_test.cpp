// Uniforms travel in std140 blocks declared once for C++ and GLSL (renderer/pass_kit.h,
// renderer/shaders/pass_block.glsl): no shader declares a uniform at a literal location and no
// renderer code sets one, so a member cannot drift from the location C++ writes.
#include "app/scene.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace {

std::vector<std::string> matches(const std::vector<std::string>& folders, const std::vector<std::string>& extensions,
                                 const std::regex& pattern) {
    std::vector<std::string> found;
    for (const std::string& folder : folders) {
        const std::filesystem::path root = vista::vistaRoot() / folder;
        if (!std::filesystem::exists(root)) continue;
        for (const auto& entry : std::filesystem::recursive_directory_iterator(root)) {
            if (!entry.is_regular_file()) continue;
            const std::string ext = entry.path().extension().string();
            if (std::find(extensions.begin(), extensions.end(), ext) == extensions.end()) continue;
            std::ifstream in(entry.path());
            std::string line;
            for (int n = 1; std::getline(in, line); ++n)
                if (std::regex_search(line, pattern))
                    found.push_back(std::filesystem::relative(entry.path(), vista::vistaRoot()).string() + ":" +
                                    std::to_string(n) + ": " + line);
        }
    }
    return found;
}

const std::vector<std::string> kSourceFolders{"app", "renderer", "terrain", "sky", "postfx", "tests/gl/shaders"};

}  // namespace

TEST_CASE("uniforms: no GLSL uniform at a literal location") {
    const std::regex literal(R"(layout\s*\(\s*location\s*=\s*\d+\s*\)\s*uniform)");
    const std::vector<std::string> found = matches(kSourceFolders, {".glsl"}, literal);
    for (const std::string& f : found) MESSAGE(f);
    CHECK(found.empty());
}

TEST_CASE("uniforms: no C++ sets a uniform by location") {
    const std::regex call(R"(\bgl(Program)?Uniform(Matrix)?[1-4])");
    const std::vector<std::string> found = matches({"app", "renderer", "terrain", "sky", "postfx"}, {".cpp", ".h"}, call);
    for (const std::string& f : found) MESSAGE(f);
    CHECK(found.empty());
}
