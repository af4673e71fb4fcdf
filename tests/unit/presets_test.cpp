// Quality presets: every preset is a valid scene (the describe() ranges, through the writer and
// the loader), High is the default, and sample counts never fall from one level to the next.
#include "config/ini.h"
#include "config/presets.h"

#include <doctest/doctest.h>

#include <string_view>

using namespace vista;

TEST_CASE("presets: each is valid, high is the default, and the quality knobs grow with the level") {
    const QualityPreset levels[] = {QualityPreset::Low, QualityPreset::Medium, QualityPreset::High,
                                    QualityPreset::Ultra, QualityPreset::Reference};
    Settings previous;
    for (std::size_t i = 0; i < std::size(levels); ++i) {
        Settings s;
        applyQualityPreset(s, levels[i]);
        INFO(qualityPresetName(levels[i]));
        Settings back;
        CHECK(loadIniString(saveIniString(s), "preset.ini", back).empty());  // within every range
        CHECK(qualityPresetFromName(qualityPresetName(levels[i])) == levels[i]);
        if (i > 0) {
            CHECK(s.ssao.directions >= previous.ssao.directions);
            CHECK(s.ssao.steps >= previous.ssao.steps);
            CHECK((!s.ssao.half_resolution || previous.ssao.half_resolution));
            CHECK(s.bloom.levels >= previous.bloom.levels);
            CHECK(s.dof.samples >= previous.dof.samples);
            CHECK(s.motion_blur.samples >= previous.motion_blur.samples);
            CHECK(s.shadows.resolution >= previous.shadows.resolution);
            CHECK(s.shadows.pcf_taps >= previous.shadows.pcf_taps);
            CHECK(s.shadows.spot_atlas_resolution >= previous.shadows.spot_atlas_resolution);
            CHECK(s.shadows.spot_taps >= previous.shadows.spot_taps);
            CHECK(s.water.grid_segments >= previous.water.grid_segments);
            CHECK(s.water.waves >= previous.water.waves);
            CHECK((s.water.reflection == WaterReflection::Ssr || previous.water.reflection == WaterReflection::Sky));
            if (previous.water.reflection == WaterReflection::Ssr) CHECK(s.water.ssr_steps >= previous.water.ssr_steps);
            CHECK(s.dof.samples + s.motion_blur.samples + s.ssao.directions * s.ssao.steps >
                  previous.dof.samples + previous.motion_blur.samples + previous.ssao.directions * previous.ssao.steps);
        }
        previous = s;
    }
    Settings high;
    applyQualityPreset(high, QualityPreset::High);
    Settings defaults;
    CHECK(saveIniString(high) == saveIniString(defaults));
    CHECK_FALSE(qualityPresetFromName("extreme"));
}

TEST_CASE("presets: every knob of the table grows finer with the level, and get reads back what apply set") {
    const Settings scene;
    for (const QualityKnob& k : qualityKnobs()) {
        INFO(k.name);
        CHECK(findQualityKnob(k.name) == &k);
        for (int i = 0; i < kQualityPresetCount; ++i) {
            Settings s;
            applyQualityPreset(s, QualityPreset(i));
            CHECK(k.get(s) == doctest::Approx(k.levels[std::size_t(i)]));
            Settings one = scene;
            k.apply(one, k.levels[std::size_t(i)], scene);
            CHECK(k.get(one) == doctest::Approx(k.levels[std::size_t(i)]));
            Settings back;
            CHECK(loadIniString(saveIniString(one), "knob.ini", back).empty());
            if (i > 0 && !k.trade) {
                if (k.descending)
                    CHECK(k.levels[std::size_t(i)] <= k.levels[std::size_t(i - 1)]);
                else
                    CHECK(k.levels[std::size_t(i)] >= k.levels[std::size_t(i - 1)]);
            }
        }
        // Depth of field, motion blur and the sea are off in Settings{} (default.ini turns the sea
        // on), and it places no objects (default.ini does): their knobs change nothing there.
        const std::string_view name = k.name;
        const bool off_by_default = name == "dof.samples" || name == "motion_blur.samples" || name.rfind("water.", 0) == 0 ||
                                    name.rfind("objects.", 0) == 0;
        CHECK(k.active(scene) == !off_by_default);
    }
    CHECK_FALSE(findQualityKnob("terrain.height_scale_m"));
}

TEST_CASE("presets: the reference draws the terrain at full resolution and a sweep away from it restores the scene's LOD") {
    Settings scene;
    scene.terrain.base_range_m = 300.0f;
    Settings ref = scene;
    applyQualityPreset(ref, QualityPreset::Reference);
    CHECK(ref.terrain.lod_metric == LodMetric::Distance);
    CHECK(ref.terrain.base_range_m >= float(kFullResolutionRangeM));
    const QualityKnob& terrain = *findQualityKnob("terrain.max_error_px");
    CHECK(terrain.get(ref) == 0.0);
    terrain.apply(ref, 2.0, scene);
    CHECK(ref.terrain.lod_metric == LodMetric::Error);
    CHECK(ref.terrain.base_range_m == 300.0f);
    CHECK(ref.terrain.max_error_px == 2.0f);
    // A preset over the reference brings the LOD back too.
    applyQualityPreset(ref, QualityPreset::Reference);
    applyQualityPreset(ref, QualityPreset::Low);
    CHECK(ref.terrain.lod_metric == LodMetric::Error);
    CHECK(ref.terrain.max_error_px == 4.0f);
}
