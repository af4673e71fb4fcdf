// The cloud layers' uniform block (std140 mirror: CloudGpu in sky/clouds/clouds.cpp), the shell
// intersection (mirrored by cloudShellSegment() in sky/clouds/cloud_model.cpp) and the density field
// shared by "clouds.shell" and "clouds.shadow". Lengths in metres; the planet frame has its
// centre at the origin and the camera at (0, c_planet.y, 0); world x/z offsets from the camera
// are the same in both frames (the curvature only enters through the radius).
#include "../../shaders/sky_bindings.glsl"
#include "cloud_noise.glsl"

#define CLOUD_MAX_LAYERS 2

struct CloudLayer {
    vec4 shell;  // x bottom radius, y top radius, z base altitude, w thickness (m)
    vec4 noise;  // xy noise coordinate of the camera's x/z (wrapped, cells), z cells per metre, w octaves
    vec4 shape;  // x coverage now, y extinction of a core (1/m), z view steps, w seed
};

layout(std140, binding = SKY_BINDING_CLOUDS) uniform CloudUniforms {
    CloudLayer c_layers[CLOUD_MAX_LAYERS];
    ivec4 c_count;   // x layers, y light samples, z and w the march subset stride (clouds_subset.glsl; 1: every pixel)
    vec4 c_planet;   // x ground radius, y camera radius, z fade-out distance, w HG g
    vec4 c_ambient;  // rgb sky radiance for the clouds (irradiance up / pi * [clouds] ambient)
    vec4 c_shadow;   // xy shadow map centre minus camera (world x/z, m), z extent (m), w camera altitude (m)
    vec4 c_sun;      // xyz unit vector towards the sun, w max(sun y, 0.05) (shadow map slant)
    vec4 c_jitter;   // xy this frame's projection jitter (NDC; TAA), which the subset march undoes, z 1: jittered
};

// Nearer and farther distance to the sphere of radius s from radius r along mu; false: missed.
bool cloudSphereRoots(float r, float mu, float s, out float t_near, out float t_far) {
    float b = r * mu, c = (r - s) * (r + s);
    float disc = b * b - c;
    t_near = t_far = 0.0;
    if (disc < 0.0) return false;
    float q = -(b + (b < 0.0 ? -sqrt(disc) : sqrt(disc)));
    float a = q, d = q != 0.0 ? c / q : 0.0;
    t_near = min(a, d);
    t_far = max(a, d);
    return true;
}

// The first stretch (x, y) of the ray inside the shell [r_bottom, r_top], cut at the ground;
// y <= x when there is none.
vec2 cloudShell(float r, float mu, float ground_r, float r_bottom, float r_top) {
    float bn, bf, tn, tf, gn, gf;
    bool hits_bottom = cloudSphereRoots(r, mu, r_bottom, bn, bf);
    bool hits_top = cloudSphereRoots(r, mu, r_top, tn, tf);
    if (!hits_top || tf <= 0.0) return vec2(0.0, -1.0);
    vec2 s;
    if (r < r_bottom) {
        s = vec2(bf, tf);
    } else {
        s.x = r > r_top ? max(tn, 0.0) : 0.0;
        s.y = hits_bottom && bn > 0.0 ? bn : tf;
    }
    if (cloudSphereRoots(r, mu, ground_r, gn, gf) && gf > 0.0) s.y = min(s.y, max(gn, 0.0));
    return s;
}

// Extinction (1/m) of layer i at camera-relative world x/z offset xz and height h01 in [0, 1]
// across the layer, from `octaves` of its fBm. The noise is stretched to [0, 1] about 0.5 and
// cut at 1 - coverage, raised towards the top (rounded tops) and faded in at the base; octaves
// that can no longer lift the sum above the cut are skipped (exact: each adds at most its
// amplitude).
float cloudDensity(int i, vec2 xz, float h01, int octaves) {
    if (h01 <= 0.0 || h01 >= 1.0) return 0.0;
    CloudLayer L = c_layers[i];
    float cells = L.noise.z;
    vec3 p = vec3(L.noise.x + xz.x * cells, h01 * L.shell.w * cells, L.noise.y + xz.y * cells);
    float cut = 1.0 - L.shape.x + 0.35 * h01 * h01;
    // Stretched fBm n' = 0.5 + 2 (n - 0.5) >= cut  <=>  n >= 0.5 + (cut - 0.5) / 2.
    float need = 0.5 + 0.5 * (cut - 0.5);
    float norm = 2.0 - exp2(1.0 - float(octaves));  // sum of the amplitudes
    float sum = 0.0, amplitude = 1.0, left = norm;
    int period = CLOUD_NOISE_PERIOD;
    uint seed = uint(L.shape.w);
    for (int k = 0; k < octaves; ++k) {
        if ((sum + left) / norm < need) return 0.0;
        sum += amplitude * cloudValueNoise(p, period, cloudOctaveSeed(seed, k));
        left -= amplitude;
        amplitude *= 0.5;
        p *= 2.0;
        period *= 2;
    }
    float n = 0.5 + 2.0 * (sum / norm - 0.5);
    float d = clamp((n - cut) * 4.0, 0.0, 1.0) * smoothstep(0.0, 0.12, h01);
    return L.shape.y * d;
}
