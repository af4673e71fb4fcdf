// [weather]: rain or snow around the camera (sky/weather/weather.h).
// describe() is the one description of the keys; config/settings.h gathers them into Settings.
#pragma once

#include "config/visitor.h"

namespace vista {

enum class WeatherKind : int { Rain, Snow };

//! Rain or snow around the camera (sky/weather/weather.h): drops placed per world cell of a box that
//! moves with the camera, falling with the wind, drawn as camera-facing streaks oriented by their
//! velocity relative to the camera ("weather.rain"), splashes on the ground ("weather.splash")
//! and wet, darker and glossier terrain. Off: no pass, no object, dry terrain.
struct WeatherSettings {
    bool enabled = false;              //!< off: no pass, no buffer, the terrain stays dry
    WeatherKind kind = WeatherKind::Rain;  //!< rain: streaks, splashes, wet ground; snow: slow swaying flakes only
    float intensity = 0.5f;            //!< 0..1: share of max_density drawn, streak opacity, splash rate, wetness
    float max_density = 3.0f;          //!< drops per m^3 at intensity 1 (visible streaks, not every real drop), 0.01..50
    float radius_m = 16.0f;            //!< m, drops are drawn up to this distance (fading over its last 25%), 2..100
    float cell_m = 2.0f;               //!< m, side of a placement cell (drops per cell = max_density * cell^3, at most 256), 0.5..8
    float near_fade_m = 0.3f;          //!< m, drops closer than this are left out; they fade in over the next near_fade_m, 0..10
    float drop_speed_m_s = 8.0f;       //!< m/s, fall speed (rain 4..9, snow 0.5..1.5), 0.1..50
    float drop_width_m = 0.003f;       //!< m, streak width (rain) or flake diameter (snow), 0.0005..0.1
    float streak_time_s = 0.02f;       //!< s, a streak spans the drop's motion relative to the camera over this time (its length), 0..0.5
    float brightness = 1.0f;           //!< scale of the light a drop sends back (sun and sky irradiance at the camera), 0..20
    bool wind_from_clouds = true;      //!< on: the wind of [clouds.low] times wind_scale; off: wind_speed_m_s toward wind_direction_deg
    float wind_scale = 0.4f;           //!< share of the low cloud layer's wind felt near the ground, 0..2
    float wind_speed_m_s = 3.0f;       //!< m/s, horizontal wind when wind_from_clouds is off, 0..100
    float wind_direction_deg = 60.0f;  //!< deg, heading the wind blows toward, clockwise from -z, -360..360
    bool splashes = true;              //!< rain: short-lived splashes on the terrain ("weather.splash")
    float splash_rate = 40.0f;         //!< splashes per m^2 per s at intensity 1, 0..1000
    float splash_radius_m = 10.0f;     //!< m, splashes drawn up to this distance, 1..50
    float splash_size_m = 0.06f;       //!< m, largest radius of a splash's crown, 0.005..1
    float splash_life_s = 0.12f;       //!< s, a splash grows and fades over this time, 0.01..2
    float wetness = 0.8f;              //!< rain: how wet the terrain gets at intensity >= 0.5 (darker, lower roughness), 0..1
};

// Lists the keys of WeatherSettings to v, in file order.
void describe(SettingsVisitor& v, WeatherSettings& s);

}  // namespace vista
