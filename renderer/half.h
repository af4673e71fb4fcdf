// IEEE 754 half floats (RGBA16F readbacks) to float, for tests and benches on the CPU.
#pragma once

#include <cmath>
#include <cstdint>

namespace vista {

inline float halfToFloat(std::uint16_t h) {
    int e = (h >> 10) & 31, m = h & 1023;
    float v = e == 0 ? std::ldexp(float(m), -24)                           // subnormal
            : e == 31 ? (m == 0 ? INFINITY : NAN)                          // Inf, NaN
                      : std::ldexp(float(m + 1024), e - 25);
    return h & 0x8000 ? -v : v;
}

}  // namespace vista
