// Light placement against the terrain and the sea. The sea is a plane at [water] level_m over
// the whole map, so a light's ground is max(terrain, level) wherever the sea is on.
#include "app/light_placement.h"

#include <algorithm>
#include <cstdio>
#include <fstream>

namespace vista {

namespace {

std::string_view trim(std::string_view t) {
    const auto begin = t.find_first_not_of(" \t\r\n");
    return begin == t.npos ? std::string_view{} : t.substr(begin, t.find_last_not_of(" \t\r\n") - begin + 1);
}

// Where [lights] KEY is defined last: the last --set naming it, else the last file line.
InputError keyLocation(const std::string& key, const std::vector<std::filesystem::path>& files,
                       const std::vector<std::string>& overrides) {
    for (auto it = overrides.rbegin(); it != overrides.rend(); ++it)
        if (trim(std::string_view(*it).substr(0, it->find('='))) == "lights." + key) return {"--set", 0, ""};
    InputError where{files.empty() ? std::string("scene") : files.back().string(), 0, ""};
    for (const auto& file : files) {
        std::ifstream in(file);
        std::string section;
        int number = 0;
        for (std::string line; std::getline(in, line);) {
            ++number;
            std::string_view t = trim(line);
            if (t.starts_with('[')) {
                section = std::string(trim(t.substr(1, t.find(']') - 1)));
            } else if (section == "lights" && t.find('=') != t.npos && trim(t.substr(0, t.find('='))) == key) {
                where = {file.string(), number, ""};
            }
        }
    }
    return where;
}

// "inside the terrain" / "under the water" / "" for a light's centre.
const char* placementProblem(const glm::dvec3& p, const GroundHeight& terrain, const WaterSettings& water) {
    if (terrain && p.y < terrain(p.x, p.z)) return "inside the terrain";
    if (water.enabled && p.y < double(water.level_m)) return "under the water";
    return "";
}

}  // namespace

GroundHeight lightGround(const GroundHeight& terrain, const WaterSettings& water) {
    if (!terrain || !water.enabled) return terrain;
    const double level = water.level_m;
    return [terrain, level](double x, double z) { return std::max(terrain(x, z), level); };
}

InputErrors checkLightPlacement(const Settings& s, const GroundHeight& terrain,
                                const std::vector<std::filesystem::path>& files,
                                const std::vector<std::string>& overrides) {
    InputErrors warnings;
    if (!s.lights.enabled) return warnings;
    const WaterSettings& water = s.water;
    char text[512];
    for (const NamedLight& l : s.lights.lights) {
        if (l.light.ground_m >= 0.0f && terrain) continue;  // placed on the ground (or the water) by construction
        const glm::dvec3& p = l.light.position;
        const char* problem = placementProblem(p, terrain, water);
        if (!*problem) continue;
        const double surface = std::string_view(problem) == "under the water" ? double(water.level_m) : terrain(p.x, p.z);
        InputError w = keyLocation("light." + l.name, files, overrides);
        std::snprintf(text, sizeof text,
                      "[lights] light.%s at y = %.1f m is %s (surface at %.1f m): it lights nothing above it; "
                      "raise its y or give it `ground H` (H m above the terrain or the water, 0..1e4)",
                      l.name.c_str(), p.y, problem, surface);
        w.message = text;
        warnings.push_back(std::move(w));
    }
    for (const NamedLightVolume& v : s.lights.volumes) {
        if (v.volume.ground_m >= 0.0f && terrain) continue;
        std::vector<Light> lights;
        generateLights(v.volume, lights);
        std::size_t inside = 0, under = 0;
        const double floor_y = std::min(v.volume.min_m.y, v.volume.max_m.y);
        for (Light& light : lights) {
            if (v.volume.ground_m >= 0.0f) light.position.y = floor_y + v.volume.ground_m;  // as collectSceneLights
            const std::string_view problem = placementProblem(light.position, terrain, water);
            inside += problem == "inside the terrain";
            under += problem == "under the water";
        }
        if (inside + under == 0) continue;
        InputError w = keyLocation("volume." + v.name, files, overrides);
        std::snprintf(text, sizeof text,
                      "[lights] volume.%s: %zu of %zu lights inside the terrain and %zu under the water (level_m %.1f): "
                      "raise the box's y or give it `ground H` (H m above the terrain or the water, 0..1e4)",
                      v.name.c_str(), inside, lights.size(), under, double(water.level_m));
        w.message = text;
        warnings.push_back(std::move(w));
    }
    return warnings;
}

}  // namespace vista
