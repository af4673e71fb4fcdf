// The depth of field passes' uniforms: postfx/dof.cpp fills them, the dof_*.glsl passes read them.
#include "../../renderer/shaders/pass_block.glsl"
PASS_BLOCK(DofBlock)
    float u_focal_m; float u_f_stop; float u_sensor_m; float u_height_px;  // the lens; the image height (px)
    float u_manual_diopters; float u_near_m; float u_max_coc_px; float u_max_diopters;  // largest diopters: 1 / (2 f)
    float u_dt; float u_rate; float u_reset; float u_taps;  // autofocus: s since the last frame, 1/s, 1: take the target at once; gather taps
    int u_tile_mode; int u_tile_reach; int u_unused0; int u_unused1;  // tiles: 0 min CoC per tile, 1 dilate by reach tiles
PASS_BLOCK_END
