// A rough memory estimate for a frame size, checked before a GL context exists: llvmpipe does
// not report every failed allocation (under `ulimit -v` an 8192x8192 capture crashed inside
// Mesa), so a frame that cannot fit is refused up front with a message instead.
#pragma once

#include <cstdint>
#include <string>

namespace vista {

// Measured with /usr/bin/time on llvmpipe (default scene, one frame): about 560 MB resident at
// 1024x1024 and 990 MB at 2048x2048, i.e. a fixed part plus ~140 bytes per pixel of targets.
constexpr std::uint64_t kFixedBytes = std::uint64_t(300) << 20;
constexpr std::uint64_t kBytesPerPixel = 128;

std::uint64_t estimatedFrameBytes(int width, int height);
// The most this process may use: RLIMIT_AS when set, else physical memory plus swap.
std::uint64_t memoryLimitBytes();
// "" when width x height should fit, else why (sizes in MiB, naming --size).
std::string checkFrameMemory(int width, int height);

}  // namespace vista
