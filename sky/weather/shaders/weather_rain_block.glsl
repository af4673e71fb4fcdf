// weather.rain's uniforms: sky/weather/weather.cpp fills them, weather_rain.glsl reads them.
#include "../../../renderer/shaders/pass_block.glsl"
PASS_BLOCK(WeatherRainBlock)
    ivec4 u_box_min;  // the box's min field cell (wrapped), cells per side
    ivec4 u_layout;   // cells from the camera's to the box edge, drops drawn per cell, count (1), unused
    vec4 u_frac;      // camera inside its cell (0..1) xyz, cell size (m)
    vec4 u_motion;    // drop velocity relative to the camera (m/s), streak time (s)
    vec4 u_shape;     // radius (m), near fade (m), drop width (m), intensity x drops per cell
    vec4 u_ambient;   // sky light a drop sends back (radiance rgb), opacity
    vec4 u_sun;       // sun light a drop sends back (radiance rgb), unused
    vec4 u_sway;      // snow: amplitude (m), phase (rad), angular rate (rad/s), unused
    // RAIN_VELOCITY only (weather.velocity):
    mat4 u_prev_clip;       // previous clip from this camera's relative space
    vec4 u_camera_motion;   // the camera's velocity (m/s), the time since the previous frame (s)
    vec4 u_velocity_cover;  // this frame's jitter (NDC) xy, the drop opacity above which a pixel takes its motion, unused
PASS_BLOCK_END
