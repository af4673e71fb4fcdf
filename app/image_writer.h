// Capture images through OpenImageIO: PNG (8-bit sRGB) or EXR (linear half float), encoded
// in memory and written with writeFileAtomic (config/file_io.h): every write and the close
// are checked, and only a complete image ever appears under its final name.
#pragma once

#include "config/file_io.h"  // writeFileAtomic, AtomicWriter

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace vista {

// rgba: width*height*4 bytes, top row first. Alpha is dropped. force: replace an existing
// file (else one that appeared since the start is refused). "" on success, else why.
std::string writePng(const std::filesystem::path& file, int width, int height, const std::vector<unsigned char>& rgba,
                     bool force);
// rgba: width*height*4 half floats, top row first. Alpha is dropped.
std::string writeExr(const std::filesystem::path& file, int width, int height, const std::vector<std::uint16_t>& rgba,
                     bool force);

}  // namespace vista
