// The aerial-perspective volume as other features read it: sky/atmosphere.h writes it each frame
// ("sky.aerial_volume"), "sky.aerial" fogs every pixel at its depth with it, and forward
// surfaces drawn after that pass (the glass, renderer/meshes/objects.h) fog themselves with it
// at their own distance. The layout (renderer/shaders/aerial_fetch.glsl reads it): `slices`
// tiles of size x size froxels side by side in two RGBA16F atlases, in-scattered radiance (HDR
// linear sRGB) and transmittance from the camera to the far end of slice k, at distance
// range_km * ((k + 1) / slices)^2 along the view ray through the froxel's screen position.
#pragma once

#include "renderer/frame_graph.h"

#include <glm/vec4.hpp>

namespace vista {

struct AerialVolume {
    TextureHandle inscatter, transmittance;  // this frame's atlases (transient: read by later passes)
    glm::vec4 layout{0.0f};                  // x range (km), y froxels per side, z slices (aerial_fetch.glsl)
    bool valid() const { return inscatter.valid() && transmittance.valid(); }
};

}  // namespace vista
