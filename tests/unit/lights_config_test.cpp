// The [lights] section in scene files: the light.NAME / volume.NAME list keys through the
// loader, `vista check`'s error collection, --set, the writer and the panel's entry view.
#include "config/ini.h"
#include "config_helpers.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <string>
#include <vector>

using namespace vista;

namespace {

using test::contains;
using test::messages;
using test::oneError;
using test::oneOverrideError;

std::vector<std::string> names(const LightsSettings& s) {
    std::vector<std::string> out;
    for (const NamedLight& l : s.lights) out.push_back(l.name);
    for (const NamedLightVolume& v : s.volumes) out.push_back(v.name);
    return out;
}

// Every list entry as "name = text" lines, for exact comparison.
std::string listText(const LightsSettings& s) {
    std::string out;
    for (const NamedLight& l : s.lights) out += "light." + l.name + " = " + formatLightSpec(l.light) + "\n";
    for (const NamedLightVolume& v : s.volumes) out += "volume." + v.name + " = " + formatVolumeSpec(v.volume) + "\n";
    return out;
}

const char* const kScene =
    "[sky]\n"
    "sun_elevation_deg = 20\n"
    "\n"
    "[lights]\n"
    "culling = tiled\n"
    "light.lantern = point 10 42 -5  radius 12  color 1 0.7 0.4  intensity 30\n"
    "volume.village = box -200 30 -150  200 40 150  count 16 1 12  radius 18  intensity 40  saturation 0.5"
    "  value 1  jitter 0.3  seed 23\n"
    "light.beam    = spot 0 50 0  radius 40  color 1 1 1  intensity 200  direction 0 -1 0  cone 20 30\n"
    "max_lights_per_cell = 128\n";

}  // namespace

TEST_CASE("lights config: a scene without list keys has no lights") {
    Settings s;
    CHECK(s.lights.lights.empty());
    CHECK(s.lights.volumes.empty());
    CHECK(messages(loadIniString("[lights]\nculling = naive\n", "scene.ini", s)) == "");
    CHECK(s.lights.lights.empty());
    CHECK(s.lights.volumes.empty());
    CHECK(s.lights.culling == LightCulling::Naive);
    CHECK(messages(loadIniString("[window]\nwidth = 64\n", "scene.ini", s)) == "");
    CHECK(s.lights.lights.empty());
}

TEST_CASE("lights config: two lights and a volume load in file order with their values") {
    Settings s;
    CHECK(messages(loadIniString(kScene, "scene.ini", s)) == "");
    CHECK(s.sky.sun_elevation_deg == 20.0f);
    CHECK(s.lights.culling == LightCulling::Tiled);
    CHECK(s.lights.max_lights_per_cell == 128);
    CHECK(names(s.lights) == std::vector<std::string>{"lantern", "beam", "village"});

    REQUIRE(s.lights.lights.size() == 2);
    const Light& lantern = s.lights.lights[0].light;
    CHECK(lantern.type == LightType::Point);
    CHECK(lantern.position == glm::dvec3(10, 42, -5));
    CHECK(lantern.radius_m == 12.0f);
    CHECK(lantern.color == glm::vec3(1.0f, 0.7f, 0.4f));
    CHECK(lantern.intensity == 30.0f);
    const Light& beam = s.lights.lights[1].light;
    CHECK(beam.type == LightType::Spot);
    CHECK(beam.direction == glm::vec3(0, -1, 0));
    CHECK(beam.inner_deg == 20.0f);
    CHECK(beam.outer_deg == 30.0f);

    REQUIRE(s.lights.volumes.size() == 1);
    const LightVolume& village = s.lights.volumes[0].volume;
    CHECK(village.min_m == glm::dvec3(-200, 30, -150));
    CHECK(village.max_m == glm::dvec3(200, 40, 150));
    CHECK(village.count == glm::ivec3(16, 1, 12));
    CHECK(village.saturation == 0.5f);
    CHECK(village.jitter == 0.3f);
    CHECK(village.seed == 23u);

    // Omitted groups take Light's defaults.
    CHECK(messages(loadIniString("[lights]\nlight.bare = point 1 2 3\n", "scene.ini", s)) == "");
    CHECK(s.lights.lights.back().light.radius_m == Light{}.radius_m);
    CHECK(s.lights.lights.back().light.intensity == Light{}.intensity);
}

TEST_CASE("lights config: bad values name the key, the bad token and what is accepted") {
    Settings s;
    CHECK(oneError("[lights]\nlight.a = point 0 0 x\n", s, 2) ==
          "[lights] light.a = point 0 0 x is not accepted: position: 'x' is not a number");
    CHECK(oneError("[lights]\nlight.a = lamp 0 0 0\n", s, 2) ==
          "[lights] light.a = lamp 0 0 0 is not accepted: expected 'point' or 'spot', got 'lamp'");
    CHECK(oneError("[lights]\n\nlight.a = point 0 0 0  radius -1\n", s, 3) ==
          "[lights] light.a = point 0 0 0  radius -1 is not accepted: radius: -1 is outside [0, 100000] (or 'auto': from the intensity and [lights] cutoff_lux)");
    CHECK(contains(oneError("[lights]\nlight.a = point 0 0 0 glow 2\n", s, 2),
                   "unknown word 'glow' (expected radius, color, candela, lumens, intensity, direction, cone, shadow or ground)"));
    CHECK(contains(oneError("[lights]\nvolume.v = box 0 0 0 1 1 1 count 10000 10000 10000\n", s, 2),
                   "is not accepted: count: 1000000000000 lights is more than 1000000"));
    CHECK(s.lights.lights.empty());  // a bad entry is not added
    CHECK(s.lights.volumes.empty());
}

TEST_CASE("lights config: a bad name, a repeated name and a list key elsewhere are errors") {
    Settings s;
    CHECK(oneError("[lights]\nlight.a-b = point 0 0 0\n", s, 2) ==
          "[lights] light.a-b: the name 'a-b' is not accepted; accepted: light.NAME with NAME made of letters, "
          "digits and _");
    CHECK(contains(oneError("[lights]\nvolume. = box 0 0 0 1 1 1\n", s, 2), "the name '' is not accepted"));
    CHECK(s.lights.lights.empty());

    CHECK(oneError("[lights]\nlight.a = point 1 0 0\nvolume.a = box 0 0 0 1 1 1\nlight.a = point 2 0 0\n", s, 4) ==
          "[lights] light.a is set twice, on lines 2 and 4; the second is ignored");
    REQUIRE(s.lights.lights.size() == 1);  // the same NAME in the other list is fine
    CHECK(s.lights.lights[0].light.position.x == 1.0);
    CHECK(s.lights.volumes.size() == 1);

    Settings t;
    CHECK(oneError("[sky]\nlight.sun = point 0 0 0\n", t, 2) ==
          "unknown key [sky] light.sun; light.NAME keys belong in [lights]");
    CHECK(oneError("[lights]\nlihgt.a = point 0 0 0\n", t, 2) ==
          "unknown key [lights] lihgt.a; did you mean 'light.a'?");
    CHECK(contains(oneError("[lights]\nlamp.a = point 0 0 0\n", t, 2),
                   "unknown key [lights] lamp.a; accepted: enabled, culling, "));
    CHECK(contains(oneError("[lights]\nlamp.a = point 0 0 0\n", t, 2), ", light.NAME, volume.NAME"));
    CHECK(contains(oneError("[lights]\nlight = point 0 0 0\n", t, 2), "unknown key [lights] light;"));
    CHECK(t.lights.lights.empty());
}

TEST_CASE("lights config: vista check collects every list error in line order") {
    Settings s;
    const InputErrors errors = loadIniString(
        "[lights]\n"
        "light.ok = point 0 0 0\n"
        "light.bad = point 0 0\n"          // 3 too few numbers
        "light.ok = point 1 1 1\n"         // 4 repeated
        "light.x.y = point 0 0 0\n"        // 5 bad name
        "volume.v = box 0 0 0 1 1 1 seed -1\n"  // 6 out of range
        "volum.w = box 0 0 0 1 1 1\n"      // 7 unknown prefix
        "cluster_slices = 999\n"           // 8 plain key out of range
        "light.last = spot 0 0 0 cone 40 30\n",  // 9 inner wider than outer
        "scene.ini", s);
    INFO(messages(errors));
    std::vector<int> lines;
    for (const InputError& e : errors) lines.push_back(e.line);
    CHECK(lines == std::vector{3, 4, 5, 6, 7, 8, 9});
    CHECK(names(s.lights) == std::vector<std::string>{"ok"});
}

TEST_CASE("lights config: save then load reproduces the lists exactly and in order") {
    Settings s;
    REQUIRE(messages(loadIniString(kScene, "scene.ini", s)) == "");
    // Values that need every digit, and a line longer than inih's 200 characters.
    s.lights.lights[0].light.position = {1.0e7 + 0.123, -0.1, 1.0 / 3.0};
    s.lights.lights[0].light.color = {0.1f, 1.0f / 3.0f, 16777217.0f / 1e6f};
    s.lights.lights[1].light.position = {-12345678.901234567, 98765432.10987654, -0.000123456789012345};
    s.lights.lights[1].light.direction = {0.123456789f, -0.987654321f, 1.0f / 7.0f};
    s.lights.lights[1].light.inner_deg = 1.0f / 3.0f;
    s.lights.volumes[0].volume.min_m = {-1.0 / 3.0, 2.0 / 3.0, -98765432.123456789};
    s.lights.volumes[0].volume.seed = 4294967295u;

    const std::string text = saveIniString(s);
    INFO(text);
    CHECK(contains(text, "\nlight.lantern = point 10000000.123 -0.1 0.3333333333333333  radius 12  color 0.1 "));
    CHECK(contains(text, "\nvolume.village = box "));
    CHECK(contains(text, "  seed 4294967295\n"));
    CHECK(text.find("light.lantern") < text.find("light.beam"));
    CHECK(text.find("[sky]") < text.find("[lights]"));
    CHECK(text.find("[lights]") < text.find("[postfx]"));
    CHECK(contains(text, "\n; a light: point|spot X Y Z (m), then any of candela C (cd; a spot: on its axis), lumens L (lm, "
                         "over the cone's solid angle), intensity I (HDR irradiance at 1 m, the old unit), "
                         "radius R (m) or radius auto (the default with candela or lumens), color R G B (filters the cd or lm), "
                         "direction X Y Z, cone INNER OUTER (deg), shadow on|off (default on; point lights with [shadows] point_enabled), ground H (m above the terrain) (one light.NAME key per entry, NAME: letters, "
                         "digits, _)\nlight.lantern = "));
    bool long_line = false;
    for (std::size_t b = 0, e; b < text.size(); b = e + 1) {
        e = text.find('\n', b);
        long_line |= e - b > 200;
    }
    CHECK(long_line);

    Settings loaded;
    CHECK(messages(loadIniString(text, "saved.ini", loaded)) == "");
    CHECK(listText(loaded.lights) == listText(s.lights));
    CHECK(names(loaded.lights) == names(s.lights));
    CHECK(loaded.lights.lights[1].light.position == s.lights.lights[1].light.position);
    CHECK(loaded.lights.volumes[0].volume.seed == 4294967295u);
    CHECK(saveIniString(loaded) == text);

    // Empty lists save as their help comments only and load back empty.
    Settings empty;
    const std::string none = saveIniString(empty);
    CHECK(!contains(none, "\nlight."));
    Settings reloaded;
    CHECK(messages(loadIniString(none, "saved.ini", reloaded)) == "");
    CHECK(reloaded.lights.lights.empty());
    CHECK(reloaded.lights.volumes.empty());
}

TEST_CASE("lights config: a file loaded over lights replaces entries by name and keeps the rest") {
    Settings s;
    REQUIRE(messages(loadIniString(kScene, "scene.ini", s)) == "");
    CHECK(messages(loadIniString("[lights]\nlight.beam = point 7 7 7\nlight.extra = point 1 1 1\n", "preset.ini", s)) == "");
    CHECK(names(s.lights) == std::vector<std::string>{"lantern", "beam", "extra", "village"});
    CHECK(s.lights.lights[1].light.type == LightType::Point);
    CHECK(s.lights.lights[1].light.position == glm::dvec3(7, 7, 7));
    CHECK(s.lights.lights[1].light.inner_deg == Light{}.inner_deg);  // replaced whole, not merged
}

TEST_CASE("lights config: --set lights.light.NAME adds or replaces one entry") {
    Settings s;
    CHECK(messages(applyOverride("lights.light.lamp=point 1 2 3 radius 5", s)) == "");
    CHECK(messages(applyOverride(" lights.volume.grid = box 0 0 0 10 10 10 count 2 2 2 ", s)) == "");
    CHECK(messages(applyOverride("lights.light.torch=spot 0 0 0", s)) == "");
    CHECK(messages(applyOverride("lights.light.lamp=point 4 5 6", s)) == "");
    CHECK(messages(applyOverride("lights.culling=hashed", s)) == "");
    CHECK(names(s.lights) == std::vector<std::string>{"lamp", "torch", "grid"});
    CHECK(s.lights.lights[0].light.position == glm::dvec3(4, 5, 6));
    CHECK(s.lights.lights[0].light.radius_m == Light{}.radius_m);
    CHECK(s.lights.volumes[0].volume.count == glm::ivec3(2));
    CHECK(s.lights.culling == LightCulling::Hashed);

    CHECK(oneOverrideError("lights.light.lamp=point 0 0 0 radius 1e9", s) ==
          "[lights] light.lamp = point 0 0 0 radius 1e9 is not accepted: radius: 1e9 is outside [0, 100000] (or 'auto': from the intensity and [lights] cutoff_lux)");
    CHECK(s.lights.lights[0].light.position == glm::dvec3(4, 5, 6));  // unchanged
    CHECK(contains(oneOverrideError("lights.light.a-b=point 0 0 0", s), "the name 'a-b' is not accepted"));
    CHECK(oneOverrideError("lights.lihgt.lamp=point 0 0 0", s) ==
          "unknown section [lights.lihgt]; did you mean 'lights.light.lamp'?");
    CHECK(contains(oneOverrideError("sky.light.lamp=point 0 0 0", s), "unknown section [sky.light]"));
    CHECK(names(s.lights) == std::vector<std::string>{"lamp", "torch", "grid"});
}

namespace {

// Sets one named field of a list entry, as the panel would.
class SetEntryField final : public SettingsVisitor {
public:
    SetEntryField(std::string key, float value) : key_(std::move(key)), value_(value) {}
    std::vector<std::string> keys;
    void section(const char*, const char*) override {}
    void field(const FieldInfo& i, bool&) override { keys.push_back(i.key); }
    void field(const FieldInfo& i, int&, int, int) override { keys.push_back(i.key); }
    void field(const FieldInfo& i, float& v, float, float) override {
        keys.push_back(i.key);
        if (key_ == i.key) v = value_;
    }
    void field(const FieldInfo& i, double&, double, double) override { keys.push_back(i.key); }
    void field(const FieldInfo& i, glm::vec3&, float, float) override { keys.push_back(i.key); }
    void field(const FieldInfo& i, glm::dvec3&, double, double) override { keys.push_back(i.key); }
    void field(const FieldInfo& i, std::string&) override { keys.push_back(i.key); }
    void choice(const FieldInfo& i, int&, std::span<const char* const>) override { keys.push_back(i.key); }
    void list(const FieldInfo&, ListField& l) override {
        for (std::size_t e = 0; e < l.size(); ++e) l.describeEntry(e, *this);
    }

private:
    std::string key_;
    float value_;
};

}  // namespace

TEST_CASE("lights config: the panel's entry fields edit values and an invalid edit is undone") {
    Settings s;
    REQUIRE(messages(loadIniString(kScene, "scene.ini", s)) == "");
    SetEntryField intensity("intensity", 77.0f);
    describe(intensity, s);
    CHECK(s.lights.lights[0].light.intensity == 77.0f);
    CHECK(s.lights.lights[1].light.intensity == 77.0f);
    CHECK(s.lights.volumes[0].volume.intensity == 77.0f);
    for (const char* key : {"type", "position", "radius", "color", "intensity", "direction", "cone_inner",
                            "cone_outer", "box_min", "box_max", "count_x", "seed", "jitter"})
        CHECK(std::ranges::count(intensity.keys, std::string(key)) >= 1);

    SetEntryField cone("cone_inner", 60.0f);  // wider than the outer 30 deg: not a valid spot
    describe(cone, s);
    CHECK(s.lights.lights[1].light.inner_deg == 20.0f);
}
