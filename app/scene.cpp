// Scene assembly and file lookup.
#include "app/scene.h"

#include "config/ini.h"

#include <cstdio>
#include <cstdlib>

namespace vista {

std::filesystem::path vistaRoot() {
    const char* env = std::getenv("VISTA_ROOT");
    return env && *env ? std::filesystem::path(env) : std::filesystem::path(VISTA_ROOT_DIR);
}

std::filesystem::path resolveInput(const std::filesystem::path& path) {
    if (path.empty() || path.is_absolute() || std::filesystem::exists(path)) return path;
    std::filesystem::path in_root = vistaRoot() / path;
    return std::filesystem::exists(in_root) ? in_root : path;
}

std::filesystem::path defaultScenePath() { return vistaRoot() / "config/default.ini"; }

InputErrors loadScene(const std::filesystem::path& file, const std::vector<std::string>& overrides, Settings& s) {
    return loadScene(std::vector<std::filesystem::path>{file}, overrides, s);
}

InputErrors loadScene(const std::vector<std::filesystem::path>& files, const std::vector<std::string>& overrides,
                      Settings& s) {
    s = Settings{};
    InputErrors errors;
    for (const auto& file : files) {
        InputErrors e = loadIniFile(file, s);
        errors.insert(errors.end(), e.begin(), e.end());
    }
    for (const auto& o : overrides) {
        InputErrors e = applyOverride(o, s);
        errors.insert(errors.end(), e.begin(), e.end());
    }
    return errors;
}

void printErrors(const InputErrors& errors) {
    for (const auto& e : errors) std::fprintf(stderr, "vista: %s\n", e.str().c_str());
}

}  // namespace vista
