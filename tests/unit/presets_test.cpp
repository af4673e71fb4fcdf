// Quality presets: every preset is a valid scene (the describe() ranges, through the writer and
// the loader), High is the default, and sample counts never fall from one level to the next.
#include "config/ini.h"
#include "config/presets.h"

#include <doctest/doctest.h>

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
