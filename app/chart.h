// Line charts as PNG (OpenImageIO): a few named series of (x, y) points on linear or log axes.
// The quality report's chart and the bench lights sweeps draw with the same font lookup and
// atomic write.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace vista {

struct ChartSeries {
    std::string name;
    std::vector<double> x, y;  // points in x order; non-finite or non-positive (log axes) ones are skipped
};

struct Chart {
    std::string title, x_label, y_label;
    bool log_x = false, log_y = false;
    std::vector<ChartSeries> series;
};

// The DejaVu Sans file, or "" when none is installed (charts then have no text).
std::string chartFontFile();

// Draws chart to file (PNG, 960x600) through a temporary name. "" or why not.
std::string writeChart(const std::filesystem::path& file, const Chart& chart);

}  // namespace vista
