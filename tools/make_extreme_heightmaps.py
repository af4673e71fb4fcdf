#!/usr/bin/env python3
"""Writes the small raw heightmaps of the extreme scenes (config/extreme/*.ini) to
data/heightmaps/extreme/: little-endian uint16 .r16 files, row z = 0 first. Deterministic
(a fixed linear congruential generator), so running it again reproduces the committed files.

    python3 tools/make_extreme_heightmaps.py
"""
import math
import os
import struct

OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "data", "heightmaps", "extreme")


def write(name, width, height, value):
    """value(x, z) in [0, 1] for each sample."""
    data = bytearray()
    for z in range(height):
        for x in range(width):
            v = min(max(value(x, z), 0.0), 1.0)
            data += struct.pack("<H", int(round(v * 65535)))
    with open(os.path.join(OUT, name), "wb") as f:
        f.write(data)


def lcg(seed):
    state = seed
    while True:
        state = (state * 1103515245 + 12345) & 0x7FFFFFFF
        yield state >> 16


def main():
    os.makedirs(OUT, exist_ok=True)
    write("flat_33x33.r16", 33, 33, lambda x, z: 0.5)
    # Every texel 0 or 1 at random: with height_scale_m 2000, 2 km cliffs between neighbours.
    bits = lcg(7)
    spiky = [float(next(bits) & 1) for _ in range(65 * 65)]
    write("spiky_65x65.r16", 65, 65, lambda x, z: spiky[z * 65 + x])
    write("tiny_2x2.r16", 2, 2, lambda x, z: 0.25 * (x + 2 * z))
    # Not a power of two (plus one) and not square: rolling hills.
    write("npot_37x53.r16", 37, 53,
          lambda x, z: 0.5 + 0.3 * math.sin(x * 0.35) * math.cos(z * 0.21) + 0.1 * math.sin((x + z) * 0.9))


if __name__ == "__main__":
    main()
