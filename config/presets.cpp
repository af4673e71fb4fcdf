// The quality knobs and their value per preset. High is the shipped default (Settings{}), so a
// scene without a preset looks the same. Reference is the terrain at full resolution and every
// other knob at the top of its range, except where that is impractical on llvmpipe: a 320x180
// frame with every range's maximum took 40 s (23 s the 256^3 x 16-step aerial volume, 13 s a
// 1024x576 x 256-step sky view rebuilt every frame, 3 s a 2048^2 cloud shadow map), so the
// per-frame sky and cloud knobs stop at 2-4x their ultra value (marked "not the maximum"). The
// levels in between were tuned from `vista quality` on the default scene (README, "Quality
// against run time"): each preset sits on or near the front of image error against GPU time.
#include "config/presets.h"

#include <algorithm>

namespace vista {

namespace {

constexpr std::array<const char*, kQualityPresetCount> kNames{"low", "medium", "high", "ultra", "reference"};

int toInt(double v) { return int(v + 0.5); }

bool skyOn(const Settings& s) { return s.sky.enabled; }
bool aerialOn(const Settings& s) { return s.sky.enabled && s.sky.aerial_perspective; }
bool cloudsOn(const Settings& s) { return s.sky.enabled && s.clouds.enabled; }
bool ssaoOn(const Settings& s) { return s.ssao.enabled; }
bool postOn(const Settings& s, PostEffect e, bool enabled) {
    return s.postfx.enabled && enabled && std::find(s.postfx.order.begin(), s.postfx.order.end(), e) != s.postfx.order.end();
}

// The table: name, unit, {low, medium, high, ultra, reference}, set, get, used by the scene.
const QualityKnob kKnobs[] = {
    // Terrain: the largest vertical screen error the LOD may leave; 0 is full resolution.
    {"terrain.max_error_px", "px", {4.0, 2.0, 1.0, 0.5, 0.0},
     [](Settings& s, double v, const Settings& scene) {
         if (v <= 0.0) {
             s.terrain.lod_metric = LodMetric::Distance;
             s.terrain.base_range_m = float(kFullResolutionRangeM);
         } else {
             s.terrain.lod_metric = scene.terrain.lod_metric == LodMetric::Distance &&
                                            scene.terrain.base_range_m >= float(kFullResolutionRangeM)
                                        ? LodMetric::Error
                                        : scene.terrain.lod_metric;
             s.terrain.base_range_m = scene.terrain.base_range_m >= float(kFullResolutionRangeM)
                                          ? TerrainSettings{}.base_range_m
                                          : scene.terrain.base_range_m;
             s.terrain.max_error_px = float(v);
         }
     },
     [](const Settings& s) {
         return s.terrain.lod_metric == LodMetric::Distance && s.terrain.base_range_m >= float(kFullResolutionRangeM)
                    ? 0.0
                    : double(s.terrain.max_error_px);
     },
     [](const Settings& s) { return s.terrain.enabled; }, "full", false, true},
    // Terrain material tiers (terrain.glsl MATERIAL_TIER): detail normals and triplanar rock
    // within detail_distance_m, layer means beyond far_material_m; the reference keeps every
    // texture at every distance (the largest values of both ranges).
    {"terrain.detail_distance_m", "m", {100, 150, 250, 400, 100000},
     [](Settings& s, double v, const Settings&) { s.terrain.detail_distance_m = float(v); },
     [](const Settings& s) { return double(s.terrain.detail_distance_m); }, [](const Settings& s) { return s.terrain.enabled; }},
    {"terrain.far_material_m", "m", {1500, 2000, 3000, 6000, 1.0e7},
     [](Settings& s, double v, const Settings&) { s.terrain.far_material_m = float(v); },
     [](const Settings& s) { return double(s.terrain.far_material_m); }, [](const Settings& s) { return s.terrain.enabled; }},
    // Sun shadows (bench shadows: error halves from 1024 to 4096 texels at 2-3x the cost).
    {"shadows.resolution", "texels", {512, 1024, 1024, 2048, 4096},
     [](Settings& s, double v, const Settings&) { s.shadows.resolution = toInt(v); },
     [](const Settings& s) { return double(s.shadows.resolution); }, [](const Settings& s) { return s.shadows.enabled; }},
    {"shadows.pcf_taps", "taps", {4, 8, 12, 16, 64},
     [](Settings& s, double v, const Settings&) { s.shadows.pcf_taps = toInt(v); },
     [](const Settings& s) { return double(s.shadows.pcf_taps); },
     [](const Settings& s) { return s.shadows.enabled && s.shadows.filter != ShadowFilter::Hard; }},
    // Spot shadows (bench shadows: the hard error falls 7x from a 1024 to a 4096 atlas at 2.6x the cost).
    {"shadows.spot_atlas_resolution", "texels", {1024, 1024, 2048, 4096, 8192},
     [](Settings& s, double v, const Settings&) { s.shadows.spot_atlas_resolution = toInt(v); },
     [](const Settings& s) { return double(s.shadows.spot_atlas_resolution); },
     [](const Settings& s) { return s.shadows.enabled && s.shadows.spot_enabled; }},
    {"shadows.spot_taps", "taps", {4, 8, 16, 16, 64},
     [](Settings& s, double v, const Settings&) { s.shadows.spot_taps = toInt(v); },
     [](const Settings& s) { return double(s.shadows.spot_taps); },
     [](const Settings& s) { return s.shadows.enabled && s.shadows.spot_enabled && s.shadows.spot_filter != ShadowFilter::Hard; }},
    // Atmosphere LUTs (bench sky's rows). Reference: the transmittance and multiple-scattering
    // LUTs (built once per settings change) at their maxima but a 1024x256 transmittance; the
    // per-frame sky view (512x288, 128 steps) and aerial volume (128^2 x 128, 8 steps) not the maximum.
    {"sky.transmittance_width", "texels", {64, 128, 256, 512, 1024},
     [](Settings& s, double v, const Settings&) {
         s.sky.transmittance_width = toInt(v);
         s.sky.transmittance_height = std::max(8, toInt(v) / 4);
     },
     [](const Settings& s) { return double(s.sky.transmittance_width); }, skyOn},
    {"sky.transmittance_steps", "steps", {12, 24, 40, 80, 512},
     [](Settings& s, double v, const Settings&) { s.sky.transmittance_steps = toInt(v); },
     [](const Settings& s) { return double(s.sky.transmittance_steps); }, skyOn},
    {"sky.multiscatter_size", "texels", {16, 24, 32, 64, 128},
     [](Settings& s, double v, const Settings&) { s.sky.multiscatter_size = toInt(v); },
     [](const Settings& s) { return double(s.sky.multiscatter_size); }, skyOn},
    {"sky.multiscatter_steps", "steps", {8, 12, 20, 40, 256},
     [](Settings& s, double v, const Settings&) { s.sky.multiscatter_steps = toInt(v); },
     [](const Settings& s) { return double(s.sky.multiscatter_steps); }, skyOn},
    {"sky.sky_view_width", "texels", {64, 128, 192, 384, 512},
     [](Settings& s, double v, const Settings&) {
         s.sky.sky_view_width = toInt(v);
         s.sky.sky_view_height = std::max(16, toInt(v) * 9 / 16);
     },
     [](const Settings& s) { return double(s.sky.sky_view_width); }, skyOn},
    {"sky.sky_view_steps", "steps", {12, 20, 32, 64, 128},
     [](Settings& s, double v, const Settings&) { s.sky.sky_view_steps = toInt(v); },
     [](const Settings& s) { return double(s.sky.sky_view_steps); }, skyOn},
    {"sky.aerial_size", "froxels", {16, 24, 32, 64, 128},
     [](Settings& s, double v, const Settings&) { s.sky.aerial_size = toInt(v); },
     [](const Settings& s) { return double(s.sky.aerial_size); }, aerialOn},
    {"sky.aerial_slices", "slices", {16, 24, 32, 64, 128},
     [](Settings& s, double v, const Settings&) { s.sky.aerial_slices = toInt(v); },
     [](const Settings& s) { return double(s.sky.aerial_slices); }, aerialOn},
    {"sky.aerial_steps", "steps", {1, 1, 2, 4, 8},
     [](Settings& s, double v, const Settings&) { s.sky.aerial_steps = toInt(v); },
     [](const Settings& s) { return double(s.sky.aerial_steps); }, aerialOn},
    // Clouds: ray marching, self-shadowing, their shadow map and the noise detail per layer.
    // Reference: 8 octaves and full resolution; light samples, steps and the shadow map not the maximum.
    {"clouds.half_resolution", "", {1, 1, 1, 1, 0},
     [](Settings& s, double v, const Settings&) { s.clouds.half_resolution = v != 0.0; },
     [](const Settings& s) { return s.clouds.half_resolution ? 1.0 : 0.0; }, cloudsOn, nullptr, true, true},
    {"clouds.light_samples", "samples", {1, 2, 3, 6, 8},
     [](Settings& s, double v, const Settings&) { s.clouds.light_samples = toInt(v); },
     [](const Settings& s) { return double(s.clouds.light_samples); }, cloudsOn},
    {"clouds.shadow_size", "texels", {128, 256, 256, 512, 1024},
     [](Settings& s, double v, const Settings&) { s.clouds.shadow_size = toInt(v); },
     [](const Settings& s) { return double(s.clouds.shadow_size); },
     [](const Settings& s) { return cloudsOn(s) && s.clouds.shadows; }},
    {"clouds.low.octaves", "", {4, 4, 4, 5, 8},
     [](Settings& s, double v, const Settings&) { s.clouds.low.octaves = toInt(v); },
     [](const Settings& s) { return double(s.clouds.low.octaves); },
     [](const Settings& s) { return cloudsOn(s) && s.clouds.low.enabled; }},
    {"clouds.low.steps", "steps", {4, 6, 8, 16, 32},
     [](Settings& s, double v, const Settings&) { s.clouds.low.steps = toInt(v); },
     [](const Settings& s) { return double(s.clouds.low.steps); },
     [](const Settings& s) { return cloudsOn(s) && s.clouds.low.enabled; }},
    {"clouds.high.octaves", "", {2, 3, 3, 4, 8},
     [](Settings& s, double v, const Settings&) { s.clouds.high.octaves = toInt(v); },
     [](const Settings& s) { return double(s.clouds.high.octaves); },
     [](const Settings& s) { return cloudsOn(s) && s.clouds.high.enabled; }},
    {"clouds.high.steps", "steps", {1, 2, 2, 4, 16},
     [](Settings& s, double v, const Settings&) { s.clouds.high.steps = toInt(v); },
     [](const Settings& s) { return double(s.clouds.high.steps); },
     [](const Settings& s) { return cloudsOn(s) && s.clouds.high.enabled; }},
    // Grass: segments per near blade (density and radius change what is drawn, not how well).
    {"grass.segments", "", {2, 3, 4, 6, 8},
     [](Settings& s, double v, const Settings&) { s.grass.segments = toInt(v); },
     [](const Settings& s) { return double(s.grass.segments); },
     [](const Settings& s) { return s.grass.enabled && s.terrain.enabled; }},
    // The sea: ring grid segments (cells about 2 pi / segments of their distance), screen-space
    // reflection steps (0: the sky alone, [water] reflection = sky) and waves.
    {"water.grid_segments", "", {64, 96, 128, 192, 256},
     [](Settings& s, double v, const Settings&) { s.water.grid_segments = toInt(v); },
     [](const Settings& s) { return double(s.water.grid_segments); }, [](const Settings& s) { return s.water.enabled; }},
    {"water.ssr_steps", "steps", {0, 16, 24, 48, 128},
     [](Settings& s, double v, const Settings&) {
         s.water.reflection = v > 0.0 ? WaterReflection::Ssr : WaterReflection::Sky;
         if (v > 0.0) s.water.ssr_steps = toInt(v);
     },
     [](const Settings& s) { return s.water.reflection == WaterReflection::Sky ? 0.0 : double(s.water.ssr_steps); },
     [](const Settings& s) { return s.water.enabled; }, "sky"},
    {"water.waves", "", {16, 20, 24, 32, 32},
     [](Settings& s, double v, const Settings&) { s.water.waves = toInt(v); },
     [](const Settings& s) { return double(s.water.waves); }, [](const Settings& s) { return s.water.enabled; }},
    // Post chain. Anti-aliasing: TAA (postfx/taa.h) from medium up; the low preset keeps FXAA,
    // one full-screen pass without history.
    {"postfx.taa", "", {0, 1, 1, 1, 1},
     [](Settings& s, double v, const Settings&) {
         s.taa.enabled = v != 0.0;
         s.fxaa.enabled = v == 0.0;
     },
     [](const Settings& s) { return s.taa.enabled ? 1.0 : 0.0; }, [](const Settings& s) { return s.postfx.enabled; },
     nullptr, true},
    {"ssao.directions", "", {2, 3, 4, 8, 16},
     [](Settings& s, double v, const Settings&) { s.ssao.directions = toInt(v); },
     [](const Settings& s) { return double(s.ssao.directions); }, ssaoOn},
    {"ssao.steps", "steps", {3, 4, 4, 8, 32},
     [](Settings& s, double v, const Settings&) { s.ssao.steps = toInt(v); },
     [](const Settings& s) { return double(s.ssao.steps); }, ssaoOn},
    {"ssao.half_resolution", "", {1, 1, 1, 0, 0},
     [](Settings& s, double v, const Settings&) { s.ssao.half_resolution = v != 0.0; },
     [](const Settings& s) { return s.ssao.half_resolution ? 1.0 : 0.0; }, ssaoOn, nullptr, true, true},
    {"bloom.levels", "levels", {3, 4, 5, 6, 10},
     [](Settings& s, double v, const Settings&) { s.bloom.levels = toInt(v); },
     [](const Settings& s) { return double(s.bloom.levels); },
     [](const Settings& s) { return postOn(s, PostEffect::Bloom, s.bloom.enabled); }},
    {"dof.samples", "taps", {12, 20, 32, 64, 256},
     [](Settings& s, double v, const Settings&) { s.dof.samples = toInt(v); },
     [](const Settings& s) { return double(s.dof.samples); },
     [](const Settings& s) { return postOn(s, PostEffect::Dof, s.dof.enabled); }},
    {"motion_blur.samples", "taps", {6, 8, 12, 24, 64},
     [](Settings& s, double v, const Settings&) { s.motion_blur.samples = toInt(v); },
     [](const Settings& s) { return double(s.motion_blur.samples); },
     [](const Settings& s) { return postOn(s, PostEffect::MotionBlur, s.motion_blur.enabled); }},
};

}  // namespace

std::span<const QualityKnob> qualityKnobs() { return kKnobs; }

const QualityKnob* findQualityKnob(std::string_view name) {
    for (const QualityKnob& k : kKnobs)
        if (name == k.name) return &k;
    return nullptr;
}

void applyQualityPreset(Settings& s, QualityPreset preset) {
    const Settings scene = s;
    for (const QualityKnob& k : kKnobs) k.apply(s, k.levels[std::size_t(preset)], scene);
}

std::optional<QualityPreset> qualityPresetFromName(std::string_view name) {
    for (std::size_t i = 0; i < kNames.size(); ++i)
        if (name == kNames[i]) return QualityPreset(i);
    return std::nullopt;
}

const char* qualityPresetName(QualityPreset preset) { return kNames[std::size_t(preset)]; }

}  // namespace vista
