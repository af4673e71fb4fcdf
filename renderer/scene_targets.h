// The targets the scene passes share: HDR colour (RGBA16F, linear) and reversed-Z depth.
#pragma once

#include "renderer/frame_graph.h"

namespace vista {

struct SceneTargets {
    TextureHandle hdr;    // RGBA16F linear radiance, before exposure
    TextureHandle depth;  // Depth32F, reversed-Z (0 = infinitely far)
};

}  // namespace vista
