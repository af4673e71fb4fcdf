// The live Dear ImGui panel: stats (fps, per-pass GPU/CPU table, counters, culled passes,
// shader errors), every setting edited through the one description (a new setting appears
// here without UI code), scene presets and "save scene as".
#pragma once

#include "app/stats.h"
#include "config/settings.h"

#include <deque>
#include <filesystem>
#include <string>
#include <vector>

namespace vista {

// Stats the window loop gathers for the panel.
struct PanelStats {
    double fps = 0.0, cpu_ms = 0.0, gpu_ms = 0.0, reference_copy_ms = 0.0;
    double time_s = 0.0;
    bool paused = false;
    std::vector<PassTiming> passes;  // latest complete GPU frame
    std::vector<std::string> culled;
    std::map<std::string, double> counters;
    std::vector<std::string> shader_errors;
    std::size_t pool_textures = 0;
    std::string renderer;
};

class Panel {
public:
    explicit Panel(std::filesystem::path scene_file);
    // Draws the panel; returns true when a setting changed.
    bool draw(Settings& s, const PanelStats& stats);
    bool visible = true;

private:
    void drawStats(const PanelStats& stats);
    bool drawPresets(Settings& s);
    void drawSave(Settings& s);

    std::filesystem::path scene_file_;
    std::string save_path_;
    std::string message_;  // result of the last preset/save action
    std::vector<std::filesystem::path> presets_;
    int preset_ = 0;
};

// Edits any settings struct through its describe() function; returns true on a change.
bool editSettings(Settings& s);

}  // namespace vista
