// The sea's Gerstner waves on the GPU: the float mirror of terrain/water/waves.cpp evaluateWaves (the
// formulas are in terrain/water/waves.h). Positions are camera-relative; each wave's phase offset
// (k d . camera - omega t + phi, wrapped to [0, 2 pi) in double on the CPU) keeps the phase exact
// at any time and distance from the origin. Also the water's uniform block.
#include "water_bindings.glsl"

layout(std140, binding = WATER_BINDING_UNIFORMS) uniform WaterUniforms {
    vec4 w_wave_a[WATER_MAX_WAVES];  // direction x, z; wavenumber k (1/m); amplitude (m)
    vec4 w_wave_b[WATER_MAX_WAVES];  // chop (m); phase offset (rad); slope variance of this and every shorter wave; omega dt (rad: back to the previous frame)
    vec4 w_grid;        // x ring constant c (m), y angle per segment (rad), z segments, w waves
    vec4 w_surface;     // x still level minus camera y (m), y roughness, z refraction strength, w foam depth (m)
    vec4 w_scatter;     // rgb single-scattering albedo, w whitecaps
    vec4 w_absorption;  // rgb extinction (1/m), unused
    vec4 w_foam;        // rgb foam albedo, w foam animation phase (rad, wrapped)
    vec4 w_sun;         // rgb sun irradiance at normal incidence, w 1 when the sky-view LUT is bound
    vec4 w_sky_up;      // rgb sky irradiance on an up-facing surface, w ray-march steps (0: sky reflection only)
    vec4 w_ground_up;   // rgb irradiance from below, w longest reflected ray (m)
    vec4 w_misc;        // x the highest a wave crest can reach above the still level (m)
    vec4 w_rain;        // rain ripples: xy camera x, z wrapped to the ripple period (m), z time wrapped (s), w intensity (0: none)
};

struct WaveSample {
    vec3 displacement;          // from the rest point (x0.x, level, x0.z)
    vec3 normal;                // unit
    float jacobian;             // horizontal squeeze, < 1 at crests
    float lost_slope_variance;  // of the waves the footprint removed
};

// 1 while the wavelength is >= 8 footprints, 0 at 4 (waves.h).
float waveFootprintWeight(float k, float footprint) {
    return 1.0 - smoothstep(0.125, 0.25, footprint * k * (1.0 / 6.28318530718));
}

// The surface at camera-relative rest position p (x, z); footprint (m) fades out short waves.
WaveSample evaluateWaves(vec2 p, float footprint) {
    WaveSample ws;
    ws.displacement = vec3(0.0);
    ws.lost_slope_variance = 0.0;
    vec3 tx = vec3(1.0, 0.0, 0.0), tz = vec3(0.0, 0.0, 1.0);
    int n = int(w_grid.w);
    for (int i = 0; i < n; ++i) {
        vec4 a = w_wave_a[i], b = w_wave_b[i];
        float k = a.z;
        float w = waveFootprintWeight(k, footprint);
        if (w <= 0.0) {
            // Waves come longest first: this one and all shorter ones are gone.
            ws.lost_slope_variance += b.z;
            break;
        }
        ws.lost_slope_variance += 0.5 * (1.0 - w * w) * (a.w * k) * (a.w * k);
        float amp = a.w * w, c = b.x * w;
        float theta = k * dot(a.xy, p) + b.y;
        float sn = sin(theta), cs = cos(theta);
        float dx = a.x, dz = a.y;
        ws.displacement += vec3(-c * dx * sn, amp * cs, -c * dz * sn);
        tx += vec3(-c * k * dx * dx * cs, -amp * k * dx * sn, -c * k * dx * dz * cs);
        tz += vec3(-c * k * dx * dz * cs, -amp * k * dz * sn, -c * k * dz * dz * cs);
    }
    ws.normal = normalize(cross(tz, tx));
    ws.jacobian = tx.x * tz.z - tx.z * tz.x;
    return ws;
}

// The displacement of rest point p (camera-relative x, z) in the previous frame (the phases moved
// back by omega dt, w_wave_b[i].w): the same waves, footprint weights and sums as evaluateWaves.
vec3 previousDisplacement(vec2 p, float footprint) {
    vec3 d = vec3(0.0);
    int n = int(w_grid.w);
    for (int i = 0; i < n; ++i) {
        vec4 a = w_wave_a[i], b = w_wave_b[i];
        float w = waveFootprintWeight(a.z, footprint);
        if (w <= 0.0) break;
        float theta = a.z * dot(a.xy, p) + b.y + b.w;
        float sn = sin(theta), cs = cos(theta);
        d += vec3(-b.x * w * a.x * sn, a.w * w * cs, -b.x * w * a.y * sn);
    }
    return d;
}
