// The atmosphere model on the GPU (the same model as sky/atmosphere_reference.cpp): the
// parameter block, densities, phase functions, planet-frame ray geometry, the LUT
// parameterisations (Bruneton 2017 for transmittance, Hillaire 2020 for the sky view) and the
// ray integrator shared by the LUT passes and the from-space sky. Lengths in km, coefficients
// in 1/km. Planet frame: centre at the origin, the camera at (0, r_cam, 0) (the world is flat
// under a curved atmosphere: the planet's centre is straight below the camera).
#include "sky_bindings.glsl"

// A program that also uses a block at SKY_BINDING_ATMOSPHERE (the light grid) defines
// SKY_ATMOSPHERE_BLOCK to another binding before including this file.
#ifndef SKY_ATMOSPHERE_BLOCK
#define SKY_ATMOSPHERE_BLOCK SKY_BINDING_ATMOSPHERE
#endif
layout(std140, binding = SKY_ATMOSPHERE_BLOCK) uniform AtmosphereUniforms {
    vec4 a_radii;          // x bottom R, y top Rt, z camera radius, w camera altitude
    vec4 a_rayleigh;       // xyz scattering, w scale height
    vec4 a_mie;            // xyz scattering, w scale height
    vec4 a_mie_ext;        // xyz extinction, w g
    vec4 a_ozone;          // xyz absorption, w centre altitude
    vec4 a_misc;           // x ozone half width, y mie phase (0 CS, 1 HG), z sun angular radius, w limb u
    vec4 a_albedo;         // xyz ground albedo
    vec4 a_solar;          // xyz solar irradiance * sun illuminance (HDR), w sun illuminance
    vec4 a_sun;            // xyz unit vector towards the sun (world = planet frame at the camera)
    vec4 a_horizon;        // the camera's horizon (double on the CPU): x mu_h, y sqrt(1 - mu_h^2), z elevation (rad, <= 0)
    vec4 a_fog;            // height fog: x extinction at the base (1/km, 0: none), y base altitude, z falloff (km)
    vec4 a_aerial;         // aerial-perspective volume: x depth reached (km), y froxels per side, z slices, w steps per slice
    vec4 a_moon;           // xyz unit vector towards the moon, w its angular radius (rad)
    vec4 a_night;          // x star intensity (HDR, 0: no stars), y moon albedo, z 1 to draw the moon, w airglow radiance
    vec4 a_colour[3];      // xyz columns: the three samples to linear sRGB, HDR units (skyRgb)
    vec4 a_celestial[3];   // rows of the rotation from the world to the celestial frame (stars)
    ivec4 a_sizes;         // transmittance w, h, multiscatter size, sky-view w
    ivec4 a_sizes2;        // sky-view h, transmittance steps, multiscatter steps, sky-view steps
    vec4 a_gl[16];         // x Gauss-Legendre node on [0, 1], y weight (multiple-scattering sphere)
    ivec4 a_gl_count;      // x polar nodes, y azimuth nodes
    vec4 a_sun_depth[SKY_SUNLIGHT_WAVELENGTHS];  // xyz: optical depth per unit of each sample's (sunlightRgb)
    vec4 a_sun_rgb[SKY_SUNLIGHT_WAVELENGTHS];    // xyz: linear sRGB of the sun's share, HDR units
};

#ifndef VISTA_PI_DEFINED  // brdf.glsl and atmosphere.glsl both define it
#define VISTA_PI_DEFINED
const float PI = 3.14159265358979;
#endif

float bottomR() { return a_radii.x; }

// Sky radiance in HDR linear sRGB from the three monochromatic samples (transfer factors at
// 680/550/440 nm) the LUTs hold: the conversion fitted against the spectral reference
// (sky/atmosphere_spectral.h skyColourMatrix()) times the sun illuminance.
vec3 skyRgb(vec3 samples) { return mat3(a_colour[0].xyz, a_colour[1].xyz, a_colour[2].xyz) * samples; }
float topR() { return a_radii.y; }

// Direct sunlight in HDR linear sRGB after a path of transmittance t (the three samples; a
// product of paths is a path): the samples' optical depths give the path's Rayleigh, Mie and
// ozone columns, which give the optical depth at each of the spectral reference's wavelengths
// (sky/atmosphere_spectral.h sunlightConversion()). t = 1 is the unattenuated sun.
vec3 sunlightRgb(vec3 t) {
    vec3 depth = -log(max(t, vec3(1e-30)));
    vec3 rgb = vec3(0.0);
    for (int i = 0; i < SKY_SUNLIGHT_WAVELENGTHS; ++i)
        rgb += a_sun_rgb[i].xyz * exp(-max(dot(a_sun_depth[i].xyz, depth), 0.0));
    return rgb;
}

struct Medium {
    vec3 rayleigh, mie, extinction;
};

// Height fog's extinction (1/km, grey, pure scattering); the exponent is capped so that deep
// below its base the density stays finite.
float fogExtinction(float h) {
    return a_fog.x > 0.0 ? a_fog.x * exp(min((a_fog.y - h) / a_fog.z, 30.0)) : 0.0;
}

// The medium at radius r. Programs that define SKY_FOG see the height fog as extra aerosol
// (same phase function); the transmittance and multiple-scattering LUTs do not.
Medium medium(float r) {
    float h = max(r - bottomR(), 0.0);
    float dr = exp(-h / a_rayleigh.w), dm = exp(-h / a_mie.w);
    float oz = a_misc.x > 0.0 ? max(0.0, 1.0 - abs(h - a_ozone.w) / a_misc.x) : 0.0;
    Medium m;
    m.rayleigh = a_rayleigh.xyz * dr;
    m.mie = a_mie.xyz * dm;
    m.extinction = m.rayleigh + a_mie_ext.xyz * dm + a_ozone.xyz * oz;
#ifdef SKY_FOG
    float fog = fogExtinction(h);
    m.mie += vec3(fog);
    m.extinction += vec3(fog);
#endif
    return m;
}

float rayleighPhase(float c) { return 3.0 / (16.0 * PI) * (1.0 + c * c); }

float miePhase(float c) {
    float g = a_mie_ext.w;
    float denom = max(1.0 + g * g - 2.0 * g * c, 1e-6);
    if (a_misc.y > 0.5) return (1.0 - g * g) / (4.0 * PI * denom * sqrt(denom));
    float k = 3.0 / (8.0 * PI) * (1.0 - g * g) / (2.0 + g * g);
    return k * (1.0 + c * c) / (denom * sqrt(denom));
}

float safeSqrt(float x) { return sqrt(max(x, 0.0)); }

bool intersectsGround(float r, float mu) {
    float R = bottomR();
    return mu < 0.0 && (R - r) * (R + r) + (r * mu) * (r * mu) >= 0.0;
}

float distanceToGround(float r, float mu) {
    float R = bottomR();
    float far_b = -r * mu + safeSqrt((R - r) * (R + r) + (r * mu) * (r * mu));
    return far_b > 0.0 ? max((r - R) * (r + R) / far_b, 0.0) : 0.0;
}

float distanceToTop(float r, float mu) {
    float Rt = topR();
    return max(-r * mu + safeSqrt((Rt - r) * (Rt + r) + (r * mu) * (r * mu)), 0.0);
}

// Distance from radius r along mu to where the ray enters the atmosphere: 0 inside it, -1 when
// the ray misses it (the aerial perspective starts there when the camera is in space).
float atmosphereEntry(float r, float mu) {
    float Rt = topR();
    if (r <= Rt) return 0.0;
    float disc = (Rt - r) * (Rt + r) + (r * mu) * (r * mu);
    if (mu >= 0.0 || disc < 0.0) return -1.0;
    return (r - Rt) * (r + Rt) / (-r * mu + sqrt(disc));
}

float horizonMu(float r) {
    float R = bottomR(), rr = max(r, R);
    return -safeSqrt((rr - R) * (rr + R)) / rr;
}

// Texel centres hold the ends of the unit range (Bruneton's GetTextureCoordFromUnitRange).
float unitToUv(float x, float n) { return 0.5 / n + x * (1.0 - 1.0 / n); }
float uvToUnit(float u, float n) { return (u - 0.5 / n) / (1.0 - 1.0 / n); }

// Transmittance LUT (Bruneton 2017): x_r = rho / H, x_mu = (d - d_min) / (d_max - d_min); covers
// the rays that miss the ground (mu >= horizon), dense near the horizon.
vec2 transmittanceUv(float r, float mu) {
    float R = bottomR(), Rt = topR();
    float H = sqrt((Rt - R) * (Rt + R));
    float rho = safeSqrt((r - R) * (r + R));
    float d = distanceToTop(r, mu);
    float d_min = Rt - r, d_max = rho + H;
    float x_mu = d_max > d_min ? (d - d_min) / (d_max - d_min) : 0.0;
    return vec2(unitToUv(clamp(x_mu, 0.0, 1.0), float(a_sizes.x)), unitToUv(clamp(rho / H, 0.0, 1.0), float(a_sizes.y)));
}

void transmittanceRMu(vec2 uv, out float r, out float mu) {
    float R = bottomR(), Rt = topR();
    float x_mu = uvToUnit(uv.x, float(a_sizes.x)), x_r = uvToUnit(uv.y, float(a_sizes.y));
    float H = sqrt((Rt - R) * (Rt + R));
    float rho = H * x_r;
    r = sqrt(rho * rho + R * R);
    float d_min = Rt - r, d_max = rho + H;
    float d = d_min + x_mu * (d_max - d_min);
    mu = d == 0.0 ? 1.0 : clamp((H * H - rho * rho - d * d) / (2.0 * r * d), -1.0, 1.0);
}

#ifdef SKY_TRANSMITTANCE_LUT
layout(binding = SKY_TEX_TRANSMITTANCE) uniform sampler2D u_transmittance;
// Transmittance to the top of the atmosphere from (r, mu), the ray held at the horizon when it
// would hit the ground (the lit-side limit: multiply by sunVisible for the planet's shadow).
vec3 transmittanceToTop(float r, float mu) {
    r = clamp(r, bottomR(), topR());
    return texture(u_transmittance, transmittanceUv(r, max(mu, horizonMu(r)))).rgb;
}
float sunVisible(float r, float mu_s) { return intersectsGround(r, mu_s) ? 0.0 : 1.0; }
#endif

#ifdef SKY_MULTISCATTER_LUT
layout(binding = SKY_TEX_MULTISCATTER) uniform sampler2D u_multiscatter;
// psi_ms (1/sr per unit solar irradiance); the LUT stores its logarithm over (sqrt altitude, mu_s).
vec2 multiscatterUv(float r, float mu_s) {
    float x = sqrt(clamp((r - bottomR()) / (topR() - bottomR()), 0.0, 1.0));
    float n = float(a_sizes.z);
    return vec2(unitToUv(clamp(mu_s * 0.5 + 0.5, 0.0, 1.0), n), unitToUv(x, n));
}
vec3 multiscatter(float r, float mu_s) { return exp(texture(u_multiscatter, multiscatterUv(r, mu_s)).rgb); }
#endif

// What a ray accumulates: radiance from the source and the transmittance to its end.
struct RaySums {
    vec3 radiance;   // int T(0, t) J(t) dt
    vec3 second;     // int T(0, t) sigma_s(t) dt (multiple-scattering pass only)
    vec3 transmittance;
};

#if defined(SKY_TRANSMITTANCE_LUT)
// Integrates along the ray (r, mu) with the sun at mu_s, nu over [0, len]. mode 0: single +
// multiple scattering (sky view, from space); mode 1: the multiple-scattering LUT's
// integrands (isotropic single scattering, and sigma_s for f_ms). The ray is split at its
// perigee and each piece is sampled at t = len u^2 from its lower-altitude end, so samples
// gather where the air is dense; each interval is integrated exactly for a constant medium
// (Hillaire 2020: (S - S T) / sigma_t).
RaySums integrateRay(float r, float mu, float mu_s, float nu, float len, int steps, int mode) {
    RaySums s;
    s.radiance = vec3(0.0);
    s.second = vec3(0.0);
    s.transmittance = vec3(1.0);
    if (!(len > 0.0)) return s;
    float phase_r = rayleighPhase(nu), phase_m = miePhase(nu);
    float t_p = -r * mu;
    bool split = t_p > 0.0 && t_p < len;
    int pieces = split ? 2 : 1;
    int n = max(steps / pieces, 2);
    for (int piece = 0; piece < pieces; ++piece) {
        // piece 0 of a split ray: [0, t_p], dense at t_p; else [a, b] dense at a (going up) or
        // at b (a ray ending on the ground, whose end is lowest).
        float a = piece == 0 ? 0.0 : t_p, b = (split && piece == 0) ? t_p : len;
        bool dense_at_a = split ? piece == 1 : !(mu < 0.0);
        float piece_len = b - a;
        float t_prev = a;
        for (int i = 1; i <= n; ++i) {
            float u = float(i) / float(n);
            float t = dense_at_a ? a + piece_len * u * u : b - piece_len * (1.0 - u) * (1.0 - u);
            float um = (float(i) - 0.5) / float(n);
            float tm = dense_at_a ? a + piece_len * um * um : b - piece_len * (1.0 - um) * (1.0 - um);
            float dt = t - t_prev;
            t_prev = t;
            float r_t = sqrt(max(r * r + tm * (2.0 * r * mu + tm), 0.0));
            float mu_s_t = clamp((r * mu_s + tm * nu) / r_t, -1.0, 1.0);
            Medium m = medium(r_t);
            vec3 sun = transmittanceToTop(r_t, mu_s_t) * sunVisible(r_t, mu_s_t);
            vec3 scattering = m.rayleigh + m.mie;
            vec3 j;
            if (mode == 0) {
                j = (m.rayleigh * phase_r + m.mie * phase_m) * sun;
#ifdef SKY_MULTISCATTER_LUT
                j += scattering * multiscatter(r_t, mu_s_t);
#endif
            } else {
                j = scattering * sun * (1.0 / (4.0 * PI));
            }
            vec3 ext = max(m.extinction, vec3(1e-12));
            vec3 step_t = exp(-ext * dt);
            vec3 weight = s.transmittance * (vec3(1.0) - step_t) / ext;  // int over the interval of T
            s.radiance += weight * j;
            s.second += weight * scattering;
            s.transmittance *= step_t;
        }
    }
    return s;
}
#endif

#if defined(SKY_TRANSMITTANCE_LUT) && defined(SKY_MULTISCATTER_LUT)
// What a view ray gathers at distance t from the camera (direction mu, sun at mu_s, nu): the
// radiance scattered towards the camera per km (single scattering with the planet's shadow,
// plus multiple scattering) and the extinction, as integrateRay's mode 0.
void viewSample(float r, float mu, float mu_s, float nu, float phase_r, float phase_m, float t, out vec3 j,
                out vec3 extinction) {
    float r_t = sqrt(max(r * r + t * (2.0 * r * mu + t), 0.0));
    float mu_s_t = clamp((r * mu_s + t * nu) / max(r_t, 1e-6), -1.0, 1.0);
    Medium m = medium(r_t);
    vec3 sun = transmittanceToTop(r_t, mu_s_t) * sunVisible(r_t, mu_s_t);
    j = (m.rayleigh * phase_r + m.mie * phase_m) * sun + (m.rayleigh + m.mie) * multiscatter(r_t, mu_s_t);
    extinction = max(m.extinction, vec3(1e-12));
}
#endif

// The camera's view rays, exact at the horizon. An acos of nearly equal angles loses ~1e-4 rad
// in float (more than a pixel's distance from the horizon at 128x72), so the angle from the
// horizon is taken as atan(sin, cos) of the difference, from the horizon the CPU computed in
// double; the ground test and distance use the same horizon.
float aboveHorizon(float mu) {
    float cos_e = safeSqrt(1.0 - mu * mu);
    return atan(mu * a_horizon.y - cos_e * a_horizon.x, cos_e * a_horizon.y + mu * a_horizon.x);
}
float cameraDistanceToGround(float mu) {
    float r = a_radii.z, h = a_radii.w;
    float root = r * safeSqrt((mu - a_horizon.x) * (mu + a_horizon.x));
    float far_b = -r * mu + root;
    return far_b > 0.0 ? h * (2.0 * bottomR() + h) / far_b : 0.0;
}
// Sky-view LUT (Hillaire 2020 with its non-linear latitude), the horizon kept sharp: the top
// half of the rows covers the sky from the zenith (first row) to the grazing ray just above the
// horizon (its last row), the bottom half the ground from the grazing ray just below it (its
// first row) to the nadir, both with a square-root mapping dense at the horizon. Each half is
// sampled only between its own first and last row centres, so bilinear filtering never mixes
// sky and ground across the horizon. u = sqrt((1 - cos(azimuth from the sun)) / 2).
int skyViewSkyRows() { return a_sizes2.x / 2; }
vec2 skyViewUv(float above_horizon, float cos_azimuth) {
    int n = a_sizes2.x, n_sky = skyViewSkyRows(), n_ground = n - n_sky;
    float e_h = a_horizon.z;
    float row;
    if (above_horizon >= 0.0) {
        float x = 1.0 - sqrt(clamp(above_horizon / (0.5 * PI - e_h), 0.0, 1.0));
        row = 0.5 + x * float(n_sky - 1);
    } else {
        float x = sqrt(clamp(-above_horizon / (0.5 * PI + e_h), 0.0, 1.0));
        row = float(n_sky) + 0.5 + x * float(n_ground - 1);
    }
    float u = sqrt(clamp(0.5 - 0.5 * cos_azimuth, 0.0, 1.0));
    return vec2(unitToUv(u, float(a_sizes.w)), row / float(n));
}

// The ray of a texel: mu, cos of the azimuth from the sun, and whether it ends on the ground.
void skyViewParams(ivec2 texel, out float mu, out float cos_azimuth, out bool ground) {
    int n_sky = skyViewSkyRows(), n_ground = a_sizes2.x - n_sky;
    float e_h = a_horizon.z, d;
    ground = texel.y >= n_sky;
    if (!ground) {
        float x = 1.0 - float(texel.y) / float(max(n_sky - 1, 1));
        d = (0.5 * PI - e_h) * x * x;
    } else {
        float x = float(texel.y - n_sky) / float(max(n_ground - 1, 1));
        d = -(0.5 * PI + e_h) * x * x;
    }
    // sin(e_h + d) without cancelling the two angles.
    mu = clamp(a_horizon.x * cos(d) + a_horizon.y * sin(d), -1.0, 1.0);
    if (ground) mu = min(mu, a_horizon.x);
    float u = uvToUnit((float(texel.x) + 0.5) / float(a_sizes.w), float(a_sizes.w));
    cos_azimuth = 1.0 - 2.0 * u * u;
}
