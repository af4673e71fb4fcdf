// Bench isolation through the settings description: the visitor sees every section and its
// `enabled` key, so no list of features here has to be kept up to date.
#include "app/bench_scene.h"

#include "config/ini.h"
#include "config/visitor.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cassert>
#include <cstdio>
#include <utility>

namespace vista {
namespace {

bool underAny(const std::string& section, const std::vector<std::string>& roots) {
    for (const std::string& r : roots)
        if (section == r || section.rfind(r + ".", 0) == 0) return true;
    return false;
}

// Calls on(section, value) for every section's `enabled` key; on may change the value.
template <class OnEnabled>
class EachEnabled final : public SettingsVisitor {
public:
    explicit EachEnabled(OnEnabled on) : on_(std::move(on)) {}
    void section(const char* name, const char*) override { section_ = name; }
    void field(const FieldInfo& info, bool& value) override {
        if (std::string(info.key) == "enabled") on_(section_, value);
    }
    void field(const FieldInfo&, int&, int, int) override {}
    void field(const FieldInfo&, float&, float, float) override {}
    void field(const FieldInfo&, double&, double, double) override {}
    void field(const FieldInfo&, glm::vec3&, float, float) override {}
    void field(const FieldInfo&, glm::dvec3&, double, double) override {}
    void field(const FieldInfo&, std::string&) override {}
    void choice(const FieldInfo&, int&, std::span<const char* const>) override {}
    void list(const FieldInfo&, ListField&) override {}

private:
    OnEnabled on_;
    std::string section_;
};

template <class OnEnabled>
void forEachEnabled(Settings& s, OnEnabled on) {
    EachEnabled<OnEnabled> visitor(std::move(on));
    describe(visitor, s);
}

std::string join(const std::vector<std::string>& items) {
    std::string out;
    for (const std::string& i : items) out += (out.empty() ? "" : ", ") + i;
    return out.empty() ? "none" : out;
}

}  // namespace

BenchScene isolateBenchScene(const std::string& bench, const Settings& scene, const std::vector<std::string>& keep,
                             const std::vector<std::string>& fixed, const std::vector<std::string>& user_overrides) {
    BenchScene b{bench, keep, {}, fixed, user_overrides, scene};
    // Sets `enabled` false in every section outside keep (and not named by the user).
    forEachEnabled(b.settings, [&](const std::string& section, bool& enabled) {
        if (!enabled || underAny(section, keep)) return;
        const std::string key = section + ".enabled";
        for (const std::string& u : user_overrides)
            if (u.rfind(key + "=", 0) == 0) return;  // the user's --set wins
        enabled = false;
        b.disabled.push_back(key + "=false");
    });
    for (const std::string& f : fixed) {
        [[maybe_unused]] InputErrors errors = applyOverride(f, b.settings);
        assert(errors.empty() && "a bench's fixed key does not parse");
    }
    for (const std::string& u : user_overrides) applyOverride(u, b.settings);  // valid: the scene loaded with them
    return b;
}

std::string BenchScene::summary() const {
    return "bench " + bench + ": scene isolated: kept [" + join(kept) + "]; switched off [" + join(disabled) +
           "]; fixed [" + join(fixed) + "]; --set [" + join(user) + "]\n";
}

nlohmann::json BenchScene::json() const {
    return {{"kept", kept}, {"disabled", disabled}, {"fixed", fixed}, {"user_overrides", user}};
}

std::vector<std::string> enabledSections(const Settings& scene) {
    Settings copy = scene;  // describe() takes a mutable struct; nothing here changes it
    std::vector<std::string> sections;
    forEachEnabled(copy, [&](const std::string& section, bool& enabled) {
        if (enabled) sections.push_back(section);
    });
    return sections;
}

std::vector<std::string> benchKeptSections(const std::string& bench) {
    if (bench == "sky") return {"sky", "clouds"};
    if (bench == "shadows") return {"terrain", "shadows", "sky", "lights"};
    if (bench == "grass") return {"terrain", "grass"};
    if (bench == "objects") return {"terrain", "objects"};
    if (bench == "terrain") return {"terrain"};
    if (bench == "lights") return {"terrain", "lights"};
    return {};
}

std::vector<std::string> benchFixedKeys(const std::string& bench) {
    std::vector<std::string> keys = {"debug.grid=false", "debug.view=final"};
    if (bench == "sky") keys.insert(keys.end(), {"sky.sun_mode=angles", "sky.moon=false", "sky.stars=false"});
    return keys;
}

}  // namespace vista
