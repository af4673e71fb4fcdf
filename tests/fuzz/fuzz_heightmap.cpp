// libFuzzer target: heightmap headers and decoding from memory. The first byte picks the
// format (raw .r16 with a size from the next four bytes, or an image: PNG, TIFF, EXR, PGM),
// the rest is the file. Any bytes must be refused with a reason or give a map whose size
// matches its samples, all finite, without crashing or allocating past the limit.
#include "terrain/heightmap.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 5) return 0;
    static const char* const kNames[] = {"fuzz.r16", "fuzz.png", "fuzz.tif", "fuzz.exr", "fuzz.pgm"};
    const std::string name = kNames[data[0] % 5];
    const int raw_width = data[1] | (data[2] & 0x0f) << 8;  // 0..4095
    const int raw_height = data[3] | (data[4] & 0x0f) << 8;
    const std::span<const unsigned char> bytes(data + 5, size - 5);
    vista::InputErrors errors;
    // 16 MiB of samples at most, so a header claiming a huge image is refused, never allocated.
    const vista::Heightmap map = vista::decodeHeightmap(bytes, name, raw_width, raw_height, errors, 16u << 20);
    if (errors.empty()) {
        if (map.width < 2 || map.height < 2) std::abort();
        if (map.samples.size() != std::size_t(map.width) * std::size_t(map.height)) std::abort();
        for (float v : map.samples)
            if (!std::isfinite(v)) std::abort();
        (void)map.sample(map.width * 0.5, map.height * 0.5);
    } else if (!map.samples.empty() || errors.front().message.empty()) {
        std::abort();
    }
    return 0;
}
