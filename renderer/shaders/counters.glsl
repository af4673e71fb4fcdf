// 64-bit GPU counters as two uints (low, high) in a buffer, read back by CounterReadback:
// adding n to the low word and carrying one into the high word when it wraps keeps the sum
// exact for any number of additions of n < 2^32. A macro because atomics need the buffer
// variable itself, not a copy.
#define ADD_COUNTER64(low, high, n)                      \
    {                                                    \
        uint add_n_ = (n);                               \
        if (add_n_ != 0u) {                              \
            uint before_ = atomicAdd(low, add_n_);       \
            if (before_ + add_n_ < before_) atomicAdd(high, 1u); \
        }                                                \
    }
