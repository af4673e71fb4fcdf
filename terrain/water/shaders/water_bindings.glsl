// Binding points and limits of the water's own GL resources, shared by C++ (terrain/water/water.cpp and
// terrain/water/waves.h include this file) and GLSL. Only #defines and // comments.
// Uniform blocks 0..2 are taken (frame, light grid or atmosphere, shadows or clouds): the water
// block and the atmosphere block the water shader reads (it also reads the light grid at 1).
#define WATER_BINDING_UNIFORMS 3
#define WATER_BINDING_ATMOSPHERE 4
#define WATER_MAX_WAVES 32
