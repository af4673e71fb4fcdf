// Line charts: axes with 1-2-5 ticks (log) or about eight ticks (linear), one colour per series,
// a legend in the top-left corner.
#include "app/chart.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace vista {
namespace {

constexpr std::array<std::array<float, 3>, 6> kColors{{{0.15f, 0.35f, 0.85f},
                                                      {0.1f, 0.6f, 0.2f},
                                                      {0.95f, 0.55f, 0.0f},
                                                      {0.85f, 0.1f, 0.1f},
                                                      {0.55f, 0.2f, 0.7f},
                                                      {0.3f, 0.3f, 0.3f}}};

struct Axis {
    bool log;
    double lo, hi;  // in axis units (log10 for log axes)
    double map(double v) const { return ((log ? std::log10(v) : v) - lo) / (hi - lo); }
    bool usable(double v) const { return std::isfinite(v) && (!log || v > 0.0); }
};

Axis makeAxis(bool log, double lo, double hi) {
    if (lo > hi) lo = hi = log ? 1.0 : 0.0;
    if (log) {
        lo = std::floor(std::log10(lo));
        hi = std::ceil(std::log10(hi));
        if (hi - lo < 1.0) hi = lo + 1.0;
    } else {
        if (lo > 0.0) lo = 0.0;  // linear axes start at zero: ratios read off the chart
        if (hi <= lo) hi = lo + 1.0;
    }
    return {log, lo, hi};
}

std::vector<double> ticks(const Axis& a) {
    std::vector<double> t;
    if (a.log) {
        for (int d = int(a.lo); d <= int(a.hi); ++d)
            for (double m : {1.0, 2.0, 5.0})
                if (double l = std::log10(m) + d; l <= a.hi + 1e-9) t.push_back(std::pow(10.0, l));
        return t;
    }
    const double raw = (a.hi - a.lo) / 8.0, mag = std::pow(10.0, std::floor(std::log10(raw)));
    const double step = raw / mag < 2.0 ? 2.0 * mag : raw / mag < 5.0 ? 5.0 * mag : 10.0 * mag;
    for (double v = std::ceil(a.lo / step) * step; v <= a.hi + 1e-9 * step; v += step) t.push_back(v);
    return t;
}

std::string label(double v) {
    char s[32];
    if (v != 0.0 && (std::abs(v) >= 1e5 || std::abs(v) < 1e-2))
        std::snprintf(s, sizeof s, "%.0e", v);
    else
        std::snprintf(s, sizeof s, "%g", v);
    return s;
}

}  // namespace

std::string chartFontFile() {
    for (const char* f : {"/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf", "/usr/share/fonts/TTF/DejaVuSans.ttf",
                          "/usr/share/fonts/dejavu/DejaVuSans.ttf"})
        if (std::filesystem::exists(f)) return f;
    return {};
}

std::string writeChart(const std::filesystem::path& file, const Chart& c) {
    namespace IBA = OIIO::ImageBufAlgo;
    const int w = 960, h = 600, x0 = 90, y0 = 50, x1 = w - 30, y1 = h - 70;
    OIIO::ImageBuf img(OIIO::ImageSpec(w, h, 3, OIIO::TypeDesc::FLOAT));
    const float white[3] = {1, 1, 1}, black[3] = {0, 0, 0}, grid[3] = {0.88f, 0.88f, 0.88f};
    IBA::fill(img, white);

    double xl = 1e300, xh = -1e300, yl = 1e300, yh = -1e300;
    const Axis probe_x{c.log_x, 0, 1}, probe_y{c.log_y, 0, 1};
    for (const ChartSeries& s : c.series)
        for (std::size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i)
            if (probe_x.usable(s.x[i]) && probe_y.usable(s.y[i])) {
                xl = std::min(xl, s.x[i]), xh = std::max(xh, s.x[i]);
                yl = std::min(yl, s.y[i]), yh = std::max(yh, s.y[i]);
            }
    const Axis ax = makeAxis(c.log_x, xl, xh), ay = makeAxis(c.log_y, yl, yh);
    auto px = [&](double v) { return x0 + int(std::lround(ax.map(v) * (x1 - x0))); };
    auto py = [&](double v) { return y1 - int(std::lround(ay.map(v) * (y1 - y0))); };

    const std::string font = chartFontFile();
    bool labels = !font.empty();
    auto text = [&](int x, int y, const std::string& s, int size, const float* color,
                    IBA::TextAlignX align = IBA::TextAlignX::Left) {
        if (labels && !IBA::render_text(img, x, y, s, size, font, OIIO::cspan<float>(color, 3), align)) labels = false;
    };
    for (double t : ticks(ax)) {
        IBA::render_line(img, px(t), y0, px(t), y1, grid);
        text(px(t), y1 + 18, label(t), 13, black, IBA::TextAlignX::Center);
    }
    for (double t : ticks(ay)) {
        IBA::render_line(img, x0, py(t), x1, py(t), grid);
        text(x0 - 8, py(t) + 5, label(t), 13, black, IBA::TextAlignX::Right);
    }
    IBA::render_box(img, x0, y0, x1, y1, black);
    text((x0 + x1) / 2, h - 25, c.x_label + (c.log_x ? " (log scale)" : ""), 15, black, IBA::TextAlignX::Center);
    text(10, y0 - 14, c.y_label + (c.log_y ? " (log scale)" : ""), 15, black);
    text(x0 + 200, 24, c.title, 15, black);

    for (std::size_t k = 0; k < c.series.size(); ++k) {
        const ChartSeries& s = c.series[k];
        const float* color = kColors[k % kColors.size()].data();
        int last_x = -1, last_y = -1;
        for (std::size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i) {
            if (!ax.usable(s.x[i]) || !ay.usable(s.y[i])) continue;
            const int x = px(s.x[i]), y = py(s.y[i]);
            if (last_x >= 0) IBA::render_line(img, last_x, last_y, x, y, OIIO::cspan<float>(color, 3));
            IBA::render_box(img, x - 3, y - 3, x + 3, y + 3, OIIO::cspan<float>(color, 3), true);
            last_x = x, last_y = y;
        }
        IBA::render_box(img, x0 + 10, y0 + 12 + 20 * int(k), x0 + 22, y0 + 24 + 20 * int(k), OIIO::cspan<float>(color, 3), true);
        text(x0 + 28, y0 + 24 + 20 * int(k), s.name, 14, color);
    }

    std::filesystem::path tmp = file;
    tmp += ".part";
    if (!img.write(tmp.string(), OIIO::TypeDesc::UINT8, "png")) return file.string() + ": " + img.geterror();
    std::error_code ec;
    std::filesystem::rename(tmp, file, ec);
    if (ec) return file.string() + ": cannot rename from " + tmp.string() + " (" + ec.message() + ")";
    return {};
}

}  // namespace vista
