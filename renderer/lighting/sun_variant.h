// The variants of "lighting.sun" (renderer/lighting/shaders/sun.glsl): what the pass reads
// (SSAO, the clouds' shadow map, the sun's cascades) and its debug output. The pass asks for
// defines(); all() is every variant a frame can request, for allPrograms() and the shader test.
#pragma once

#include "renderer/program_key.h"

#include <string>
#include <vector>

namespace vista {

struct SunVariant {
    enum class Debug { None, Cascades, ShadowTerm };  // [debug] view = cascades, shadow
    static constexpr const char* kFile = "renderer/lighting/shaders/sun.glsl";

    bool ao = false;            // HAS_AO: the ambient times targets.ao
    bool cloud_shadow = false;  // HAS_CLOUD_SHADOW: the sun times the clouds' shadow map
    bool sun_shadow = false;    // HAS_SUN_SHADOW: the sun times the cascades
    Debug debug = Debug::None;  // SHADOW_CASCADE_VIEW (needs sun_shadow), SHADOW_TERM_VIEW
    bool pcss = true;           // false: SHADOW_NO_PCSS, the cascades' filter is hard or pcf (needs sun_shadow)

    // The rules between the fields: the cascade view tints by cascade, so it needs cascades
    // (without them the pass asks for no debug define); so does a filter.
    bool valid() const { return (debug != Debug::Cascades || sun_shadow) && (pcss || sun_shadow); }

    std::vector<std::string> defines() const {
        std::vector<std::string> d;
        if (ao) d.push_back("HAS_AO");
        if (cloud_shadow) d.push_back("HAS_CLOUD_SHADOW");
        if (sun_shadow) d.push_back("HAS_SUN_SHADOW");
        if (!pcss) d.push_back("SHADOW_NO_PCSS");
        if (debug == Debug::Cascades) d.push_back("SHADOW_CASCADE_VIEW");
        if (debug == Debug::ShadowTerm) d.push_back("SHADOW_TERM_VIEW");
        return d;
    }
    ProgramKey key() const { return {kFile, defines()}; }

    // Every valid combination of the fields.
    static std::vector<SunVariant> all() {
        std::vector<SunVariant> out;
        for (bool ao : {false, true})
            for (bool cloud : {false, true})
                for (bool shadow : {false, true})
                    for (Debug debug : {Debug::None, Debug::Cascades, Debug::ShadowTerm})
                        for (bool pcss : {true, false})
                            if (SunVariant v{ao, cloud, shadow, debug, pcss}; v.valid()) out.push_back(v);
        return out;
    }
};

}  // namespace vista
