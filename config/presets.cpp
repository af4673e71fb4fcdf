// The quality knobs and their value per preset. High is the shipped default (Settings{}), so a
// scene without a preset looks the same. Reference is the terrain at full resolution and every
// other knob at the top of its range, except where that is impractical on llvmpipe: a 320x180
// frame with every range's maximum took 40 s (23 s the 256^3 x 16-step aerial volume, 13 s a
// 1024x576 x 256-step sky view rebuilt every frame, 3 s a 2048^2 cloud shadow map), so the
// per-frame sky and cloud knobs stop at 2-4x their ultra value (marked "not the maximum"). The
// levels in between were tuned from `vista quality` on the default scene (docs/quality.md, "Quality
// against run time"): each preset sits on or near the front of image error against GPU time.
#include "config/presets.h"

#include "config/visitor.h"

#include <algorithm>
#include <cassert>
#include <cstring>
#include <string>

namespace vista {

namespace {

constexpr std::array<const char*, kQualityPresetCount> kNames{"low", "medium", "high", "ultra", "reference"};

int toInt(double v) { return int(v + 0.5); }

// Whether the scene uses a knob (a disabled feature's knob changes nothing).
bool terrainOn(const Settings& s) { return s.terrain.enabled; }
bool shadowsOn(const Settings& s) { return s.shadows.enabled; }
bool shadowFilterOn(const Settings& s) { return s.shadows.enabled && s.shadows.filter != ShadowFilter::Hard; }
bool spotShadowsOn(const Settings& s) { return s.shadows.enabled && s.shadows.spot_enabled; }
bool spotFilterOn(const Settings& s) { return spotShadowsOn(s) && s.shadows.spot_filter != ShadowFilter::Hard; }
bool skyOn(const Settings& s) { return s.sky.enabled; }
bool aerialOn(const Settings& s) { return s.sky.enabled && s.sky.aerial_perspective; }
bool cloudsOn(const Settings& s) { return s.sky.enabled && s.clouds.enabled; }
bool cloudShadowsOn(const Settings& s) { return cloudsOn(s) && s.clouds.shadows; }
bool lowCloudsOn(const Settings& s) { return cloudsOn(s) && s.clouds.low.enabled; }
bool highCloudsOn(const Settings& s) { return cloudsOn(s) && s.clouds.high.enabled; }
bool grassOn(const Settings& s) { return s.grass.enabled && s.terrain.enabled; }
bool waterOn(const Settings& s) { return s.water.enabled; }
bool objectsOn(const Settings& s) { return s.terrain.enabled && objectsWanted(s.objects); }
bool ssaoOn(const Settings& s) { return s.ssao.enabled; }
bool postOn(const Settings& s, PostEffect e, bool enabled) {
    return s.postfx.enabled && enabled && std::find(s.postfx.order.begin(), s.postfx.order.end(), e) != s.postfx.order.end();
}
bool bloomOn(const Settings& s) { return postOn(s, PostEffect::Bloom, s.bloom.enabled); }
bool dofOn(const Settings& s) { return postOn(s, PostEffect::Dof, s.dof.enabled); }
bool motionBlurOn(const Settings& s) { return postOn(s, PostEffect::MotionBlur, s.motion_blur.enabled); }

// The knobs that set several keys together; every other knob is its one key, set and read
// through the settings visitor (keyValue below).
void setTerrainError(Settings& s, double v, const Settings& scene) {
    if (v <= 0.0) {
        s.terrain.lod_metric = LodMetric::Distance;
        s.terrain.base_range_m = float(kFullResolutionRangeM);
        return;
    }
    const bool scene_full = scene.terrain.base_range_m >= float(kFullResolutionRangeM);
    s.terrain.lod_metric = scene.terrain.lod_metric == LodMetric::Distance && scene_full ? LodMetric::Error
                                                                                        : scene.terrain.lod_metric;
    s.terrain.base_range_m = scene_full ? TerrainSettings{}.base_range_m : scene.terrain.base_range_m;
    s.terrain.max_error_px = float(v);
}
double terrainError(const Settings& s) {
    return s.terrain.lod_metric == LodMetric::Distance && s.terrain.base_range_m >= float(kFullResolutionRangeM)
               ? 0.0
               : double(s.terrain.max_error_px);
}
void setTransmittance(Settings& s, double v, const Settings&) {
    s.sky.transmittance_width = toInt(v);
    s.sky.transmittance_height = std::max(8, toInt(v) / 4);
}
void setSkyView(Settings& s, double v, const Settings&) {
    s.sky.sky_view_width = toInt(v);
    s.sky.sky_view_height = std::max(16, toInt(v) * 9 / 16);
}
void setSsrSteps(Settings& s, double v, const Settings&) {
    s.water.reflection = v > 0.0 ? WaterReflection::Ssr : WaterReflection::Sky;
    if (v > 0.0) s.water.ssr_steps = toInt(v);
}
double ssrSteps(const Settings& s) { return s.water.reflection == WaterReflection::Sky ? 0.0 : double(s.water.ssr_steps); }
bool postfxOn(const Settings& s) { return s.postfx.enabled; }
void setTaa(Settings& s, double v, const Settings&) {
    s.taa.enabled = v != 0.0;
    s.fxaa.enabled = v == 0.0;
}
double taaOn(const Settings& s) { return s.taa.enabled ? 1.0 : 0.0; }
// Parallax occlusion mapping: 0 is off (no program variant), otherwise its linear steps.
void setPomSteps(Settings& s, double v, const Settings&) {
    s.terrain.pom.enabled = v > 0.0;
    if (v > 0.0) s.terrain.pom.max_steps = toInt(v);
}
double pomSteps(const Settings& s) { return s.terrain.pom.enabled ? double(s.terrain.pom.max_steps) : 0.0; }
// Tessellated displacement: 0 is off (no program variant), otherwise the largest edge factor.
void setTessFactor(Settings& s, double v, const Settings&) {
    s.terrain.tessellation.enabled = v > 0.0;
    if (v > 0.0) s.terrain.tessellation.max_factor = float(v);
}
double tessFactor(const Settings& s) {
    return s.terrain.tessellation.enabled ? double(s.terrain.tessellation.max_factor) : 0.0;
}

// The table: key, unit, {low, medium, high, ultra, reference}, whether the scene uses it.
const QualityKnob kKnobs[] = {
    // Terrain: the largest vertical screen error the LOD may leave; 0 is full resolution.
    {"terrain.max_error_px", "px", {4.0, 2.0, 1.0, 0.5, 0.0}, terrainOn, setTerrainError, terrainError, "full", false, true},
    // Terrain material tiers (terrain.glsl MATERIAL_TIER): detail normals and triplanar rock
    // within detail_distance_m, layer means beyond far_material_m; the reference keeps every
    // texture at every distance (the largest values of both ranges).
    {"terrain.detail_distance_m", "m", {100, 150, 250, 400, 100000}, terrainOn},
    {"terrain.far_material_m", "m", {1500, 2000, 3000, 6000, 1.0e7}, terrainOn},
    // Material filtering and relief up close (docs/terrain-detail.md): anisotropic filtering
    // of the material textures; parallax occlusion mapping's linear steps and tessellation's
    // largest edge factor from ultra up (0: off, no program variant), and the tessellated range
    // (it counts only where the factor is on). Ultra's factor 8: the eye-height meadow at
    // 640x360 costs 1.08x of off (16: 1.38x; docs/terrain-detail.md). The reference: 128 steps,
    // the largest factor (32, where llvmpipe's tessellator still works) over twice the range.
    {"terrain.material_anisotropy", "x", {1, 1, 1, 8, 16}, terrainOn},
    {"terrain.pom.max_steps", "steps", {0, 0, 0, 24, 128}, terrainOn, setPomSteps, pomSteps, "off"},
    {"terrain.tessellation.max_factor", "", {0, 0, 0, 8, 32}, terrainOn, setTessFactor, tessFactor, "off"},
    {"terrain.tessellation.range_m", "m", {40, 40, 40, 40, 80}, terrainOn},
    // Sun shadows (bench shadows: error halves from 1024 to 4096 texels at 2-3x the cost).
    {"shadows.resolution", "texels", {512, 1024, 1024, 2048, 4096}, shadowsOn},
    {"shadows.pcf_taps", "taps", {4, 8, 12, 16, 64}, shadowFilterOn},
    // Terrain casters coarser than the view draws them (docs/shadows.md); 0: full detail.
    {"shadows.caster_step_texels", "texels", {4, 2, 1, 0.5, 0}, shadowsOn, nullptr, nullptr, "full", false, true},
    // Spot shadows (bench shadows: the hard error falls 7x from a 1024 to a 4096 atlas at 2.6x the cost).
    {"shadows.spot_atlas_resolution", "texels", {1024, 1024, 2048, 4096, 8192}, spotShadowsOn},
    {"shadows.spot_taps", "taps", {4, 8, 16, 16, 64}, spotFilterOn},
    // Atmosphere LUTs (bench sky's rows). Reference: the transmittance and multiple-scattering
    // LUTs (built once per settings change) at their maxima but a 1024x256 transmittance; the
    // per-frame sky view (512x288, 128 steps) and aerial volume (128^2 x 128, 8 steps) not the maximum.
    // The transmittance width also sets the height (width / 4), the sky view's width its height (9/16).
    {"sky.transmittance_width", "texels", {64, 128, 256, 512, 1024}, skyOn, setTransmittance},
    {"sky.transmittance_steps", "steps", {12, 24, 40, 80, 512}, skyOn},
    {"sky.multiscatter_size", "texels", {16, 24, 32, 64, 128}, skyOn},
    {"sky.multiscatter_steps", "steps", {8, 12, 20, 40, 256}, skyOn},
    {"sky.sky_view_width", "texels", {64, 128, 192, 384, 512}, skyOn, setSkyView},
    {"sky.sky_view_steps", "steps", {12, 20, 32, 64, 128}, skyOn},
    {"sky.aerial_size", "froxels", {16, 24, 32, 64, 128}, aerialOn},
    {"sky.aerial_slices", "slices", {16, 24, 32, 64, 128}, aerialOn},
    {"sky.aerial_steps", "steps", {1, 1, 2, 4, 8}, aerialOn},
    // Clouds: ray marching, self-shadowing, their shadow map and the noise detail per layer.
    // Reference: 8 octaves and full resolution; light samples, steps and the shadow map not the maximum.
    // High and ultra march 1 of 16 pixels a frame ([clouds] march_subset, docs/temporal.md) and
    // spend the 16x saved on the reference's march (full size, 8 octaves, 32/16 steps, 8 light samples);
    // low and medium march their cheaper, noisier march at every pixel (a subset of it would
    // stay grainy in motion), the reference every pixel of its own.
    {"clouds.march_subset", "pixels", {1, 1, 16, 16, 1}, cloudsOn, nullptr, nullptr, nullptr, false, true, true},
    {"clouds.half_resolution", "", {1, 1, 0, 0, 0}, cloudsOn, nullptr, nullptr, nullptr, true, true},
    {"clouds.light_samples", "samples", {1, 2, 8, 8, 8}, cloudsOn},
    {"clouds.shadow_size", "texels", {128, 256, 256, 512, 1024}, cloudShadowsOn},
    {"clouds.low.octaves", "", {4, 4, 8, 8, 8}, lowCloudsOn},
    {"clouds.low.steps", "steps", {4, 6, 32, 32, 32}, lowCloudsOn},
    {"clouds.high.octaves", "", {2, 3, 8, 8, 8}, highCloudsOn},
    {"clouds.high.steps", "steps", {1, 2, 16, 16, 16}, highCloudsOn},
    // Grass: segments per near blade (density and radius change what is drawn, not how well).
    {"grass.segments", "", {2, 3, 4, 6, 8}, grassOn},
    // Objects: the mesh LOD distances and where octahedral impostors take over; the reference
    // draws every instance as its full mesh.
    {"objects.lod1_distance_m", "m", {30, 45, 60, 100, 1.0e5}, objectsOn},
    {"objects.lod2_distance_m", "m", {120, 180, 250, 400, 1.0e5}, objectsOn},
    {"objects.impostor_distance_m", "m", {80, 110, 150, 300, 1.0e6}, objectsOn},
    // The sea: ring grid segments (cells about 2 pi / segments of their distance), screen-space
    // reflection steps (0: the sky alone, [water] reflection = sky) and waves.
    {"water.grid_segments", "", {64, 96, 128, 192, 256}, waterOn},
    {"water.ssr_steps", "steps", {0, 16, 24, 48, 128}, waterOn, setSsrSteps, ssrSteps, "sky"},
    {"water.waves", "", {16, 20, 24, 32, 32}, waterOn},
    // Post chain (keys of [postfx.NAME]). Anti-aliasing: TAA (postfx/taa.h) from medium up; the
    // low preset keeps FXAA, one full-screen pass without history.
    {"postfx.taa", "", {0, 1, 1, 1, 1}, postfxOn, setTaa, taaOn, nullptr, true},
    {"ssao.directions", "", {2, 3, 4, 8, 16}, ssaoOn},
    {"ssao.steps", "steps", {3, 4, 4, 8, 32}, ssaoOn},
    {"ssao.half_resolution", "", {1, 1, 1, 0, 0}, ssaoOn, nullptr, nullptr, nullptr, true, true},
    {"bloom.levels", "levels", {3, 4, 5, 6, 10}, bloomOn},
    {"dof.samples", "taps", {12, 20, 32, 64, 256}, dofOn},
    {"motion_blur.samples", "taps", {6, 8, 12, 24, 64}, motionBlurOn},
};

// Sets (set = true) or reads the field whose key is name: "section.key", or "NAME.key" for
// [postfx.NAME]. A number field takes value as it is (an int rounded), a flag value != 0.
class KeyValue final : public SettingsVisitor {
public:
    KeyValue(std::string_view name, bool set, double value) : name_(name), set_(set), value_(value) {}
    bool found = false;
    double value() const { return value_; }

    void section(const char* name, const char*) override {
        section_ = name;
        if (section_.rfind("postfx.", 0) == 0) section_.erase(0, 7);
    }
    void field(const FieldInfo& info, bool& v) override {
        if (match(info)) set_ ? void(v = value_ != 0.0) : void(value_ = v ? 1.0 : 0.0);
    }
    void field(const FieldInfo& info, int& v, int, int) override {
        if (match(info)) set_ ? void(v = toInt(value_)) : void(value_ = double(v));
    }
    void field(const FieldInfo& info, float& v, float, float) override {
        if (match(info)) set_ ? void(v = float(value_)) : void(value_ = double(v));
    }
    void field(const FieldInfo& info, double& v, double, double) override {
        if (match(info)) set_ ? void(v = value_) : void(value_ = v);
    }
    void field(const FieldInfo&, glm::vec3&, float, float) override {}
    void field(const FieldInfo&, glm::dvec3&, double, double) override {}
    void field(const FieldInfo&, std::string&) override {}
    void choice(const FieldInfo&, int&, std::span<const char* const>) override {}
    void list(const FieldInfo&, ListField&) override {}

private:
    bool match(const FieldInfo& info) {
        const bool hit = name_.size() == section_.size() + 1 + std::strlen(info.key) && name_.rfind(section_, 0) == 0 &&
                         name_[section_.size()] == '.' && name_.substr(section_.size() + 1) == info.key;
        found = found || hit;
        return hit;
    }
    std::string_view name_;
    bool set_;
    double value_;
    std::string section_;
};

double keyValue(const char* name, Settings& s, bool set, double value) {
    KeyValue v(name, set, value);
    describe(v, s);
    assert(v.found && "a quality knob names no numeric or flag setting");
    return v.value();
}

}  // namespace

void QualityKnob::apply(Settings& s, double value, const Settings& scene) const {
    if (set)
        set(s, value, scene);
    else
        keyValue(name, s, true, value);
}

double QualityKnob::get(const Settings& s) const {
    if (read) return read(s);
    Settings copy = s;  // describe() takes a mutable struct; reading changes nothing
    return keyValue(name, copy, false, 0.0);
}

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
