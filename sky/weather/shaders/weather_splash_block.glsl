// weather.splash's uniforms: sky/weather/weather.cpp fills them, weather_splash.glsl reads them.
#include "../../../renderer/shaders/pass_block.glsl"
PASS_BLOCK(WeatherSplashBlock)
    ivec4 u_layout;   // cells per side, cells from the camera's to the edge, slots drawn per cell, count (1)
    vec4 u_cycle;     // camera inside its cell (0..1) x, z, cycle fraction, slots kept (j + keep below it)
    vec4 u_look;      // crown radius (m), draw radius (m), opacity, cell size (m)
    vec4 u_ambient;   // sky light sent back (radiance rgb), unused
    vec4 u_sun;       // sun light sent back (radiance rgb), unused
    vec2 u_map_min; vec2 u_texel_m;  // camera-relative x, z of heightmap texel (0, 0) (m); metres between samples in x, z
    vec2 u_height_map; ivec2 u_box;  // height = offset + scale * sample: (scale, offset - camera y); the box's min ground cell x, z (wrapped)
    ivec4 u_tiles;    // the height texture's tiles (terrain/shaders/tiles.glsl)
    vec4 u_tile_layer;
    uvec4 u_cycle_index;  // x: floor(t / period), low 32 bits
PASS_BLOCK_END
