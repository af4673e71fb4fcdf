// Terrain material textures, generated at load (no image files, no licence doubts):
// five layers (sand, grass, rock, snow, dirt) of tileable noise, each with an albedo +
// roughness texture and a detail normal map derived from the same noise heights.
#pragma once

#include <cstdint>
#include <vector>

namespace vista {

enum class MaterialLayer : int { Sand, Grass, Rock, Snow, Dirt, Count };

struct MaterialImages {
    int size = 0;                        // texels per side (power of two)
    int layers = 0;
    std::vector<std::uint8_t> albedo;    // RGBA8 per layer: sRGB albedo, A = roughness
    std::vector<std::uint8_t> normal;    // RGBA8 per layer: tangent-space normal in RGB (0.5 + 0.5 n)
};

// Deterministic: the same size gives the same bytes on every machine.
MaterialImages generateMaterialImages(int size = 256);

}  // namespace vista
