// "postfx.exposure.apply": multiplies the image by the exposure scale, when the effect after
// exposure in the chain is not the tone map (which applies it itself).
#include "../../renderer/shaders/fullscreen.glsl"

#ifdef FRAGMENT_SHADER
#include "../../renderer/shaders/bindings.glsl"
#include "exposure.glsl"
layout(binding = BINDING_TEX_0) uniform sampler2D u_image;
#include "exposure_block.glsl"
layout(location = 0) out vec4 o_color;

void main() {
    vec4 c = texelFetch(u_image, ivec2(gl_FragCoord.xy), 0);
    o_color = vec4(c.rgb * exposureScale(u_exposure), c.a);
}
#endif
