// Hashing shared by the weather shaders, mirrored by sky/weather/weather_model.cpp (weatherHash,
// weatherRandom): the same bits on the CPU and the GPU.
#include "../../clouds/shaders/cloud_noise.glsl"

uint weatherHash(uint a, uint b, uint c, uint d) {
    return cloudHash(a ^ cloudHash(b ^ cloudHash(c ^ cloudHash(d ^ 0x3c6ef372u))));
}

// Random number k in [0, 1) of a drop or splash whose hash is h.
float weatherRandom(uint h, uint k) {
    return float(cloudHash(h ^ (k * 0x9e3779b9u + 0x7f4a7c15u)) >> 8) * (1.0 / 16777216.0);
}
