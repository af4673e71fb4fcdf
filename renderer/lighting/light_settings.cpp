// [lights] keys for the settings visitor, and the text format of light.NAME / volume.NAME
// entries. Parsing is strict (every token checked, ranges enforced) so a typo in a scene file is
// an error with a reason rather than a silently different light.
#include "renderer/lighting/light_settings.h"

#include "config/spec_text.h"

#include <array>
#include <cmath>

namespace vista {
namespace {

constexpr double kMaxCoord = 1e8;  // m

using spec::Reader;
using spec::str;

constexpr double kMaxPhotometric = 1e9;  // cd or lm
constexpr std::array<const char*, 3> kUnitNames{"intensity", "candela", "lumens"};  // LightUnit's order

// The strength keywords shared by lights and volumes: `intensity I` (HDR, the old unit),
// `candela C`, `lumens L`; and `radius R|auto`. Returns false if key is none of them; else
// fills error on failure. radius_given records an explicit radius (a photometric light without
// one gets radius auto).
bool strengthKey(std::string_view key, Reader& r, float& intensity, LightUnit& unit, float& radius_m,
                 bool& radius_given, std::string& error) {
    double v[1];
    if (key == "radius") {
        radius_given = true;
        if (r.peek() == "auto") {
            r.word();
            radius_m = -1.0f;
            return true;
        }
        if (r.numbers(key, v, 1, 0.0, 1e5, error)) radius_m = float(v[0]);
        else error += " (or 'auto': from the intensity and [lights] cutoff_lux)";
        return true;
    }
    for (int u = 0; u < 3; ++u) {
        if (key != kUnitNames[std::size_t(u)]) continue;
        if (r.numbers(key, v, 1, 0.0, u == 0 ? 1e7 : kMaxPhotometric, error)) {
            intensity = float(v[0]);
            unit = LightUnit(u);
        }
        return true;
    }
    return false;
}

std::string strengthText(float intensity, LightUnit unit, float radius_m) {
    std::string s = radius_m < 0.0f ? "  radius auto" : "  radius " + str(radius_m);
    return s + "  " + kUnitNames[std::size_t(unit)] + " " + str(intensity);
}

// One entry's values as fields, for the panel (NamedList::describeEntry); ranges as in the parsers.
void describeLight(SettingsVisitor& v, Light& l) {
    static constexpr std::array<const char*, 2> types{"point", "spot"};
    v.choice({"type", "", "point or spot"}, l.type, types);
    v.field({"position", "m", "world position"}, l.position, -kMaxCoord, kMaxCoord);
    v.field({"radius", "m", "influence radius; 0 reaches nothing; -1 = auto (from the intensity and cutoff_lux)"}, l.radius_m, -1.0f, 1.0e5f);
    v.field({"color", "", "linear RGB"}, l.color, 0.0f, 1.0e3f);
    v.choice({"unit", "", "unit of intensity: intensity (HDR irradiance at 1 m), candela or lumens"}, l.unit, kUnitNames);
    v.field({"intensity", "", "in unit: HDR irradiance at 1 m, cd (a spot: on its axis) or lm"}, l.intensity, 0.0f, float(kMaxPhotometric));
    v.field({"ground", "m", "height above the terrain; -1 = the position's y"}, l.ground_m, -1.0f, 1.0e4f);
    v.field({"shadow", "", "casts a shadow (spot: the spot shadow atlas, [shadows] spot_*; point: a depth cube, [shadows] point_*)"}, l.shadow);
    if (l.type != LightType::Spot) return;
    v.field({"direction", "", "spot axis, not all zero"}, l.direction, -1.0e6f, 1.0e6f);
    v.field({"cone_inner", "deg", "half-angle of full intensity, at most cone_outer"}, l.inner_deg, 0.0f, 180.0f);
    v.field({"cone_outer", "deg", "half-angle where the light ends"}, l.outer_deg, 0.0f, 180.0f);
}

void describeVolume(SettingsVisitor& v, LightVolume& g) {
    v.field({"box_min", "m", "box corner"}, g.min_m, -kMaxCoord, kMaxCoord);
    v.field({"box_max", "m", "opposite box corner"}, g.max_m, -kMaxCoord, kMaxCoord);
    v.field({"count_x", "", "lights along x"}, g.count.x, 1, 10000);
    v.field({"count_y", "", "lights along y"}, g.count.y, 1, 10000);
    v.field({"count_z", "", "lights along z"}, g.count.z, 1, 10000);
    v.field({"radius", "m", "radius of each light; -1 = auto (from the intensity and cutoff_lux)"}, g.radius_m, -1.0f, 1.0e5f);
    v.choice({"unit", "", "unit of intensity: intensity (HDR irradiance at 1 m), candela or lumens"}, g.unit, kUnitNames);
    v.field({"intensity", "", "of each light, in unit: HDR irradiance at 1 m, cd or lm"}, g.intensity, 0.0f, float(kMaxPhotometric));
    v.field({"saturation", "", "HSV saturation of the random hues"}, g.saturation, 0.0f, 1.0f);
    v.field({"value", "", "HSV value of the random hues"}, g.value, 0.0f, 1.0f);
    v.field({"jitter", "", "random offset, fraction of a grid cell"}, g.jitter, 0.0f, 1.0f);
    double seed = g.seed;  // a double holds every uint32 exactly, an int does not
    v.field({"seed", "", "random hues and offsets"}, seed, 0.0, 4294967295.0);
    g.seed = std::uint32_t(seed);
    v.field({"hue_min", "", "lowest random hue, fraction of the colour wheel"}, g.hue_min, 0.0f, 1.0f);
    v.field({"hue_max", "", "highest random hue"}, g.hue_max, 0.0f, 1.0f);
    v.field({"ground", "m", "height of every light above the terrain; -1 = the box's y"}, g.ground_m, -1.0f, 1.0e4f);
}

}  // namespace

void describe(SettingsVisitor& v, LightsSettings& s) {
    static constexpr std::array<const char*, 4> methods{"naive", "tiled", "clustered", "hashed"};
    static constexpr std::array<const char*, 4> tiles{"16", "32", "8", "64"};  // the enum's order
    static constexpr std::array<const char*, 3> motions{"none", "circle", "bob"};
    v.section("lights", "local point and spot lights and their culling");
    v.field({"enabled", "", "local lights (off: no culling pass and no light buffers)"}, s.enabled);
    v.choice({"culling", "", "light culling: naive, tiled, clustered or hashed"}, s.culling, methods);
    v.choice({"tile_size", "px", "screen tile of tiled and clustered culling"}, s.tile_size, tiles);
    v.field({"cluster_slices", "", "depth slices; 0 = cubic clusters (002), at most 64"}, s.cluster_slices, 0, 256);
    v.field({"cluster_near_m", "m", "near_0 of the slices near_k = near_0 * ratio^k; 0 = the camera's near plane"}, s.cluster_near_m, 0.0f, 1.0e4f);
    v.field({"cluster_far_m", "m", "view depth the slices reach; the last slice also takes all beyond"}, s.cluster_far_m, 1.0f, 1.0e7f);
    v.field({"max_lights_per_cell", "", "list capacity per tile or cluster; overflow is counted"}, s.max_lights_per_cell, 1, 4096);
    v.field({"min_screen_px", "px",
             "tiled and clustered: a light whose bounding sphere's screen radius is below this is skipped before any "
             "per-tile work (0: none, the default; above 0 a skipped light can still have lit a pixel, so the methods may "
             "differ)"},
            s.min_screen_px, 0.0f, 64.0f);
    v.field({"hash_node_m", "m", "leaf node size of the hashed light octree; 0 = half the mean radius"}, s.hash_node_m, 0.0f, 1.0e5f);
    v.field({"hash_memory_mb", "MiB", "memory bound of the hashed tables; beyond it nodes coarsen"}, s.hash_memory_mb, 1.0f, 65536.0f);
    v.field({"hash_slack", "", "extra hash table room for incremental updates (fraction)"}, s.hash_slack, 0.0f, 4.0f);
    v.field({"glow", "",
             "glow around the lights in fog: their light scattered once by the air and [sky] height_fog between the "
             "camera and the surface (only where the medium's optical depth across a light's radius reaches 0.001)"},
            s.glow);
    v.field({"glow_max_lights", "", "lights that glow at most per frame, the brightest on screen"}, s.glow_max_lights, 0, 1024);
    v.choice({"animation", "", "light motion: none, circle (horizontal) or bob (vertical)"}, s.animation.motion, motions);
    v.field({"animation_amplitude_m", "m", "circle radius or bob height"}, s.animation.amplitude_m, 0.0f, 1.0e4f);
    v.field({"animation_period_s", "s", "time of one loop"}, s.animation.period_s, 0.01f, 1.0e6f);
    v.field({"animation_fraction", "", "share of the lights that move"}, s.animation.fraction, 0.0f, 1.0f);
    int seed = int(s.animation.seed & 0x7FFFFFFFu);
    v.field({"animation_seed", "", "which lights move and their phases"}, seed, 0, 0x7FFFFFFF);
    s.animation.seed = std::uint32_t(seed);
    NamedList lights(s.lights, &NamedLight::light, parseLightSpec, formatLightSpec, describeLight);
    v.field({"cutoff_lux", "lx",
             "a light with `radius auto` (the default with candela or lumens) reaches as far as its brightest channel's "
             "illuminance I * max(color) / d^2 stays above this (r = sqrt(I * max(color) / cutoff_lux - 0.01 m^2)); the "
             "falloff's window takes it smoothly to 0 there"},
            s.cutoff_lux, 1.0e-6f, 1.0e3f);
    v.list({"light", "", "a light: point|spot X Y Z (m), then any of candela C (cd; a spot: on its axis), lumens L (lm, "
                         "over the cone's solid angle), intensity I (HDR irradiance at 1 m, the old unit), "
                         "radius R (m) or radius auto (the default with candela or lumens), color R G B (filters the cd or lm), "
                         "direction X Y Z, cone INNER OUTER (deg), shadow on|off (default on; point lights with [shadows] point_enabled), ground H (m above the terrain)"},
           lights);
    NamedList volumes(s.volumes, &NamedLightVolume::volume, parseVolumeSpec, formatVolumeSpec, describeVolume);
    v.list({"volume", "", "a grid of lights of random hue: box X0 Y0 Z0 X1 Y1 Z1 (m), then any of count NX NY NZ, "
                          "radius R (m) or auto, candela C, lumens L or intensity I (as a light's), saturation S, value V, jitter J, seed N, hue MIN MAX, ground H (m)"},
           volumes);
}

std::string parseLightSpec(std::string_view text, Light& out) {
    Reader r(text);
    std::string_view type = r.word();
    if (type == "point") out.type = LightType::Point;
    else if (type == "spot") out.type = LightType::Spot;
    else return "expected 'point' or 'spot', got '" + std::string(type) + "'";
    std::string error;
    double v[3];
    if (!r.numbers("position", v, 3, -kMaxCoord, kMaxCoord, error)) return error;
    out.position = {v[0], v[1], v[2]};
    bool radius_given = false;
    while (!r.done()) {
        std::string_view key = r.word();
        if (strengthKey(key, r, out.intensity, out.unit, out.radius_m, radius_given, error)) {
            if (!error.empty()) return error;
        } else if (key == "color") {
            if (!r.numbers(key, v, 3, 0.0, 1e3, error)) return error;
            out.color = {float(v[0]), float(v[1]), float(v[2])};
        } else if (key == "direction") {
            if (!r.numbers(key, v, 3, -1e6, 1e6, error)) return error;
            if (v[0] == 0.0 && v[1] == 0.0 && v[2] == 0.0) return "direction must not be 0 0 0";
            out.direction = {float(v[0]), float(v[1]), float(v[2])};
        } else if (key == "cone") {
            if (!r.numbers(key, v, 2, 0.0, 180.0, error)) return error;
            if (v[0] > v[1]) return "cone: inner angle " + str(v[0]) + " is wider than outer angle " + str(v[1]);
            out.inner_deg = float(v[0]);
            out.outer_deg = float(v[1]);
        } else if (key == "ground") {
            if (!r.numbers(key, v, 1, 0.0, 1e4, error)) return error;
            out.ground_m = float(v[0]);
        } else if (key == "shadow") {
            std::string_view value = r.word();
            if (value != "on" && value != "off")
                return "shadow: expected 'on' or 'off', got '" + std::string(value) + "'";
            out.shadow = value == "on";
        } else {
            return "unknown word '" + std::string(key) +
                   "' (expected radius, color, candela, lumens, intensity, direction, cone, shadow or ground)";
        }
    }
    if (out.unit != LightUnit::Hdr && !radius_given) out.radius_m = -1.0f;
    return {};
}

std::string parseVolumeSpec(std::string_view text, LightVolume& out) {
    Reader r(text);
    std::string_view type = r.word();
    if (type != "box") return "expected 'box', got '" + std::string(type) + "'";
    std::string error;
    double v[6];
    if (!r.numbers("box", v, 6, -kMaxCoord, kMaxCoord, error)) return error;
    out.min_m = {v[0], v[1], v[2]};
    out.max_m = {v[3], v[4], v[5]};
    bool radius_given = false;
    while (!r.done()) {
        std::string_view key = r.word();
        if (strengthKey(key, r, out.intensity, out.unit, out.radius_m, radius_given, error)) {
            if (!error.empty()) return error;
        } else if (key == "count") {
            if (!r.numbers(key, v, 3, 1.0, 10000.0, error)) return error;
            for (int k = 0; k < 3; ++k)
                if (v[k] != std::floor(v[k])) return "count: " + str(v[k]) + " is not a whole number";
            out.count = {int(v[0]), int(v[1]), int(v[2])};
            // lightCount() (lights.cpp) would tie vista_config to the renderer; counts are >= 1 here.
            const std::uint64_t n = std::uint64_t(out.count.x) * std::uint64_t(out.count.y) * std::uint64_t(out.count.z);
            if (n > kMaxVolumeLights)
                return "count: " + std::to_string(n) + " lights is more than " + std::to_string(kMaxVolumeLights);
        } else if (key == "saturation" || key == "value" || key == "jitter") {
            if (!r.numbers(key, v, 1, 0.0, 1.0, error)) return error;
            (key == "saturation" ? out.saturation : key == "value" ? out.value : out.jitter) = float(v[0]);
        } else if (key == "seed") {
            if (!r.numbers(key, v, 1, 0.0, 4294967295.0, error)) return error;
            if (v[0] != std::floor(v[0])) return "seed: " + str(v[0]) + " is not a whole number";
            out.seed = std::uint32_t(v[0]);
        } else if (key == "hue") {
            if (!r.numbers(key, v, 2, 0.0, 1.0, error)) return error;
            if (v[0] > v[1]) return "hue: " + str(v[0]) + " " + str(v[1]) + ": the first must not exceed the second";
            out.hue_min = float(v[0]);
            out.hue_max = float(v[1]);
        } else if (key == "ground") {
            if (!r.numbers(key, v, 1, 0.0, 1e4, error)) return error;
            out.ground_m = float(v[0]);
        } else {
            return "unknown word '" + std::string(key) +
                   "' (expected count, radius, candela, lumens, intensity, saturation, value, jitter, seed, hue or ground)";
        }
    }
    if (out.unit != LightUnit::Hdr && !radius_given) out.radius_m = -1.0f;
    return {};
}

std::string formatLightSpec(const Light& l) {
    std::string s = l.type == LightType::Spot ? "spot " : "point ";
    s += str(l.position.x) + " " + str(l.position.y) + " " + str(l.position.z);
    s += l.radius_m < 0.0f ? "  radius auto" : "  radius " + str(l.radius_m);
    s += "  color " + str(l.color.r) + " " + str(l.color.g) + " " + str(l.color.b);
    s += std::string("  ") + kUnitNames[std::size_t(l.unit)] + " " + str(l.intensity);
    if (l.type == LightType::Spot) {
        s += "  direction " + str(l.direction.x) + " " + str(l.direction.y) + " " + str(l.direction.z);
        s += "  cone " + str(l.inner_deg) + " " + str(l.outer_deg);
    }
    if (!l.shadow) s += "  shadow off";
    if (l.ground_m >= 0.0f) s += "  ground " + str(l.ground_m);
    return s;
}

std::string formatVolumeSpec(const LightVolume& v) {
    std::string s = "box " + str(v.min_m.x) + " " + str(v.min_m.y) + " " + str(v.min_m.z) + "  " + str(v.max_m.x) +
                    " " + str(v.max_m.y) + " " + str(v.max_m.z);
    s += "  count " + std::to_string(v.count.x) + " " + std::to_string(v.count.y) + " " + std::to_string(v.count.z);
    s += strengthText(v.intensity, v.unit, v.radius_m);
    s += "  saturation " + str(v.saturation) + "  value " + str(v.value) + "  jitter " + str(v.jitter);
    s += "  seed " + std::to_string(v.seed);
    if (v.hue_min != 0.0f || v.hue_max != 1.0f) s += "  hue " + str(v.hue_min) + " " + str(v.hue_max);
    if (v.ground_m >= 0.0f) s += "  ground " + str(v.ground_m);
    return s;
}

}  // namespace vista
