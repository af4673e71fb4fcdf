// Capture images through OpenImageIO: PNG (8-bit sRGB) or EXR (linear half float),
// written to a temporary name and renamed, so an interrupted capture never leaves a
// truncated image under a final name.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace vista {

// rgba: width*height*4 bytes, top row first. Alpha is dropped. "" on success, else why.
std::string writePng(const std::filesystem::path& file, int width, int height, const std::vector<unsigned char>& rgba);
// rgba: width*height*4 half floats, top row first. Alpha is dropped.
std::string writeExr(const std::filesystem::path& file, int width, int height, const std::vector<std::uint16_t>& rgba);

}  // namespace vista
