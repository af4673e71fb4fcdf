// [postfx.bloom] (postfx/bloom.h).
// describe() is the one description of the keys; config/settings.h gathers them into Settings.
#pragma once

#include "config/visitor.h"

namespace vista {

//! Bloom after Jimenez 2014: a 13-tap downsample chain (Karis average on the first level),
//! tent-filtered upsampling back up, blended into the image.
struct BloomSettings {
    bool enabled = true;
    float intensity = 0.04f;  //!< share of the blurred image in the result (mix), 0..1
    float radius = 0.7f;      //!< weight of each coarser level while upsampling: 0 tight, 1 wide, 0..1
    int levels = 5;           //!< downsample levels (each half the size), 1..10
    float clamp = 1000.0f;    //!< highlights are clamped to this before blurring (NaN/Inf to 0), 1..65504
};

// Lists the keys of BloomSettings to v, in file order.
void describe(SettingsVisitor& v, BloomSettings& s);

}  // namespace vista
