// Quality presets: one call sets every quality knob (samples, levels, resolution scale) to a
// level, leaving the look (intensities, lens, enabled flags) alone. Features add their knobs to
// applyQualityPreset; `vista quality` compares the levels against Reference.
#pragma once

#include "config/settings.h"

#include <optional>
#include <string_view>

namespace vista {

enum class QualityPreset : int { Low, Medium, High, Ultra, Reference };

void applyQualityPreset(Settings& s, QualityPreset preset);

// "low", "medium", "high", "ultra", "reference"; none for anything else.
std::optional<QualityPreset> qualityPresetFromName(std::string_view name);
const char* qualityPresetName(QualityPreset preset);

}  // namespace vista
