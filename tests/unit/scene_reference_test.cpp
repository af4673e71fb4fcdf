// The scene-file reference is generated from describe(): the committed docs/scene-file.md must be
// what `vista check --reference` prints now, and it must name every section and key.
#include "app/scene.h"
#include "config/ini.h"

#include <doctest/doctest.h>

#include <fstream>
#include <sstream>
#include <string>

using namespace vista;

TEST_CASE("docs: docs/scene-file.md is the current reference generated from the settings' descriptions") {
    const std::filesystem::path file = vistaRoot() / "docs/scene-file.md";
    std::ifstream in(file, std::ios::binary);
    REQUIRE_MESSAGE(in, file.string() << " is missing: run `build/vista check --reference > docs/scene-file.md`");
    std::stringstream committed;
    committed << in.rdbuf();
    const std::string generated = sceneFileReference();
    CHECK_MESSAGE(committed.str() == generated,
                  file.string() << " is out of date: run `build/vista check --reference > docs/scene-file.md`");
    // Spot checks that it is the whole description: a section, a nested section, a list key, a choice.
    CHECK(generated.find("## [terrain]") != std::string::npos);
    CHECK(generated.find("## [clouds.low]") != std::string::npos);
    CHECK(generated.find("| `light.NAME` |") != std::string::npos);
    CHECK(generated.find("| `lod_metric` | error |") != std::string::npos);
}
