// 3D colour lookup tables for grading: the .cube format (Adobe/Resolve: TITLE, LUT_3D_SIZE N,
// DOMAIN_MIN/MAX r g b, then N^3 lines "r g b" with red changing fastest), parsed with an error
// naming file:line for every malformed line, and uploaded as a linearly filtered 3D texture.
#pragma once

#include "config/input_error.h"
#include "renderer/gl/objects.h"

#include <glm/vec3.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace vista {

struct CubeLut {
    int size = 0;                  // entries per side, 2..256
    glm::vec3 domain_min{0.0f};    // input mapped to the first entry
    glm::vec3 domain_max{1.0f};    // input mapped to the last entry
    std::vector<glm::vec3> table;  // size^3 entries, red fastest, then green, then blue
};

// Parses .cube text; file names it in errors. None (and the errors) when malformed.
std::optional<CubeLut> parseCube(std::string_view text, const std::string& file, InputErrors& errors);
// Reads and parses a file; a missing or unreadable file is an error too.
std::optional<CubeLut> loadCube(const std::filesystem::path& path, InputErrors& errors);

// The table as a 3D RGB32F texture (linear filtering, clamped to the edges).
gl::Texture uploadCube(const CubeLut& lut, std::string_view name);

}  // namespace vista
