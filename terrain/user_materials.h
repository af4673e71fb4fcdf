// The user's own terrain materials and splat maps ([terrain.material.NAME], [terrain] splat_map,
// docs/terrain-materials.md): image files read with OpenImageIO, checked (regular file, format,
// channels, size) with errors naming the file and what is accepted, merged with the generated
// layers (terrain/materials.h) into the arrays the terrain shader samples. No GL here, so `vista
// check` runs the very same checks.
#pragma once

#include "config/input_error.h"
#include "terrain/materials.h"
#include "terrain/terrain_settings.h"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace vista {

// Layers of the material arrays at most: the five generated ones and three added by the user
// (terrain/shaders/terrain_block.glsl holds as many: TERRAIN_BLOCK_LAYERS).
inline constexpr int kMaxMaterialLayers = 8;
// Splat images at most (4 channels each; terrain.glsl gets the count as TERRAIN_SPLAT).
inline constexpr int kMaxSplatImages = 2;
// User material images: square, a power of two in this range. Smaller ones are enlarged (bilinear,
// repeating) to the generated layers' 256 so every layer of the arrays has one size.
inline constexpr int kMinMaterialImage = 4, kMaxMaterialImage = 2048, kGeneratedMaterialSize = 256;

struct MaterialSet {
    MaterialImages images;             // every layer: the generated ones (replaced where the user names them), then added ones
    std::vector<std::string> names;    // per layer: sand grass rock snow dirt, then the added user materials' names
    std::vector<float> repeat_m;       // per layer: m per repeat of its images (0: generated, [terrain] texture_scale_m)
    std::vector<bool> user;            // per layer: from the user's images
    // Splat maps: images x (width x height) RGBA8 weights, one texel per heightmap sample; empty
    // when the height/slope rules place the layers.
    int splat_images = 0, splat_width = 0, splat_height = 0;
    std::vector<std::uint8_t> splat;
    std::vector<int> splat_layers;     // per channel (4 per image): the layer it weighs, -1 none
};

// Reads and checks the settings' user materials and splat maps for a heightmap of map_width x
// map_height samples. Without either, the generated layers alone (generateMaterialImages()). On
// bad input, errors get one line per problem and the set is empty (images.layers == 0).
MaterialSet loadMaterialSet(const TerrainSettings& s, int map_width, int map_height, InputErrors& errors);

// True when s names user materials or a splat map.
inline bool usesUserMaterials(const TerrainSettings& s) { return !s.materials.empty() || !s.splat_map.empty(); }

// s with every material and splat image path passed through resolve (the app's resolveInput).
TerrainSettings resolveMaterialPaths(TerrainSettings s, const std::function<std::filesystem::path(const std::filesystem::path&)>& resolve);

// The files of splat_map (separated by blanks).
std::vector<std::string> splatFiles(const TerrainSettings& s);

}  // namespace vista
