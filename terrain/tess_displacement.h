// The tessellated terrain's displacement (terrain/shaders/terrain_tess.glsl) on the CPU, in double:
// which relief, how deep, and where it fades out. terrain.cpp sets the shader's uniforms from
// tessRelief(), so the shader and this mirror take their numbers from one place; the GL test
// compares rendered points of the displaced surface with tessDisplacement().
#pragma once

#include "terrain/materials.h"

#include <glm/glm.hpp>

namespace vista {

struct TessRelief {
    double depth_m = 0.1;          // relief height 0 lies this far below the drawn surface (height 1)
    double period_m = 4.0;         // metres per repeat of the relief texture
    double fade_start_m = 20.0;    // full displacement nearer than this (camera distance)
    double fade_end_m = 36.0;      // none from here on: the factors are 1 too
    int layer = int(MaterialLayer::Rock);  // whose relief: the pixel's layer blend is out of reach per vertex
};

// The relief for [terrain.tessellation] depth_m and range_m, with the rock layer repeating every
// period_m: full up to half the range, none from 90% of it, so the outermost tessellated quadrants
// meet their untessellated neighbours flat (and with factor 1).
TessRelief tessRelief(double depth_m, double range_m, double period_m);

// Share of the displacement left at distance_m from the camera (smoothstep, as GLSL's).
double tessFade(const TessRelief& r, double distance_m);

// A layer's relief height (0..1) at texture coordinates (u, v) as the GPU samples it at mip 0:
// bilinear between texel centres, repeating.
double reliefAt(const MaterialImages& m, int layer, double u, double v);

// The displacement (m, <= 0, vertical) of the undisplaced surface point `rel` (camera-relative,
// m) whose position relative to the terrain origin is world_xz (what the relief repeats over).
double tessDisplacement(const MaterialImages& m, const TessRelief& r, const glm::dvec3& rel, const glm::dvec2& world_xz);

}  // namespace vista
