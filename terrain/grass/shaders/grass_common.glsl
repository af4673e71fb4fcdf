// Grass hashing and wind, mirrored on the CPU by terrain/grass/grass_placement.cpp (same bits for the
// hash, same formulas for the wind; tests compare both).

uint grassHash(uint x, uint y, uint z) {
    uint h = x * 0x8da6b343u ^ y * 0xd8163841u ^ z * 0xcb1ab31fu;
    h ^= h >> 16;
    h *= 0x7feb352du;
    h ^= h >> 15;
    h *= 0x846ca68bu;
    h ^= h >> 16;
    return h;
}

// Random number k in [0, 1) of a blade whose hash is h.
float grassRandom(uint h, uint k) {
    return float(grassHash(h, k, 0x2545f491u) >> 8) * (1.0 / 16777216.0);
}

const int kGustPeriod = 64;  // noise cells; the CPU wraps the gust origin by it

float gustLattice(ivec2 i) {
    uvec2 w = uvec2(i & (kGustPeriod - 1));
    return float(grassHash(w.x, w.y, 7u) >> 8) * (1.0 / 16777216.0);
}

float gustValueNoise(vec2 q) {
    vec2 f = floor(q);
    ivec2 i = ivec2(f);
    vec2 u = q - f;
    u = u * u * (3.0 - 2.0 * u);
    float a = gustLattice(i), b = gustLattice(i + ivec2(1, 0));
    float c = gustLattice(i + ivec2(0, 1)), d = gustLattice(i + ivec2(1, 1));
    float top = a + (b - a) * u.x, bottom = c + (d - c) * u.x;
    return top + (bottom - top) * u.y;
}

float grassGustNoise(vec2 q) {
    return 0.65 * gustValueNoise(q) + 0.35 * gustValueNoise(q * 2.0 + 17.0);
}

struct GrassWind {
    vec2 dir;          // horizontal unit vector the wind blows toward (x, z)
    vec2 gust_origin;  // noise coordinates of the camera, wrapped to [0, kGustPeriod)
    float inv_gust_scale;
    float sway_phase;  // rad, wrapped: 2 pi f t / 8 mod 2 pi
    float strength, gust, sway;  // rad
};

// Horizontal tilt (rad, x and z) the wind gives a blade at camera-relative rel_xz: a mean
// bend, a travelling gust field and a per-blade sway (frequency base * step / 8).
vec2 grassWindTilt(GrassWind w, vec2 rel_xz, float phase, int frequency_step) {
    float n = grassGustNoise(rel_xz * w.inv_gust_scale + w.gust_origin);
    float gust = smoothstep(0.35, 0.85, n);
    float angle = float(frequency_step) * w.sway_phase + phase;
    float along = w.strength + w.gust * gust + w.sway * sin(angle);
    float across = 0.35 * w.sway * cos(angle);
    return w.dir * along + vec2(-w.dir.y, w.dir.x) * across;
}

// One culled blade, written by grass.cull and drawn by grass.gbuffer (std430: 48 bytes).
struct GrassBlade {
    vec4 root_width;    // camera-relative root position (m), width at the root (m)
    vec4 shape;         // length (m), facing angle (rad), bend (x, z): direction and tip angle (rad)
    uvec4 look;         // packed sqrt(tip albedo) RGBA8, packed terrain normal (snorm), candidate id,
                        // the bend one frame earlier minus now (half2, rad; 0 without a previous frame)
};
