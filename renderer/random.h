// A small deterministic random number generator for scene generation and hash construction:
// splitmix64 (Steele, Lea and Flood 2014). Unlike <random>'s distributions its output is
// specified bit for bit, so a seed gives the same lights and the same tables on every
// platform and standard library.
#pragma once

#include <cstdint>

namespace vista {

// One splitmix64 step: advances state and returns 64 well-mixed bits.
inline std::uint64_t splitmix64(std::uint64_t& state) {
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

// A stateless mix of a seed and an index (counter-based): the value for item i does not
// depend on how many values were drawn for other items.
inline std::uint64_t hashIndex(std::uint64_t seed, std::uint64_t index) {
    std::uint64_t state = seed ^ (index * 0xD1B54A32D192ED03ull);
    return splitmix64(state);
}

// A 32-bit hash of up to four integers (cells, candidates, seeds): a multiply-xor mix, then
// lowbias32's finaliser. terrain/grass/shaders/grass_common.glsl's grassHash is the same of three.
inline std::uint32_t hashInts(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d = 0) {
    std::uint32_t h = a * 0x8da6b343u ^ b * 0xd8163841u ^ c * 0xcb1ab31fu ^ d * 0x165667b1u;
    h ^= h >> 16;
    h *= 0x7feb352du;
    h ^= h >> 15;
    h *= 0x846ca68bu;
    h ^= h >> 16;
    return h;
}

class Rng {
public:
    explicit Rng(std::uint64_t seed) : state_(seed) {}
    std::uint64_t next() { return splitmix64(state_); }
    // Uniform in [0, 1), 53 random bits.
    double uniform() { return double(next() >> 11) * (1.0 / 9007199254740992.0); }
    double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
    // Uniform integer in [0, n), n > 0 (multiply-shift; bias below 2^-32 for n < 2^32).
    std::uint32_t below(std::uint32_t n) { return std::uint32_t(((next() >> 32) * std::uint64_t(n)) >> 32); }

private:
    std::uint64_t state_;
};

}  // namespace vista
