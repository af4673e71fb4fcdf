// A bounds check of an OpenEXR file's headers, run before OpenEXR sees the bytes.
//
// OpenEXR allocates what a header declares (an attribute's value, the chunk offset table of a
// data window) before anything checks that the file holds it, so a few corrupt bytes can ask
// for gigabytes. This walks the headers with the file's bytes in hand and refuses:
// - an attribute whose value runs past the end of the file, or a header that never ends;
// - a data window that is empty, inverted, or larger than max_bytes as float samples;
// - tiles of zero size, or a chunk offset table (8 bytes per scan-line block or tile, over
//   every mip or rip level) larger than max_bytes;
// - deep data (a heightmap is one flat image).
// It does not decode pixels; OpenImageIO still does, and still checks channels and sizes.
#pragma once

#include <cstdint>
#include <span>
#include <string>

namespace vista {

// True when bytes start with the OpenEXR magic number (76 2f 31 01).
bool isExr(std::span<const unsigned char> bytes);

// Empty when every header's sizes fit within the file and max_bytes; otherwise what is wrong.
std::string checkExrHeaders(std::span<const unsigned char> bytes, std::uint64_t max_bytes);

}  // namespace vista
