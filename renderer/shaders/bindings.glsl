// Binding points shared by C++ (renderer/bindings.h) and GLSL. Only #defines and //
// comments: tests/unit/bindings_test.cpp includes this file as C++ to check both agree.
#define BINDING_FRAME_UNIFORMS 0
#define BINDING_COUNTERS 0
#define BINDING_IMAGE_OUTPUT 0
#define BINDING_TEX_0 0
#define BINDING_TEX_1 1
#define BINDING_TEX_2 2
#define BINDING_TEX_3 3
#define BINDING_TEX_4 4
#define BINDING_TERRAIN_NODES 1
#define BINDING_LIGHT_GRID 1
#define BINDING_LIGHTS 2
#define BINDING_LIGHT_CELLS 3
#define BINDING_LIGHT_INDICES 4
#define BINDING_LIGHT_HASH 5
#define BINDING_LIGHT_SPHERES 6
#define BINDING_AUX 7
#define BINDING_SHADOW_UNIFORMS 2
#define BINDING_SHADOW_MAP 8
#define BINDING_SHADOW_DEPTH 9
#define BINDING_SPOT_SHADOW_UNIFORMS 3
#define BINDING_SPOT_SHADOW_MAP 10
#define BINDING_SPOT_SHADOW_DEPTH 11
#define BINDING_GRASS_BLADES 8
#define BINDING_GRASS_DRAWS 9
#define BINDING_BLUE_NOISE 15
#define BINDING_WEATHER_CELLS 8
