// "clouds.shell": the cloud layers over the image, after the sky. Each pixel's view ray is cut
// to the first stretch inside each layer's spherical shell (and to the scene's depth, so
// terrain in front of a cloud hides it and a cloud in front of terrain covers it), the
// stretches are marched nearest first with a per-pixel jittered start, and each sample is lit
// by the sun (its irradiance through the atmosphere's transmittance LUT at the sample, so the
// clouds redden at dawn and dusk, Henyey-Greenstein forward scattering, a few samples towards
// the sun for self-shadowing) and the sky's ambient light. The result fades into the aerial
// perspective by the atmosphere's transmittance from the camera to the clouds: the sky already
// in the image stands for the haze in front of them. Output: premultiplied radiance and
// coverage, blended as hdr = rgb + hdr * (1 - a); with HALF_RES into a half-size target that
// clouds_composite.glsl blends over the image. With TEMPORAL (half or full size) into a target
// of its own, plus the clouds' mean distance (attachment 1) along which clouds_temporal.glsl
// reprojects the history. The start offset is spatiotemporal blue noise, so the error of one
// frame is fine-grained and a pixel's offsets over frames are evenly spread (accumulated by
// "clouds.temporal"). Variant SUBSET, the subset march (c_count.z = stride > 1, clouds_subset.glsl): the target is
// 1/stride of the cloud target's size and each texel marches the pixel of its block that this frame
// stands for; the blue-noise index then counts that pixel's own visits (every stride^2 frames).
// A frame without history marches every pixel even so (the variant without SUBSET, c_count.w > 1).
#include "../../../renderer/shaders/fullscreen.glsl"

#ifdef FRAGMENT_SHADER
#include "../../../renderer/shaders/common.glsl"
#include "../../../renderer/shaders/gbuffer.glsl"
#define SKY_TEX_TRANSMITTANCE BINDING_TEX_0
#define SKY_TRANSMITTANCE_LUT
#include "../../shaders/atmosphere.glsl"
#include "clouds_common.glsl"
#include "../../../renderer/shaders/blue_noise.glsl"
#ifdef SUBSET
#include "clouds_subset.glsl"
#endif
layout(binding = BINDING_TEX_1) uniform sampler2D u_depth;
in vec2 v_uv;
layout(location = 0) out vec4 o_color;
#ifdef TEMPORAL
layout(location = 1) out float o_distance;  // m, the clouds' mean distance along the ray (0: none)
#endif

float hgPhase(float c, float g) {
    float denom = max(1.0 + g * g - 2.0 * g * c, 1e-6);
    return (1.0 - g * g) / (4.0 * PI * denom * sqrt(denom));
}

// Transmittance of the atmosphere between the camera (radius r km, cosine mu) and a point d km
// along the ray, from the LUT's rays to the top (Bruneton 2017); 1 outside the atmosphere.
vec3 viewTransmittance(float r, float mu, float d) {
    float entry = atmosphereEntry(r, mu);
    if (entry < 0.0 || d <= entry) return vec3(1.0);
    if (entry > 0.0) {
        float r_e = sqrt(max(entry * entry + 2.0 * r * mu * entry + r * r, 0.0));
        mu = clamp((r * mu + entry) / r_e, -1.0, 1.0);
        d -= entry;
        r = r_e;
    }
    r = clamp(r, bottomR(), topR());
    float r_d = clamp(sqrt(max(d * d + 2.0 * r * mu * d + r * r, 0.0)), bottomR(), topR());
    float mu_d = clamp((r * mu + d) / r_d, -1.0, 1.0);
    vec3 t;
    if (mu >= 0.0 || !intersectsGround(r, mu))
        t = transmittanceToTop(r, mu) / max(transmittanceToTop(r_d, mu_d), vec3(1e-20));
    else
        t = transmittanceToTop(r_d, -mu_d) / max(transmittanceToTop(r, -mu), vec3(1e-20));
    return clamp(t, vec3(0.0), vec3(1.0));
}

void main() {
    // This texel's pixel of the cloud target and its uv (the same as v_uv without a subset).
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec2 uv = v_uv;
    uint noise_frame = uint(u_time.z);
#ifdef SUBSET
    int stride = c_count.z;
#ifdef HALF_RES
    ivec2 size = (textureSize(u_depth, 0) + 1) / 2;
#else
    ivec2 size = textureSize(u_depth, 0);
#endif
    pixel = pixel * stride + cloudSubsetOffset(stride, noise_frame);
    if (any(greaterThanEqual(pixel, size))) discard;
    uv = (vec2(pixel) + 0.5) / vec2(size);
    noise_frame /= uint(stride * stride);
    // A pixel's visits come every stride^2 frames, each at the same phase of TAA's jitter, so that
    // jitter would never cover the pixel: it is undone, and with TAA (c_jitter.z) each visit takes
    // its own sub-pixel offset (the R2 sequence over the visits), so the history averages the
    // whole pixel as TAA's does.
    vec2 own = c_jitter.z * (fract(0.5 + float(noise_frame) * vec2(0.7548776662, 0.5698402910)) - 0.5);
    vec2 ray_uv = uv + 0.5 * c_jitter.xy + own / vec2(size);
#else
    if (c_count.w > 1) {
        // A whole march of a subset configuration (a frame without history): the visit before
        // every pixel's first subset visit, so no two visits of a pixel share a noise frame.
        noise_frame = noise_frame / uint(c_count.w * c_count.w) - 1u;
    }
    vec2 ray_uv = uv;
#endif
    vec3 dir = viewRay(ray_uv);
    vec3 sun = a_sun.xyz;
    float rc = c_planet.y, mu = clamp(dir.y, -1.0, 1.0);
    float t_scene = 1e30;
#ifdef HALF_RES
    // One texel for 2x2 pixels: cut at the farthest of them (clouds.composite hides the clouds
    // behind nearer geometry per pixel).
    ivec2 full = textureSize(u_depth, 0) - 1;
    ivec2 q = pixel * 2;
    float depth = min(min(texelFetch(u_depth, min(q, full), 0).r, texelFetch(u_depth, min(q + ivec2(1, 0), full), 0).r),
                      min(texelFetch(u_depth, min(q + ivec2(0, 1), full), 0).r, texelFetch(u_depth, min(q + 1, full), 0).r));
#else
    float depth = texelFetch(u_depth, pixel, 0).r;
#endif
    if (depth > 0.0) t_scene = length(positionFromDepth(uv, depth));

    // The layers' stretches, nearest first.
    vec2 seg[CLOUD_MAX_LAYERS];
    int order[CLOUD_MAX_LAYERS];
    int n = 0;
    for (int i = 0; i < c_count.x; ++i) {
        vec2 s = cloudShell(rc, mu, c_planet.x, c_layers[i].shell.x, c_layers[i].shell.y);
        s.y = min(s.y, min(t_scene, c_planet.z));
        seg[i] = s;
        if (s.y <= s.x) continue;
        int j = n++;
        while (j > 0 && seg[order[j - 1]].x > s.x) {
            order[j] = order[j - 1];
            --j;
        }
        order[j] = i;
    }
    if (n == 0) discard;

    float nu = dot(dir, sun);
    float g = c_planet.w;
    float phase = mix(hgPhase(nu, g), hgPhase(nu, -0.3), 0.25);
    float jitter = blueNoise(pixel, noise_frame, 0);
    float fade_start = 0.6 * c_planet.z;
    vec3 radiance = vec3(0.0);
    float transmittance = 1.0, weight = 0.0, t_weighted = 0.0;
    for (int o = 0; o < n && transmittance > 0.01; ++o) {
        int i = order[o];
        CloudLayer L = c_layers[i];
        int steps = int(L.shape.z), octaves = int(L.noise.w);
        int light_octaves = max(octaves - 2, 1);
        float dt = (seg[i].y - seg[i].x) / float(steps);
        float light_step = L.shell.w / float(max(c_count.y, 1));
        for (int k = 0; k < steps && transmittance > 0.01; ++k) {
            float t = seg[i].x + (float(k) + jitter) * dt;
            vec3 p = vec3(0.0, rc, 0.0) + t * dir;
            float r = length(p);
            float h01 = (r - L.shell.x) / L.shell.w;
            float sigma = cloudDensity(i, t * dir.xz, h01, octaves);
            sigma *= 1.0 - smoothstep(fade_start, c_planet.z, t);
            if (sigma <= 0.0) continue;
            // The sun's light at the sample: through the atmosphere, then through the layer.
            float mu_s = dot(p, sun) / r;
            float r_km = r * 1e-3;
            vec3 sun_light = sunVisible(r_km, mu_s) > 0.0 ? sunlightRgb(transmittanceToTop(r_km, mu_s)) : vec3(0.0);
            float tau = 0.0;
            if (any(greaterThan(sun_light, vec3(0.0))))
                for (int j = 0; j < c_count.y; ++j) {
                    vec3 q = p + (float(j) + 0.5) * light_step * sun;
                    float hq = (length(q) - L.shell.x) / L.shell.w;
                    tau += cloudDensity(i, t * dir.xz + (float(j) + 0.5) * light_step * sun.xz, hq, light_octaves) * light_step;
                }
            // Beer's law for the direct light, plus a softer, less forward term for the light
            // scattered more than once (it reaches deeper into the cloud).
            vec3 j_sun = sun_light * (phase * exp(-tau) + 0.5 / (4.0 * PI) * exp(-0.1 * tau));
            vec3 j_amb = c_ambient.rgb * mix(0.45, 1.0, clamp(h01, 0.0, 1.0));
            float e = exp(-sigma * dt);
            float absorbed = transmittance * (1.0 - e);
            radiance += absorbed * (j_sun + j_amb);
            t_weighted += absorbed * t;
            weight += absorbed;
            transmittance *= e;
        }
    }
    float alpha = 1.0 - transmittance;
    if (alpha <= 0.0) discard;
    float t_mean = weight > 0.0 ? t_weighted / weight : 0.0;
    vec3 aerial = viewTransmittance(a_radii.z, mu, t_mean * 1e-3);
    float aerial_mean = dot(aerial, vec3(1.0 / 3.0));
    o_color = vec4(clamp(radiance * aerial, vec3(0.0), vec3(60000.0)), alpha * aerial_mean);
#ifdef TEMPORAL
    o_distance = t_mean;
#endif
}
#endif
