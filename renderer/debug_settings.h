// [debug]: the debug views and the reference grid (renderer/debug_view.h, debug_grid.h).
// describe() is the one description of the keys; config/settings.h gathers them into Settings.
#pragma once

#include "config/visitor.h"

namespace vista {

enum class DebugView : int { Final, Depth, Albedo, Normals, Lights, Cascades, ShadowMap, Shadow, SpotAtlas, PointShadows };

struct DebugSettings {
    DebugView view = DebugView::Final;
    bool grid = true;           //!< reference grid on the y = 0 plane
    float grid_spacing = 10.0f; //!< m between minor lines; major lines every 10
    float heat_max = 32.0f;     //!< lights per pixel shown red in the lights view, 1..65536
};

// Lists the keys of DebugSettings to v, in file order.
void describe(SettingsVisitor& v, DebugSettings& s);

}  // namespace vista
