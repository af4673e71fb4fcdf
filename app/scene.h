// Where vista finds its files, and how a scene is assembled: defaults, then the ini
// file, then --set overrides.
#pragma once

#include "config/input_error.h"
#include "config/settings.h"

#include <filesystem>
#include <string>
#include <vector>

namespace vista {

// The directory holding config/, data/ and the shaders: $VISTA_ROOT, else the source tree
// vista was built from.
std::filesystem::path vistaRoot();

// A user-given path as is when it exists (or is absolute), else relative to vistaRoot().
std::filesystem::path resolveInput(const std::filesystem::path& path);

// The default scene file.
std::filesystem::path defaultScenePath();

// Fills s from defaults, file and overrides, collecting every problem.
InputErrors loadScene(const std::filesystem::path& file, const std::vector<std::string>& overrides, Settings& s);
// The same for several scene files (`-c` repeated): each later file overrides the earlier ones.
InputErrors loadScene(const std::vector<std::filesystem::path>& files, const std::vector<std::string>& overrides,
                      Settings& s);

// Prints errors, one per line, to stderr.
void printErrors(const InputErrors& errors);

}  // namespace vista
