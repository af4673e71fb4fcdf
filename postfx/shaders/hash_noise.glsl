// A uniform value in [0, 1) per pixel and pattern: an integer hash, the same on every GPU
// (film grain, night-vision noise).
float hashNoise(uvec3 v) {
    uint h = v.x * 1664525u + v.y * 22695477u + v.z * 2891336453u + 1013904223u;
    h ^= h >> 16; h *= 2246822519u; h ^= h >> 13; h *= 3266489917u; h ^= h >> 16;
    return float(h >> 8) / 16777216.0;
}
