// "water.underwater": with the camera at or below the surface, the water between the eye and
// what each pixel shows (the surface from below, the sea floor, nothing: deep water) absorbs
// and scatters: hdr = hdr * e^(-sigma d) + scattered light * (1 - e^(-sigma d)), by dual-source
// blending like the aerial perspective. A pixel is under water when its ray's point on the near
// plane is below the wave height there, so a camera at the water line splits the image cleanly.
#include "../../../renderer/shaders/fullscreen.glsl"

#ifdef FRAGMENT_SHADER
#include "../../../renderer/shaders/common.glsl"
#include "../../../renderer/shaders/gbuffer.glsl"
#include "waves.glsl"
layout(binding = BINDING_TEX_0) uniform sampler2D u_depth;
in vec2 v_uv;
layout(location = 0, index = 0) out vec4 o_inscatter;
layout(location = 0, index = 1) out vec4 o_transmittance;

void main() {
    vec3 ray = viewRay(v_uv);
    float forward = max(-(mat3(u_view) * ray).z, 1e-3);
    vec3 near_point = ray * (u_near.x / forward);
    // Deeper than any trough reaches: every pixel is under water, no wave to evaluate. Else the
    // waves longer than about 1 m decide (the split line needs no ripples).
    float surface = w_surface.x;
    if (near_point.y > w_surface.x - w_misc.x) {
        surface += evaluateWaves(near_point.xz, 0.15).displacement.y;
        if (near_point.y >= surface) discard;
    }
    float depth = texelFetch(u_depth, ivec2(gl_FragCoord.xy), 0).r;
    float d = depth > 0.0 ? length(positionFromDepth(v_uv, depth)) : 1e6;
    vec3 sigma = w_absorption.rgb;
    vec3 transmittance = exp(-sigma * min(d, 1e4));
    // Daylight reaching the eye's depth, scattered towards it by the water along the ray.
    vec3 e_down = (w_sun.rgb * max(u_sun_dir.y, 0.0) + w_sky_up.rgb) * exp(-sigma * min(surface - near_point.y, 1e4));
    vec3 inscatter = w_scatter.rgb * e_down / 3.14159265 * (1.0 - transmittance);
    o_inscatter = vec4(clamp(inscatter, vec3(0.0), vec3(60000.0)), 0.0);
    o_transmittance = vec4(transmittance, 1.0);
}
#endif
