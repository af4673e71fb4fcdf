// The variants of the local lights' passes: "lights.cull" (shaders/light_cull.glsl) and
// "lights.shade" (shaders/light_shade.glsl). The passes ask for defines(); all() is every
// variant a frame can request, for allPrograms() and the shader test.
#pragma once

#include "renderer/lighting/light_settings.h"
#include "renderer/program_key.h"

#include <string>
#include <vector>

namespace vista {

// The shaders' name of a culling method (LIGHTS_NAIVE, _TILED, _CLUSTERED, _HASHED).
inline const char* lightMethodDefine(LightCulling m) {
    switch (m) {
        case LightCulling::Naive: return "LIGHTS_NAIVE";
        case LightCulling::Tiled: return "LIGHTS_TILED";
        case LightCulling::Clustered: return "LIGHTS_CLUSTERED";
        case LightCulling::Hashed: return "LIGHTS_HASHED";
    }
    return "LIGHTS_NAIVE";
}

inline constexpr LightCulling kLightMethods[] = {LightCulling::Naive, LightCulling::Tiled, LightCulling::Clustered,
                                                  LightCulling::Hashed};

// Tiled and clustered build per-tile lists on the GPU ("lights.cull"); naive and hashed do not.
inline bool screenCulled(LightCulling m) { return m == LightCulling::Tiled || m == LightCulling::Clustered; }

struct LightCullVariant {
    static constexpr const char* kFile = "renderer/lighting/shaders/light_cull.glsl";
    LightCulling method = LightCulling::Tiled;  // tiled or clustered (screenCulled())
    bool forward = false;                       // LIGHTS_FORWARD: lists also for transparent depths

    std::vector<std::string> defines() const {
        std::vector<std::string> d = {lightMethodDefine(method)};
        if (forward) d.push_back("LIGHTS_FORWARD");
        return d;
    }
    ProgramKey key() const { return {kFile, defines()}; }
    static std::vector<LightCullVariant> all() {
        std::vector<LightCullVariant> out;
        for (LightCulling m : kLightMethods)
            for (bool forward : {false, true})
                if (screenCulled(m)) out.push_back({m, forward});
        return out;
    }
};

struct LightShadeVariant {
    static constexpr const char* kFile = "renderer/lighting/shaders/light_shade.glsl";
    LightCulling method = LightCulling::Naive;
    bool count = false;          // COUNT_LIGHTS: lights.evaluations and lights.exact
    bool heat = false;           // LIGHT_HEAT: evaluations per pixel (lights debug view, heat readback)
    bool spot_shadows = false;   // HAS_SPOT_SHADOWS: the spot atlas
    bool point_shadows = false;  // HAS_POINT_SHADOWS: the point cubes

    std::vector<std::string> defines() const {
        std::vector<std::string> d = {lightMethodDefine(method)};
        if (count) d.push_back("COUNT_LIGHTS");
        if (heat) d.push_back("LIGHT_HEAT");
        if (spot_shadows) d.push_back("HAS_SPOT_SHADOWS");
        if (point_shadows) d.push_back("HAS_POINT_SHADOWS");
        return d;
    }
    ProgramKey key() const { return {kFile, defines()}; }
    // Every method with every combination of the four switches (each is set independently:
    // counters by the caller, heat by the debug view or a readback, shadows by the scene).
    static std::vector<LightShadeVariant> all() {
        std::vector<LightShadeVariant> out;
        for (LightCulling m : kLightMethods)
            for (unsigned bits = 0; bits < 16; ++bits) out.push_back({m, bool(bits & 1), bool(bits & 2), bool(bits & 4), bool(bits & 8)});
        return out;
    }
};

}  // namespace vista
