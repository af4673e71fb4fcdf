// The day/night cycle: [sky] time_scale advances the time of day with scene time (sun_mode =
// time), carrying the day of the year and the moon's age along, so the sun, the moon and the
// stars move together. A function of the settings and the scene time alone (a capture shard
// renders frame k as a sequential run does).
#pragma once

#include "sky/sky_settings.h"

namespace vista {

// Days from one new moon to the next (the moon's phase repeats with it).
inline constexpr double kSynodicMonthDays = 29.530589;

// sky with time_of_day_h advanced by time_scale hours per second of scene_time_s, wrapped to
// [0, 24) with day_of_year (wrapped to [1, 366)) and moon_age_days (to the synodic month)
// advanced by the whole days passed. Unchanged when time_scale is 0 or sun_mode is angles.
SkySettings skyAtTime(const SkySettings& sky, double scene_time_s);

}  // namespace vista
