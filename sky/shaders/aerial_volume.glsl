// "sky.aerial_volume": the aerial-perspective froxel volume (Hillaire 2020). For a grid of view
// rays through the screen (aerial size x size, edge to edge) and depth slices at distance
// range * ((k + 1) / slices)^2 (dense near the camera), the in-scattered radiance (HDR linear
// sRGB: skyRgb of the three samples, a linear map, so interpolating after it is the same) and
// the transmittance (rgb) from the camera to the end of each slice, both
// integrated exactly per step for a constant medium, as the sky-view LUT does. The slices lie
// side by side in two 2D atlases (slice k at x = k * size) so the frame graph can pool them
// (renderer/aerial_volume.h: the glass reads them too).
#ifdef COMPUTE_SHADER
#include "../../renderer/shaders/common.glsl"
#define SKY_TEX_TRANSMITTANCE BINDING_TEX_0
#define SKY_TEX_MULTISCATTER BINDING_TEX_1
#define SKY_TRANSMITTANCE_LUT
#define SKY_MULTISCATTER_LUT
#define SKY_FOG
#include "atmosphere.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba16f, binding = BINDING_IMAGE_OUTPUT) uniform writeonly image2D u_inscatter;
layout(rgba16f, binding = SKY_IMAGE_AERIAL_TRANSMITTANCE) uniform writeonly image2D u_aerial_transmittance;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    int size = int(a_aerial.y), slices = int(a_aerial.z), steps = int(a_aerial.w);
    if (p.x >= size || p.y >= size) return;
    // Froxel columns span the screen edge to edge (the first and last on the borders), so no
    // pixel is extrapolated: the haze towards the sun changes fast across the screen.
    vec3 dir = viewRay(vec2(p) / float(size - 1));
    vec3 sun = a_sun.xyz;
    float r = a_radii.z, mu = clamp(dir.y, -1.0, 1.0), mu_s = clamp(sun.y, -1.0, 1.0);
    float nu = clamp(dot(dir, sun), -1.0, 1.0);
    float phase_r = rayleighPhase(nu), phase_m = miePhase(nu);
    vec3 radiance = vec3(0.0), transmittance = vec3(1.0);
    float t_prev = 0.0;
    for (int k = 0; k < slices; ++k) {
        float x = float(k + 1) / float(slices);
        float t_end = a_aerial.x * x * x;
        float dt = (t_end - t_prev) / float(steps);
        for (int i = 0; i < steps; ++i) {
            vec3 j, ext;
            viewSample(r, mu, mu_s, nu, phase_r, phase_m, t_prev + (float(i) + 0.5) * dt, j, ext);
            vec3 step_t = exp(-ext * dt);
            radiance += transmittance * (vec3(1.0) - step_t) / ext * j;
            transmittance *= step_t;
        }
        t_prev = t_end;
        ivec2 texel = ivec2(k * size + p.x, p.y);
        imageStore(u_inscatter, texel, vec4(clamp(skyRgb(radiance), vec3(0.0), vec3(60000.0)), 1.0));
        imageStore(u_aerial_transmittance, texel, vec4(transmittance, 1.0));
    }
}
#endif
