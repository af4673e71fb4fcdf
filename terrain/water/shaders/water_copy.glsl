// "water.copy": the opaque scene as the deferred lighting left it, copied before the water is
// drawn over it: colour for refraction and screen-space reflection, depth as R32F (the surface
// pass writes the depth target while it reads this).
#include "../../../renderer/shaders/fullscreen.glsl"

#ifdef FRAGMENT_SHADER
#include "../../../renderer/shaders/bindings.glsl"
layout(binding = BINDING_TEX_0) uniform sampler2D u_hdr;
layout(binding = BINDING_TEX_1) uniform sampler2D u_depth;
layout(location = 0) out vec4 o_color;
layout(location = 1) out float o_depth;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    o_color = texelFetch(u_hdr, p, 0);
    o_depth = texelFetch(u_depth, p, 0).r;
}
#endif
