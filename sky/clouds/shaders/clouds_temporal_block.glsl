// clouds.temporal's uniforms: sky/clouds/clouds.cpp fills them, clouds_temporal.glsl reads them.
#include "../../../renderer/shaders/pass_block.glsl"
PASS_BLOCK(CloudsTemporalBlock)
    mat4 u_prev_clip;  // the previous frame's unjittered clip from this camera's relative space
    vec4 u_shift;      // xyz this camera minus the previous one (m), w march subset stride (1: every pixel marched)
    vec4 u_params;     // x blend, y 1: history rejected everywhere, zw this frame's jitter (NDC)
    vec4 u_motion;     // x the sample count's decay per pixel of parallax ([clouds] temporal_parallax_decay)
PASS_BLOCK_END
