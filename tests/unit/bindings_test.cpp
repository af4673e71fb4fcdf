// The binding points C++ uses must be the ones GLSL declares: the GLSL header is plain
// #defines, so it is included here as C++ and compared.
#include "renderer/bindings.h"
#include "renderer/shaders/bindings.glsl"
#include "renderer/shaders/pass_block.glsl"

#include <doctest/doctest.h>

TEST_CASE("bindings: C++ constants match renderer/shaders/bindings.glsl") {
    using namespace vista;
    CHECK(binding::kFrameUniforms == BINDING_FRAME_UNIFORMS);
    CHECK(binding::kCounters == BINDING_COUNTERS);
    CHECK(binding::kImageOutput == BINDING_IMAGE_OUTPUT);
    CHECK(binding::kTex0 == BINDING_TEX_0);
    CHECK(binding::kTex1 == BINDING_TEX_1);
    CHECK(binding::kTex2 == BINDING_TEX_2);
    CHECK(binding::kTex3 == BINDING_TEX_3);
    CHECK(binding::kTex4 == BINDING_TEX_4);
    CHECK(binding::kTex5 == BINDING_TEX_5);
    CHECK(binding::kTerrainNodes == BINDING_TERRAIN_NODES);
    CHECK(binding::kTerrainPages == BINDING_TERRAIN_PAGES);
    CHECK(binding::kLightGrid == BINDING_LIGHT_GRID);
    CHECK(binding::kLights == BINDING_LIGHTS);
    CHECK(binding::kLightCells == BINDING_LIGHT_CELLS);
    CHECK(binding::kLightIndices == BINDING_LIGHT_INDICES);
    CHECK(binding::kLightHash == BINDING_LIGHT_HASH);
    CHECK(binding::kLightSpheres == BINDING_LIGHT_SPHERES);
    CHECK(binding::kAux == BINDING_AUX);
    CHECK(binding::kAux2 == BINDING_AUX_2);
    CHECK(binding::kLightShadeDraw == BINDING_LIGHT_SHADE_DRAW);
    CHECK(binding::kShadowUniforms == BINDING_SHADOW_UNIFORMS);
    CHECK(binding::kShadowMap == BINDING_SHADOW_MAP);
    CHECK(binding::kShadowDepth == BINDING_SHADOW_DEPTH);
    CHECK(binding::kSpotShadowUniforms == BINDING_SPOT_SHADOW_UNIFORMS);
    CHECK(binding::kSpotShadowMap == BINDING_SPOT_SHADOW_MAP);
    CHECK(binding::kSpotShadowDepth == BINDING_SPOT_SHADOW_DEPTH);
    CHECK(binding::kPointShadowUniforms == BINDING_POINT_SHADOW_UNIFORMS);
    CHECK(binding::kPointShadowMap == BINDING_POINT_SHADOW_MAP);
    CHECK(binding::kPointShadowDepth == BINDING_POINT_SHADOW_DEPTH);
    CHECK(binding::kBlueNoise == BINDING_BLUE_NOISE);
    CHECK(binding::kGrassBlades == BINDING_GRASS_BLADES);
    CHECK(binding::kGrassDraws == BINDING_GRASS_DRAWS);
    CHECK(binding::kWeatherCells == BINDING_WEATHER_CELLS);
    CHECK(binding::kObjectInstances == BINDING_OBJECT_INSTANCES);
    CHECK(binding::kObjectVisible == BINDING_OBJECT_VISIBLE);
    CHECK(binding::kObjectCounts == BINDING_OBJECT_COUNTS);
    CHECK(binding::kObjectDraws == BINDING_OBJECT_DRAWS);
    CHECK(binding::kObjectModels == BINDING_OBJECT_MODELS);
    CHECK(binding::kAerialInscatter == BINDING_AERIAL_INSCATTER);
    CHECK(binding::kAerialTransmittance == BINDING_AERIAL_TRANSMITTANCE);
    CHECK(binding::kPassBlock == BINDING_PASS_BLOCK);
}
