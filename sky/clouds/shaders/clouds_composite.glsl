// "clouds.composite": the half-resolution clouds (premultiplied radiance, coverage) upsampled
// bilinearly over the full-size image, blended as hdr = rgb + hdr * (1 - a). A pixel whose
// geometry lies nearer than every layer's shell along its ray keeps no cloud (the half-size
// pass cut its rays at the farthest geometry of each 2x2 block).
#include "../../../renderer/shaders/fullscreen.glsl"

#ifdef FRAGMENT_SHADER
#include "../../../renderer/shaders/common.glsl"
#include "../../../renderer/shaders/gbuffer.glsl"
#include "clouds_common.glsl"
layout(binding = BINDING_TEX_0) uniform sampler2D u_clouds;
layout(binding = BINDING_TEX_1) uniform sampler2D u_depth;
in vec2 v_uv;
layout(location = 0) out vec4 o_color;

void main() {
    float depth = texelFetch(u_depth, ivec2(gl_FragCoord.xy), 0).r;
    if (depth > 0.0) {
        float t_scene = length(positionFromDepth(v_uv, depth));
        float mu = clamp(viewRay(v_uv).y, -1.0, 1.0);
        bool behind = true;
        for (int i = 0; i < c_count.x; ++i) {
            vec2 s = cloudShell(c_planet.y, mu, c_planet.x, c_layers[i].shell.x, c_layers[i].shell.y);
            if (s.y > s.x && s.x < t_scene) behind = false;
        }
        if (behind) discard;
    }
    vec4 c = texture(u_clouds, v_uv);
    if (c.a <= 0.0 && dot(c.rgb, vec3(1.0)) <= 0.0) discard;
    o_color = c;
}
#endif
