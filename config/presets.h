// Quality presets: one call sets every quality knob (samples, steps, LUT and map sizes, the
// terrain's error threshold) to a level, leaving the look (intensities, lens, enabled flags)
// alone. The knobs and their value per level are one table (qualityKnobs()); applyQualityPreset
// and `vista quality`'s per-knob sweeps both read it, so a knob added there is in both.
#pragma once

#include "config/settings.h"

#include <array>
#include <optional>
#include <span>
#include <string_view>

namespace vista {

enum class QualityPreset : int { Low, Medium, High, Ultra, Reference };
inline constexpr int kQualityPresetCount = 5;

// One quality knob: the setting it turns (its key, "NAME.key" for [postfx.NAME]), its value at
// each preset (low, medium, high = the defaults, ultra, reference = the maximum) and whether the
// scene uses it (a disabled feature's knob changes nothing). A knob is set and read through the
// settings visitor by its key, so its range and help stay in describe(); a knob that sets
// several keys together has its own set/read.
struct QualityKnob {
    const char* name;  // "shadows.resolution"; "sky.transmittance_width" also sets the height (width / 4)
    const char* unit;  // for the report: "texels", "px", "taps", "" ...
    std::array<double, kQualityPresetCount> levels;
    bool (*used)(const Settings& scene);
    // For knobs over several keys. scene: the settings before any preset (what the terrain's
    // knob restores: its LOD metric and base range).
    void (*set)(Settings& s, double value, const Settings& scene) = nullptr;
    double (*read)(const Settings& s) = nullptr;
    // Value as the report prints it ("full" for the terrain's 0, "on"/"off" for flags).
    const char* special_zero = nullptr;  // label of value 0, if it has one
    bool flag = false;                   // 0/1 knob
    bool descending = false;             // finer at lower values (error thresholds, half-resolution flags)
    // Not finer with the level: a cost the preset trades against its other knobs (the cloud march
    // subset, whose saving high and ultra spend on a finer march).
    bool trade = false;

    void apply(Settings& s, double value, const Settings& scene) const;
    double get(const Settings& s) const;
    bool active(const Settings& scene) const { return used(scene); }
};

// Every knob, in report order.
std::span<const QualityKnob> qualityKnobs();
const QualityKnob* findQualityKnob(std::string_view name);

// The terrain at full resolution (the reference's LOD): every heightmap texel a vertex, i.e.
// distance-only selection with an LOD 0 range beyond any map.
inline constexpr double kFullResolutionRangeM = 1.0e6;

void applyQualityPreset(Settings& s, QualityPreset preset);

// "low", "medium", "high", "ultra", "reference"; none for anything else.
std::optional<QualityPreset> qualityPresetFromName(std::string_view name);
const char* qualityPresetName(QualityPreset preset);

}  // namespace vista
