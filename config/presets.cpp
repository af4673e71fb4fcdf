// The post chain's, the sun shadows' and the sea's quality knobs per preset. High is the shipped default (Settings{}), so a scene
// without a preset looks the same; Reference is everything at its maximum.
#include "config/presets.h"

#include <array>

namespace vista {

namespace {

struct PostKnobs {
    int ssao_directions, ssao_steps;
    bool ssao_half;
    int bloom_levels, dof_samples, motion_blur_samples;
};

constexpr std::array<PostKnobs, 5> kPost{{
    {2, 3, true, 3, 12, 6},      // low
    {3, 4, true, 4, 20, 8},      // medium
    {4, 4, true, 5, 32, 12},     // high (the defaults)
    {8, 8, false, 6, 64, 24},    // ultra
    {16, 32, false, 10, 256, 64} // reference: the ranges' maxima
}};

// Sun shadows: texels per cascade and filter taps (bench shadows: error halves from 1024 to
// 4096 texels at 2-3x the cost; the reference is the bench's 4096-texel row with 64 taps).
// Spot shadows: atlas side and taps (bench shadows: hard error falls 7x from 1024 to 4096 at
// 2.6x the atlas cost; the reference is the largest atlas with 64 taps).
struct ShadowKnobs {
    int resolution, pcf_taps, spot_atlas, spot_taps;
};

constexpr std::array<ShadowKnobs, 5> kShadow{{
    {512, 4, 1024, 4},     // low
    {1024, 8, 1024, 8},    // medium
    {1024, 12, 2048, 16},  // high (the defaults)
    {2048, 16, 4096, 16},  // ultra
    {4096, 64, 8192, 64},  // reference: the ranges' maxima
}};

// The sea: ring grid segments (cells about 2 pi / segments of their distance), screen-space
// reflection steps (0: the sky alone, [water] reflection = sky) and waves.
struct WaterKnobs {
    int grid_segments, ssr_steps, waves;
};

constexpr std::array<WaterKnobs, 5> kWater{{
    {64, 0, 16},     // low: sky reflection only
    {96, 16, 20},    // medium
    {128, 24, 24},   // high (the defaults)
    {192, 48, 32},   // ultra
    {256, 128, 32},  // reference: the ranges' maxima for steps and waves
}};

constexpr std::array<const char*, 5> kNames{"low", "medium", "high", "ultra", "reference"};

}  // namespace

void applyQualityPreset(Settings& s, QualityPreset preset) {
    const PostKnobs& k = kPost[std::size_t(preset)];
    s.ssao.directions = k.ssao_directions;
    s.ssao.steps = k.ssao_steps;
    s.ssao.half_resolution = k.ssao_half;
    s.bloom.levels = k.bloom_levels;
    s.dof.samples = k.dof_samples;
    s.motion_blur.samples = k.motion_blur_samples;
    const ShadowKnobs& sh = kShadow[std::size_t(preset)];
    s.shadows.resolution = sh.resolution;
    s.shadows.pcf_taps = sh.pcf_taps;
    s.shadows.spot_atlas_resolution = sh.spot_atlas;
    s.shadows.spot_taps = sh.spot_taps;
    const WaterKnobs& w = kWater[std::size_t(preset)];
    s.water.grid_segments = w.grid_segments;
    s.water.reflection = w.ssr_steps > 0 ? WaterReflection::Ssr : WaterReflection::Sky;
    if (w.ssr_steps > 0) s.water.ssr_steps = w.ssr_steps;
    s.water.waves = w.waves;
}

std::optional<QualityPreset> qualityPresetFromName(std::string_view name) {
    for (std::size_t i = 0; i < kNames.size(); ++i)
        if (name == kNames[i]) return QualityPreset(i);
    return std::nullopt;
}

const char* qualityPresetName(QualityPreset preset) { return kNames[std::size_t(preset)]; }

}  // namespace vista
