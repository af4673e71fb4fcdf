// "sky.atmosphere": sky radiance behind everything drawn (pixels still at infinite depth). Inside
// the atmosphere it comes from the sky-view LUT; from above it (orbit) each pixel ray-marches
// the part of its ray inside the atmosphere. The sun disk (limb-darkened, normalised to the
// solar irradiance) and a sunlit Lambertian ground where a ray meets the planet are added; a
// small dither hides 8-bit banding after tone mapping. Output: HDR, linear.
#include "../../renderer/shaders/common.glsl"
#if defined(VERTEX_SHADER) && defined(SKY_CLIP)
// The full-screen triangle clipped to the view rays pointing up (SKY_CLIP 1) or down (-1) from
// the horizontal, each side with a sliver of the other: a ray pointing up never meets the planet,
// so the upper part takes the variant without the ground (atmosphere.cpp draws the lower part
// second, over the sliver). A ray's height is affine on the screen, so the clip is exact.
out vec2 v_uv;
out float gl_ClipDistance[1];
void main() {
    vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
    v_uv = p;
    gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
    vec4 q = u_inv_view_proj * vec4(p * 2.0 - 1.0, 0.5, 1.0);
    vec3 ray = q.xyz / q.w;
    gl_ClipDistance[0] = float(SKY_CLIP) * ray.y + 1e-3 * length(ray);
}
#else
#include "../../renderer/shaders/fullscreen.glsl"
#endif

#ifdef FRAGMENT_SHADER
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

// The moon: a sphere of albedo a_night.y lit by the sun (the sun is far, so it lights the moon
// from the same direction as the earth: the phase follows from the angle between them), with
// the Lommel-Seeliger law that makes the full moon a flat disk: L = E albedo / pi *
// 2 cos_i / (cos_i + cos_e). cover: the fraction of the pixel the disk covers (antialiased edge).
// Grey, per unit of the solar irradiance: the caller multiplies by the sunlight's colour through
// the air in front of the moon (sunlightRgb).
float moonRadiance(vec3 dir, vec3 sun, float pixel_rad, out float cover) {
    vec3 m = a_moon.xyz;
    float radius = a_moon.w;
    float cos_angle = dot(dir, m);
    cover = 0.0;
    if (cos_angle < cos(radius + 2.0 * pixel_rad)) return 0.0;
    vec3 side = dir - m * cos_angle;
    float angle = atan(length(side), cos_angle);
    cover = clamp((radius - angle) / max(pixel_rad, 1e-7) + 0.5, 0.0, 1.0);
    float x = min(angle / radius, 1.0);
    vec3 n = -m * sqrt(1.0 - x * x) + safeNormalize(side) * x;  // the visible hemisphere's normal
    float cos_i = dot(n, sun), cos_e = max(sqrt(1.0 - x * x), 1e-3);
    if (cos_i <= 0.0) return 0.0;
    return cover * (a_night.y / PI) * 2.0 * cos_i / (cos_i + cos_e);
}

vec3 hash33(vec3 p) {
    p = fract(p * vec3(0.1031, 0.1030, 0.0973));
    p += dot(p, p.yxz + 33.33);
    return fract((p.xxy + p.yxx) * p.zyx);
}

// A fixed field of stars on the celestial sphere (it turns with the sky in sun_mode = time):
// cube faces of 160^2 cells, a star in a third of them at a random spot, peak brightness 1
// for the brightest and a power law below (a night-adapted exposure, ~2^16, shows a few
// hundred in a 60 deg view), a random colour temperature; each star a
// Gaussian about a pixel wide, from the pixel's cell and its eight neighbours. A star fades out
// as the sky behind it brightens from 1% to 10% of its peak (faint ones first, as at dusk).
vec3 starField(vec3 dir, float pixel_rad, float sky_luminance) {
    vec3 c = vec3(dot(a_celestial[0].xyz, dir), dot(a_celestial[1].xyz, dir), dot(a_celestial[2].xyz, dir));
    vec3 a = abs(c);
    float face;
    vec2 uv;
    if (a.x >= a.y && a.x >= a.z) {
        face = c.x > 0.0 ? 0.0 : 1.0;
        uv = c.yz / a.x;
    } else if (a.y >= a.z) {
        face = c.y > 0.0 ? 2.0 : 3.0;
        uv = c.xz / a.y;
    } else {
        face = c.z > 0.0 ? 4.0 : 5.0;
        uv = c.xy / a.z;
    }
    const float cells = 160.0;
    vec2 g = (uv * 0.5 + 0.5) * cells;
    vec2 cell0 = floor(g);
    float sigma = max(0.6 * pixel_rad, 1e-5), cell_rad = 0.5 * PI / cells;
    vec3 sum = vec3(0.0);
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            vec2 cell = cell0 + vec2(dx, dy);
            if (any(lessThan(cell, vec2(0.0))) || any(greaterThanEqual(cell, vec2(cells)))) continue;
            vec3 h = hash33(vec3(cell, face * 191.0 + 7.0));
            if (h.z > 0.33) continue;
            // Distance on the face, as an angle (the face's own distortion is below 2x).
            vec2 d = (cell + 0.15 + 0.7 * h.xy - g) * cell_rad;
            // Star counts grow as brightness^-1.25 (10^(0.5 m) stars per magnitude) from the
            // brightest (1, about one over the sky) through ~1500 above 0.3% of it to ~50,000
            // above 0.02%: under a night-adapted exposure the faint end stays below visibility.
            float brightness = min(1.0, pow(max(1.0 - h.z / 0.33, 1e-9), -0.8) / 5750.0);
            vec3 tint = mix(vec3(1.0, 0.78, 0.6), vec3(0.75, 0.85, 1.0), fract(h.x * 7.13 + h.y * 3.7));
            float peak = a_night.x * brightness;
            float contrast = smoothstep(10.0, 100.0, peak / max(sky_luminance, 1e-30));
            sum += tint * (peak * contrast) * exp(-dot(d, d) / (2.0 * sigma * sigma));
        }
    return sum;
}

void main() {
    vec3 dir = viewRay(gl_FragCoord.xy * u_viewport.zw);  // the pixel's centre, however the triangle was clipped
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
    radiance = skyRgb(radiance);
    if (hits_ground) {
#ifndef SKY_NO_GROUND
        // Sunlit ground seen through the atmosphere (no skylight on it); the sunlight's colour
        // after both paths, the sun's to the ground and the ground's to the camera.
        float mu_s_g = clamp((r0 * mu_s0 + len * nu) / R, -1.0, 1.0);
        vec3 t_view = transmittanceToGround(r0, mu0, len);
        if (mu_s_g > 0.0)
            radiance += (a_albedo.xyz / PI) * mu_s_g * sunlightRgb(t_view * transmittanceToTop(R, mu_s_g));
#endif
    } else {
        // Transmittance to what lies beyond the atmosphere, fetched only where something does.
        vec3 t_view = vec3(1.0);
        float pixel_rad = 2.0 / (u_proj[1][1] * u_viewport.y);
        float sky_luminance = dot(radiance, vec3(0.2126, 0.7152, 0.0722));
        // The moon in front of the sun and the stars (an eclipse shows its dark side).
        // Each only in the variant of a view that can show it (SKY_MOON, SKY_SUN_DISK, SKY_STARS;
        // atmosphere.cpp skyShows()): a shader core runs a branch's body for every pixel.
        float moon_cover = 0.0;
#ifdef SKY_MOON
        float moon = a_night.z > 0.5 ? moonRadiance(dir, sun, pixel_rad, moon_cover) : 0.0;
#else
        const float moon = 0.0;
#endif
        // The sun disk: I(c) = 1 - u (1 - c), c = cos of the angle from the limb's normal.
        float alpha = a_misc.z, u = a_misc.w;
        float cos_alpha = cos(alpha);
#ifdef SKY_SUN_DISK
        bool sun_disk = nu > cos_alpha;
#else
        const bool sun_disk = false;
#endif
#ifdef SKY_STARS
        bool stars_visible = a_night.x > 10.0 * sky_luminance && moon_cover < 1.0;
#else
        const bool stars_visible = false;
#endif
        if ((sun_disk || moon_cover > 0.0 || stars_visible) && r0 <= Rt) t_view = transmittanceToTop(r0, mu0);
        // Sunlight through the air in front of the camera, in colour: the sun disk and the moon.
        vec3 sunlight = (sun_disk || moon > 0.0) ? sunlightRgb(t_view) : vec3(0.0);
        if (sun_disk) {
            float x = safeSqrt(1.0 - nu * nu) / max(sin(alpha), 1e-6);
            float limb = 1.0 - u * (1.0 - safeSqrt(1.0 - x * x));
            float norm = 1.0 / (PI * alpha * alpha * (1.0 - u / 3.0));
            radiance += (1.0 - moon_cover) * sunlight * limb * norm;
        }
        radiance += sunlight * moon + a_night.w;  // airglow and unresolved starlight: the night's floor
        // Each star fades out as the sky behind it brightens from 1% to 10% of its own peak.
        if (stars_visible)
            radiance += t_view * (1.0 - moon_cover) * starField(dir, pixel_rad, sky_luminance);
    }
    // Dither: +-0.5 of an 8-bit step, relative (the tone curve is roughly logarithmic). Seeded by
    // the scene time, not the frame index: the same scene at the same time renders the same image
    // whatever was drawn before it (captures, saved scenes and golden images compare frames).
    float noise = hash12(gl_FragCoord.xy + fract(u_time.x * 0.618034) * 97.0) + hash12(gl_FragCoord.yx + 13.7) - 1.0;
    radiance *= 1.0 + noise / 255.0;
    o_color = vec4(clamp(radiance, vec3(0.0), vec3(60000.0)), 1.0);
}
#endif
