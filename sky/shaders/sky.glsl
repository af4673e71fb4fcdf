// "sky.atmosphere": sky radiance behind everything drawn (pixels still at infinite depth). Inside
// the atmosphere it comes from the sky-view LUT; from above it (orbit) each pixel ray-marches
// the part of its ray inside the atmosphere. The sun disk (limb-darkened, normalised to the
// solar irradiance) and a sunlit Lambertian ground where a ray meets the planet are added; a
// small dither hides 8-bit banding after tone mapping. Output: HDR, linear.
#include "../../renderer/shaders/fullscreen.glsl"

#ifdef FRAGMENT_SHADER
#include "../../renderer/shaders/common.glsl"
#define SKY_TEX_TRANSMITTANCE BINDING_TEX_0
#define SKY_TEX_MULTISCATTER BINDING_TEX_1
#define SKY_TRANSMITTANCE_LUT
#define SKY_MULTISCATTER_LUT
#define SKY_FOG
#include "atmosphere.glsl"
layout(binding = BINDING_TEX_2) uniform sampler2D u_sky_view;
in vec2 v_uv;
layout(location = 0) out vec4 o_color;

// Transmittance along a ray that ends on the ground, from the two upward rays (Bruneton 2017).
vec3 transmittanceToGround(float r, float mu, float d) {
    float r_d = clamp(sqrt(max(d * d + 2.0 * r * mu * d + r * r, 0.0)), bottomR(), topR());
    float mu_d = clamp((r * mu + d) / r_d, -1.0, 1.0);
    vec3 a = texture(u_transmittance, transmittanceUv(r_d, max(-mu_d, horizonMu(r_d)))).rgb;
    vec3 b = texture(u_transmittance, transmittanceUv(clamp(r, bottomR(), topR()), max(-mu, horizonMu(r)))).rgb;
    return min(a / max(b, vec3(1e-20)), vec3(1.0));
}

float hash12(vec2 p) {
    vec3 p3 = fract(vec3(p.xyx) * 0.1031);
    p3 += dot(p3, p3.yzx + 33.33);
    return fract((p3.x + p3.y) * p3.z);
}

void main() {
    vec3 dir = viewRay(v_uv);
    vec3 sun = a_sun.xyz;
    float R = bottomR(), Rt = topR();
    float r = a_radii.z;
    float mu = clamp(dir.y, -1.0, 1.0);
    float nu = clamp(dot(dir, sun), -1.0, 1.0);
    vec3 radiance;
    bool hits_ground = false;
    float t_enter = 0.0, len = 0.0;
    float r0 = r, mu0 = mu, mu_s0 = sun.y;
    bool in_atmosphere = r < Rt;
    if (in_atmosphere) {
        float above_horizon = aboveHorizon(mu);
        hits_ground = above_horizon < 0.0;
        len = hits_ground ? cameraDistanceToGround(mu) : distanceToTop(r, mu);
        vec2 h = dir.xz, s = sun.xz;
        float hl = dot(h, h), sl = dot(s, s);
        float cos_az = hl > 1e-12 && sl > 1e-12 ? dot(h, s) * inversesqrt(hl * sl) : 1.0;
        radiance = texture(u_sky_view, skyViewUv(above_horizon, cos_az)).rgb;
    } else {
        // From above the atmosphere: march from where the ray enters it.
        radiance = vec3(0.0);
        float disc = (Rt - r) * (Rt + r) + (r * mu) * (r * mu);
        if (mu < 0.0 && disc >= 0.0) {
            t_enter = (r - Rt) * (r + Rt) / (-r * mu + sqrt(disc));
            vec3 entry = vec3(0.0, r, 0.0) + t_enter * dir;
            r0 = length(entry);
            mu0 = clamp(dot(entry, dir) / r0, -1.0, 1.0);
            mu_s0 = clamp(dot(entry, sun) / r0, -1.0, 1.0);
            hits_ground = intersectsGround(r0, mu0);
            len = hits_ground ? distanceToGround(r0, mu0) : distanceToTop(r0, mu0);
            radiance = integrateRay(r0, mu0, mu_s0, nu, len, a_sizes2.w, 0).radiance;
        } else {
            hits_ground = false;
        }
    }
    radiance *= a_solar.xyz;
    if (hits_ground) {
        // Sunlit ground seen through the atmosphere (no skylight on it).
        float mu_s_g = clamp((r0 * mu_s0 + len * nu) / R, -1.0, 1.0);
        vec3 t_view = transmittanceToGround(r0, mu0, len);
        if (mu_s_g > 0.0)
            radiance += t_view * (a_albedo.xyz / PI) * mu_s_g * transmittanceToTop(R, mu_s_g) * a_solar.xyz;
    } else {
        // The sun disk: I(c) = 1 - u (1 - c), c = cos of the angle from the limb's normal.
        float alpha = a_misc.z, u = a_misc.w;
        float cos_alpha = cos(alpha);
        if (nu > cos_alpha) {
            float x = safeSqrt(1.0 - nu * nu) / max(sin(alpha), 1e-6);
            float limb = 1.0 - u * (1.0 - safeSqrt(1.0 - x * x));
            float norm = 1.0 / (PI * alpha * alpha * (1.0 - u / 3.0));
            vec3 t_sun = r0 <= Rt ? transmittanceToTop(r0, mu0) : vec3(1.0);
            radiance += a_solar.xyz * t_sun * limb * norm;
        }
    }
    // Dither: +-0.5 of an 8-bit step, relative (the tone curve is roughly logarithmic). Seeded by
    // the scene time, not the frame index: the same scene at the same time renders the same image
    // whatever was drawn before it (captures, saved scenes and golden images compare frames).
    float noise = hash12(gl_FragCoord.xy + fract(u_time.x * 0.618034) * 97.0) + hash12(gl_FragCoord.yx + 13.7) - 1.0;
    radiance *= 1.0 + noise / 255.0;
    o_color = vec4(clamp(radiance, vec3(0.0), vec3(60000.0)), 1.0);
}
#endif
