// The targets the scene passes share: the HDR light buffer, reversed-Z depth and the G-buffer.
//
// G-buffer (written by terrain.gbuffer and other opaque geometry, read by lighting.*):
//   hdr     RGBA16F  linear radiance before exposure. Geometry writes its emissive radiance
//                    here (0 for terrain); the lighting passes add reflected light on top.
//   albedo  RGBA8    rgb = sqrt(linear base colour) (a gamma-2 encoding: 8 bits keep dark
//                    colours), a = perceptual roughness in [0, 1] (GGX alpha = roughness^2).
//   normal  RGB10A2  rg = world-space normal, octahedral encoding mapped to [0, 1];
//                    b = specular reflectance F0 / 0.16 (Filament's "reflectance": 0.5 = 4 %);
//                    a = 1 lit, 0 unlit (the clear value: sky, debug geometry, emissive-only).
//   depth   Depth32F reversed-Z, infinite far plane (0 = infinitely far). Positions are rebuilt
//                    camera-relative from depth and the pixel (renderer/shaders/gbuffer.glsl).
// The encoding functions live in renderer/shaders/gbuffer.glsl; tests decode the same way.
#pragma once

#include "renderer/frame_graph.h"

namespace vista {

struct SceneTargets {
    TextureHandle hdr;     // RGBA16F linear radiance, before exposure
    TextureHandle depth;   // Depth32F, reversed-Z (0 = infinitely far)
    TextureHandle albedo;  // G-buffer (above); invalid when nothing opaque is drawn
    TextureHandle normal;
    TextureHandle light_heat;  // R32F local lights evaluated per pixel; only for [debug] view = lights
    TextureHandle ao;          // ambient occlusion in r, [0, 1] (1 = open); invalid: none (lighting.sun multiplies its ambient by it)
    TextureHandle cloud_shadow;  // R16F sun transmittance through the clouds (sky/clouds/clouds.h); invalid: none
    TextureHandle velocity;      // RGBA32F motion vectors ("temporal.velocity", renderer/velocity.h); invalid: none this frame
};

}  // namespace vista
