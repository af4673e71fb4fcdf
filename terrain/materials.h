// Terrain material textures, generated at load (no image files, no licence doubts):
// five layers (sand, grass, rock, snow, dirt) of tileable noise, each with an albedo +
// roughness texture and a detail normal map derived from the same noise heights, which the
// normal map's alpha keeps (parallax occlusion mapping marches them: terrain/shaders/pom.glsl).
#pragma once

#include <cstdint>
#include <vector>

namespace vista {

enum class MaterialLayer : int { Sand, Grass, Rock, Snow, Dirt, Count };

struct MaterialImages {
    int size = 0;                        // texels per side (power of two)
    int layers = 0;
    std::vector<std::uint8_t> albedo;    // RGBA8 per layer: sRGB albedo, A = roughness
    std::vector<std::uint8_t> normal;    // RGBA8 per layer: tangent-space normal in RGB (0.5 + 0.5 n), A = relief
                                         // height (0 lowest .. 1 highest texel of the layer)
};

// Deterministic: the same size gives the same bytes on every machine.
MaterialImages generateMaterialImages(int size = 256);

// The relief height (0..1) of texel (x, y) of a layer: the normal map's alpha.
inline float materialHeight(const MaterialImages& m, int layer, int x, int y) {
    return float(m.normal[((std::size_t(layer) * std::size_t(m.size) + std::size_t(y)) * std::size_t(m.size) + std::size_t(x)) * 4 + 3]) / 255.0f;
}

}  // namespace vista
