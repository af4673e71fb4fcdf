// postfx.taa's uniforms: postfx/taa.cpp fills them, taa.glsl reads them.
#include "../../renderer/shaders/pass_block.glsl"
PASS_BLOCK(TaaBlock)
    vec4 u_jitter;  // xy this frame's jitter (NDC), z near plane (m), w disocclusion tolerance (fraction of the distance)
    vec4 u_params;  // x blend, y clip gamma, z sharpen, w 1: history rejected (cut, first frame)
PASS_BLOCK_END
