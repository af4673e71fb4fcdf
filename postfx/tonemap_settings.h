// [postfx.tonemap]: the tone mapping operator (postfx/tonemap.h).
// describe() is the one description of the keys; config/settings.h gathers them into Settings.
#pragma once

#include "config/visitor.h"

namespace vista {

enum class Tonemapper : int { Reinhard, Aces, Clamp, Agx };

struct TonemapSettings {
    bool enabled = true;
    Tonemapper op = Tonemapper::Aces;
    float white = 4.0f;  //!< linear value that maps to white (Reinhard)
};

// Lists the keys of TonemapSettings to v, in file order.
void describe(SettingsVisitor& v, TonemapSettings& s);

}  // namespace vista
