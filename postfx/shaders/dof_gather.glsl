// "postfx.dof.gather": per pixel, u_taps taps on a Vogel disk of radius R = max(own |CoC|,
// the near tiles' radius), each tap weighted by how much its own disc covers this pixel:
// coverage = clamp(r - distance + 0.5, 0, 1), over the disc's area r^2 (a pixel's light spreads
// over its disc).
// - Far field (CoC >= 0): r = min(tap CoC, own CoC), so a tap behind this pixel spreads no
//   further than this pixel's own blur (the sharp object in front stays sharp). A near pixel
//   sees the far taps around it unweighted (what lies behind the foreground).
// - Near field (CoC < 0): r = the tap's own radius; the layer's opacity is the share of the
//   pixel the foreground discs cover, sum(coverage * R^2 / (taps * r^2)), so a blurred
//   foreground edge fades over the sharp background.
// In focus (R < 0.5) the pixel is copied. DOF_DEBUG (a variant): red far, green near, blue in focus.
#include "../../renderer/shaders/fullscreen.glsl"

#ifdef FRAGMENT_SHADER
#include "postfx_bindings.glsl"
#include "../../renderer/shaders/bindings.glsl"
layout(binding = BINDING_TEX_0) uniform sampler2D u_coc;   // rgb colour (sanitised), a signed CoC (px)
layout(binding = BINDING_TEX_1) uniform sampler2D u_near;  // dilated near radius per tile
#include "dof_block.glsl"
layout(location = 0) out vec4 o_color;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    ivec2 size = textureSize(u_coc, 0);
    vec4 centre = texelFetch(u_coc, p, 0);
    float own = centre.a;
#ifdef DOF_DEBUG
    float t = clamp(abs(own) / u_max_coc_px, 0.0, 1.0);
    o_color = abs(own) < 0.5 ? vec4(0.0, 0.0, 1.0, 1.0) : own > 0.0 ? vec4(t, 0.0, 0.0, 1.0) : vec4(0.0, t, 0.0, 1.0);
#else
    float radius = max(abs(own), texelFetch(u_near, p / DOF_TILE, 0).r);
    if (radius < 0.5) {
        o_color = vec4(centre.rgb, 1.0);
        return;
    }
    int taps = int(u_taps);
    vec3 far_sum = vec3(0.0), near_sum = vec3(0.0);
    float far_w = 0.0, near_w = 0.0, cover = 0.0;
    if (own >= 0.0) {
        far_sum = centre.rgb / max(own * own, 0.25);
        far_w = 1.0 / max(own * own, 0.25);
    }
    for (int i = 0; i < taps; ++i) {
        float dist = radius * sqrt((float(i) + 0.5) / float(taps));
        float angle = float(i) * 2.39996323;  // the golden angle
        ivec2 q = clamp(p + ivec2(round(dist * vec2(cos(angle), sin(angle)))), ivec2(0), size - 1);
        vec4 s = texelFetch(u_coc, q, 0);
        float d = length(vec2(q - p));
        if (s.a >= 0.0) {
            float w = 1.0;
            if (own >= 0.0) {
                float r = min(s.a, own);
                w = clamp(r - d + 0.5, 0.0, 1.0) / max(r * r, 0.25);
            }
            far_sum += s.rgb * w;
            far_w += w;
        } else {
            float r = -s.a;
            float coverage = clamp(r - d + 0.5, 0.0, 1.0);
            float w = coverage / max(r * r, 0.25);
            near_sum += s.rgb * w;
            near_w += w;
            cover += coverage * radius * radius / (float(taps) * max(r * r, 0.25));
        }
    }
    vec3 far = far_w > 0.0 ? far_sum / far_w : vec3(0.0);
    vec3 near = near_w > 0.0 ? near_sum / near_w : vec3(0.0);
    float alpha = far_w > 0.0 ? (near_w > 0.0 ? clamp(cover, 0.0, 1.0) : 0.0) : 1.0;
    vec3 c = near_w > 0.0 || far_w > 0.0 ? mix(far, near, alpha) : centre.rgb;
    o_color = vec4(c, 1.0);
#endif
}
#endif
