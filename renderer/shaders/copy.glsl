// Full-screen copy of an RGBA16F texture: the cost unit ("one copy") of the stats.
#include "fullscreen.glsl"

#ifdef FRAGMENT_SHADER
#include "bindings.glsl"
layout(binding = BINDING_TEX_0) uniform sampler2D u_source;
layout(location = 0) out vec4 o_color;
void main() {
    o_color = texelFetch(u_source, ivec2(gl_FragCoord.xy), 0);
}
#endif
