// Binding points shared with GLSL (renderer/shaders/bindings.glsl); a unit test checks
// that both agree.
#pragma once

namespace vista::binding {

constexpr int kFrameUniforms = 0;  // uniform block: FrameUniforms
constexpr int kCounters = 0;       // shader storage: GPU counters (uint)
constexpr int kImageOutput = 0;    // image unit written by compute passes
constexpr int kTex0 = 0;           // texture units, in the order a pass declares its inputs
constexpr int kTex1 = 1;
constexpr int kTex2 = 2;
constexpr int kTex3 = 3;
constexpr int kTex4 = 4;
constexpr int kTex5 = 5;
constexpr int kTerrainNodes = 1;   // shader storage: selected terrain node instances
constexpr int kTerrainPages = 16;  // shader storage: the streamed terrain's page table (terrain/tile_stream.h)
constexpr int kLightGrid = 1;      // uniform block: LightGrid (renderer/lighting/shaders/lights.glsl)
constexpr int kLights = 2;         // shader storage: local lights
constexpr int kLightCells = 3;     // shader storage: per tile / cluster (offset, count)
constexpr int kLightIndices = 4;   // shader storage: light index lists
constexpr int kLightHash = 5;      // shader storage: hashed light octree tables
constexpr int kLightSpheres = 6;   // shader storage: view-space bounding spheres (culling)
constexpr int kAux = 7;            // shader storage: a pass's second counter or pool
constexpr int kAux2 = 8;           // shader storage: a pass's third counter
constexpr int kLightShadeDraw = 10;  // shader storage: lights.shade's indirect draw (lights.cull sets it)
constexpr int kShadowUniforms = 2; // uniform block: ShadowUniforms (renderer/shadows/shaders/shadows.glsl)
constexpr int kShadowMap = 8;      // texture unit: sun cascades, depth compare (sampler2DArrayShadow)
constexpr int kShadowDepth = 9;    // texture unit: the same cascades, raw depth (PCSS blocker search)
constexpr int kSpotShadowUniforms = 3;  // uniform block: SpotShadowUniforms (renderer/shadows/shaders/spot_shadows.glsl)
constexpr int kSpotShadowMap = 10;      // texture unit: spot shadow atlas, depth compare (sampler2DShadow)
constexpr int kSpotShadowDepth = 11;    // texture unit: the same atlas, raw depth (PCSS blocker search, debug view)
constexpr int kPointShadowUniforms = 5;  // uniform block: PointShadowUniforms (renderer/shadows/shaders/point_shadows.glsl; 3, 4 are the water's)
constexpr int kPointShadowMap = 12;     // texture unit: point-light depth cubes, depth compare (samplerCubeArrayShadow)
constexpr int kPointShadowDepth = 13;   // texture unit: the same cubes, raw depth (PCSS blocker search, debug view)
constexpr int kGrassBlades = 8;    // shader storage: culled grass blades (terrain/grass/shaders/grass_common.glsl)
constexpr int kGrassDraws = 9;     // shader storage: grass indirect draw commands (near, far)
constexpr int kBlueNoise = 15;     // texture unit: the blue-noise map (renderer/blue_noise.h), bound every frame
constexpr int kWeatherCells = 8;   // shader storage: the rain's visible drop cells (sky/weather/shaders/weather_rain.glsl)
constexpr int kObjectInstances = 11;  // shader storage: placed objects (renderer/meshes/shaders/object_common.glsl)
constexpr int kObjectVisible = 12;    // shader storage: culled instance indices per (model, LOD) region
constexpr int kObjectCounts = 13;     // shader storage: instances kept per (model, LOD) group
constexpr int kObjectDraws = 14;      // shader storage: the indirect draw commands (instance counts set on the GPU)
constexpr int kObjectModels = 15;     // shader storage: per model bounding sphere, regions and triangles per LOD
constexpr int kAerialInscatter = 6;      // texture unit: the aerial-perspective volume's in-scattering (renderer/aerial_volume.h), forward passes
constexpr int kAerialTransmittance = 7;  // texture unit: its transmittance
constexpr int kPassBlock = 8;  // uniform block: the executing pass's own block (renderer/shaders/pass_block.glsl, renderer/pass_kit.h)

}  // namespace vista::binding
