// Tileable 3D value noise and fBm for the cloud layers; sky/clouds/cloud_model.cpp mirrors every line
// in double (tests/gl/clouds_test.cpp compares them). Integer hashing: the same value for a
// lattice point on every GPU, and an exact wrap to the period.
#define CLOUD_NOISE_PERIOD 64

uint cloudHash(uint x) {
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}

float cloudLattice(ivec3 cell, int period, uint seed) {
    uvec3 w = uvec3(cell) & uvec3(uint(period - 1));
    uint h = cloudHash(w.x ^ cloudHash(w.y ^ cloudHash(w.z ^ seed)));
    return float(h >> 8) * (1.0 / 16777216.0);
}

// In [0, 1], periodic with `period` (a power of two) cells along every axis.
float cloudValueNoise(vec3 p, int period, uint seed) {
    vec3 i = floor(p), f = p - i;
    ivec3 c = ivec3(i);
    vec3 u = f * f * f * (f * (f * 6.0 - 15.0) + 10.0);
    float x00 = mix(cloudLattice(c, period, seed), cloudLattice(c + ivec3(1, 0, 0), period, seed), u.x);
    float x10 = mix(cloudLattice(c + ivec3(0, 1, 0), period, seed), cloudLattice(c + ivec3(1, 1, 0), period, seed), u.x);
    float x01 = mix(cloudLattice(c + ivec3(0, 0, 1), period, seed), cloudLattice(c + ivec3(1, 0, 1), period, seed), u.x);
    float x11 = mix(cloudLattice(c + ivec3(0, 1, 1), period, seed), cloudLattice(c + ivec3(1, 1, 1), period, seed), u.x);
    return mix(mix(x00, x10, u.y), mix(x01, x11, u.y), u.z);
}

uint cloudOctaveSeed(uint seed, int octave) { return seed + uint(octave) * 0x9e3779b9u; }

// Octaves of value noise (frequency x2, amplitude x1/2), divided by the sum of amplitudes.
float cloudFbm(vec3 p, int octaves, uint seed) {
    float sum = 0.0, amplitude = 1.0, norm = 0.0;
    int period = CLOUD_NOISE_PERIOD;
    for (int k = 0; k < octaves; ++k) {
        sum += amplitude * cloudValueNoise(p, period, cloudOctaveSeed(seed, k));
        norm += amplitude;
        amplitude *= 0.5;
        p *= 2.0;
        period *= 2;
    }
    return norm > 0.0 ? sum / norm : 0.0;
}
