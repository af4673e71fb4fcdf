// Rain ripples on a water surface: expanding rings in 0.5 m cells, one per cell and second at a
// hashed place and phase (8 places over the 8 s wrap), growing until their outer edge is one
// cell from their centre, fading in and out. Periodic over RAIN_RIPPLE_WRAP_M in x and z and
// RAIN_RIPPLE_WRAP_S in time: the caller passes world x/z and time wrapped in double on the CPU
// (sky/weather/weather_model.h rainRippleWrap; its rainRippleNormal mirrors this in double).
#include "weather_common.glsl"

#define RAIN_RIPPLE_WRAP_M 32.0
#define RAIN_RIPPLE_WRAP_S 8.0

// Unit normal (y up) of the rippled surface; add its x/z to a water normal to perturb it.
// intensity 0..1: share of the cells that ripple; 0 gives exactly (0, 1, 0).
vec3 rainRippleNormal(vec2 world_xz_wrapped, float time_wrapped, float intensity) {
    const float cell_m = RAIN_RIPPLE_WRAP_M / 64.0, amplitude = 0.0035, wavelength = 0.06;
    const float two_pi = 6.28318530718;
    vec2 slope = vec2(0.0);
    ivec2 c = ivec2(floor(world_xz_wrapped / cell_m));
    for (int dz = -1; dz <= 1; ++dz)
        for (int dx = -1; dx <= 1; ++dx) {
            ivec2 cell = c + ivec2(dx, dz);
            uvec2 w = uvec2(cell) & uvec2(63u);
            uint h = weatherHash(w.x, w.y, 0x9127u, 0u);
            float u = time_wrapped + weatherRandom(h, 0u);
            float k = floor(u), age = u - k;
            uint hk = weatherHash(w.x, w.y, 0x9127u, uint(int(k) & 7) + 1u);
            if (weatherRandom(hk, 1u) >= intensity) continue;
            vec2 centre = (vec2(cell) + vec2(weatherRandom(hk, 2u), weatherRandom(hk, 3u))) * cell_m;
            vec2 d = world_xz_wrapped - centre;
            float r = length(d);
            float x = (r - age * (cell_m - wavelength)) / wavelength;
            if (abs(x) >= 1.0 || r < 1e-6) continue;
            // Height a (1 - x^2)^2 sin(2 pi x) fade(age) around the front; its radial slope.
            float b = (1.0 - x * x) * (1.0 - x * x), db = -4.0 * x * (1.0 - x * x);
            float fade = (1.0 - age) * (1.0 - age) * min(1.0, 8.0 * age);
            float dh = amplitude * fade / wavelength * (db * sin(two_pi * x) + b * two_pi * cos(two_pi * x));
            slope += dh * d / r;
        }
    return normalize(vec3(-slope.x, 1.0, -slope.y));
}
