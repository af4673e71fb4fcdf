// The bloom passes' uniforms: postfx/bloom.cpp fills them, bloom_down.glsl and bloom_up.glsl read them.
#include "../../renderer/shaders/pass_block.glsl"
PASS_BLOCK(BloomBlock)
    vec2 u_texel; float u_clamp; float u_mix;  // down: 1 / source size, highlight clamp (first level); up: mix weight
PASS_BLOCK_END
