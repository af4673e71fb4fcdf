// Scene files: ini text <-> Settings, through the one description in settings.cpp.
// Every function collects all problems it finds instead of stopping at the first, so
// `vista check` can list them at once.
#pragma once

#include "config/input_error.h"
#include "config/settings.h"

#include <filesystem>
#include <span>
#include <string>
#include <string_view>

namespace vista {

// Reads file over s (keys the file omits keep their current value). Unknown sections and
// keys (with a did-you-mean suggestion), malformed and out-of-range values, and duplicate
// keys are reported with file:line and what is accepted; a bad value leaves the field as it was.
// A list key PREFIX.NAME (light.lantern in [lights]) replaces the entry NAME or appends one.
InputErrors loadIniFile(const std::filesystem::path& file, Settings& s);
// Same, from text; name is used as the file name in errors.
InputErrors loadIniString(std::string_view text, const std::string& name, Settings& s);

// Applies one "section.key=value" override (the --set syntax); the section may itself
// contain dots ("postfx.tonemap.op=aces"), and so may a list key ("lights.light.lamp=point 0 9 0"
// sets [lights] light.lamp). Errors use "--set" as the file name.
InputErrors applyOverride(std::string_view assignment, Settings& s);

// The whole of s as an ini file, each key preceded by a comment with its help, unit and
// range. loadIniString(saveIniString(s)) reproduces s exactly (floats round-trip).
std::string saveIniString(Settings& s);
// The scene-file reference as Markdown (docs/scene-file.md): every section and key with its
// default, unit, accepted values and help, from describe().
std::string sceneFileReference();
// Writes saveIniString(s) to file atomically (temporary name, then rename). Empty on
// success, otherwise the reason.
std::string saveIniFile(const std::filesystem::path& file, Settings& s);

// The candidate closest to word by edit distance, or "" when none is close enough to be
// a plausible typo.
std::string didYouMean(std::string_view word, std::span<const std::string> candidates);

}  // namespace vista
