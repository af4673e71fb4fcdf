// The day/night cycle (sky/day_cycle.h). Time is added in double and wrapped once, so a long
// run keeps its precision (a float time of day would step in whole seconds after ~2 days).
#include "sky/day_cycle.h"

#include <cmath>

namespace vista {

namespace {

double wrap(double v, double period) {
    const double r = std::fmod(v, period);
    return r < 0.0 ? r + period : r;
}

}  // namespace

SkySettings skyAtTime(const SkySettings& sky, double scene_time_s) {
    if (sky.sun_mode != SunMode::Time || sky.time_scale == 0.0f || !std::isfinite(scene_time_s)) return sky;
    SkySettings out = sky;
    const double hours = double(sky.time_of_day_h) + double(sky.time_scale) * scene_time_s;
    const double days = std::floor(hours / 24.0);
    out.time_of_day_h = float(wrap(hours, 24.0));
    if (out.time_of_day_h >= 24.0f) out.time_of_day_h = 0.0f;  // float rounding of 23.99999...
    out.day_of_year = float(1.0 + wrap(double(sky.day_of_year) - 1.0 + days, 365.0));
    // The moon's age follows the continuous time (its phase changes through the night).
    out.moon_age_days = float(wrap(double(sky.moon_age_days) + (hours - double(sky.time_of_day_h)) / 24.0,
                                   kSynodicMonthDays));
    return out;
}

}  // namespace vista
