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

// One quality knob: its name (the ini key it sets, or the pair it sets together), its value at
// each preset (low, medium, high = the defaults, ultra, reference = the maximum), how to set it
// and whether the scene uses it (a disabled feature's knob changes nothing).
struct QualityKnob {
    const char* name;  // "shadows.resolution"; "sky.transmittance_width" also sets the height (width / 4)
    const char* unit;  // for the report: "texels", "px", "taps", "" ...
    std::array<double, kQualityPresetCount> levels;
    // Sets the knob to value in s. scene: the settings before any preset (what a knob that maps
    // onto several keys restores: the terrain's LOD metric and base range).
    void (*apply)(Settings& s, double value, const Settings& scene);
    double (*get)(const Settings& s);
    bool (*active)(const Settings& scene);
    // Value as the report prints it ("full" for the terrain's 0, "on"/"off" for flags).
    const char* special_zero = nullptr;  // label of value 0, if it has one
    bool flag = false;                   // 0/1 knob
    bool descending = false;             // finer at lower values (error thresholds, half-resolution flags)
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
