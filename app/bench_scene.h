// The scene a bench measures: the loaded scene with every feature it does not measure switched
// off, so a feature added later (the sea entered `bench sky`'s views and took it from 59.6 to
// 16.3 dB) cannot leak in. Features are found through the settings description: every section's
// `enabled` key outside the kept sections is set false, whatever sections exist by then. What
// was switched off, the bench's fixed keys and the user's --set overrides (which win) are
// stated in the bench's output and its JSON ("scene").
#pragma once

#include "config/settings.h"

#include <nlohmann/json_fwd.hpp>

#include <string>
#include <vector>

namespace vista {

struct BenchScene {
    std::string bench;                   // "sky", "shadows", ...
    std::vector<std::string> kept;       // feature sections left as the scene has them (with their sub-sections)
    std::vector<std::string> disabled;   // "water.enabled=false", ...: switched off by the bench
    std::vector<std::string> fixed;      // the bench's own keys, "debug.grid=false", ...
    std::vector<std::string> user;       // the user's --set overrides, applied last
    Settings settings;                   // what the bench renders from

    // One printed paragraph: "bench sky: scene: kept sky, clouds; off: ...; fixed: ...; --set: ...".
    std::string summary() const;
    nlohmann::json json() const;
};

// Isolates scene for bench: every `enabled` key of a section that is neither in keep nor under a
// kept section ("clouds" keeps "clouds.low") is set false, unless the user's overrides set that
// key; then the fixed keys (`section.key=value`, the --set syntax) and the user's overrides are
// applied. A fixed key that does not parse is a programming error (asserted).
BenchScene isolateBenchScene(const std::string& bench, const Settings& scene, const std::vector<std::string>& keep,
                             const std::vector<std::string>& fixed, const std::vector<std::string>& user_overrides);

// The sections whose `enabled` key is true (what `bench frame`, which measures the scene as
// given, states as its scene).
std::vector<std::string> enabledSections(const Settings& scene);

// The sections each bench keeps, and its fixed keys (one definition, used by the CLI and the tests).
std::vector<std::string> benchKeptSections(const std::string& bench);
std::vector<std::string> benchFixedKeys(const std::string& bench);

}  // namespace vista
