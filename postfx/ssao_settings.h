// [postfx.ssao]: screen-space ambient occlusion (postfx/ssao.h).
// describe() is the one description of the keys; config/settings.h gathers them into Settings.
#pragma once

#include "config/visitor.h"

namespace vista {

//! Screen-space ambient occlusion (horizon based, HBAO style) from depth and G-buffer normals,
//! computed before the lighting, which multiplies its ambient term by it. Not part of the
//! post chain's order: it runs wherever there is a G-buffer.
struct SsaoSettings {
    bool enabled = true;
    float radius_m = 2.0f;         //!< m, world-space reach of the horizon search, 0.01..100
    float intensity = 1.0f;        //!< strength: ao = 1 - intensity * occlusion, 0..4
    float bias = 0.1f;             //!< sine of the horizon angle ignored (against self-occlusion of flat ground), 0..0.9
    int directions = 4;            //!< horizon directions per pixel (rotated per pixel), 1..16
    int steps = 4;                 //!< depth samples along each direction, 1..32
    bool half_resolution = true;   //!< compute at half size; the blur upsamples depth-aware
    bool blur = true;              //!< 3x3 bilateral (depth-aware) blur; off: nearest upsample only
    float blur_depth_tolerance = 0.05f;  //!< relative depth difference at which blur weights fall by e, 0.001..1
};

// Lists the keys of SsaoSettings to v, in file order.
void describe(SettingsVisitor& v, SsaoSettings& s);

}  // namespace vista
