// [weather]: the keys, units, ranges and help text.
#include "sky/weather/weather_settings.h"

#include <array>

namespace vista {

void describe(SettingsVisitor& v, WeatherSettings& s) {
    static constexpr std::array<const char*, 2> kinds{"rain", "snow"};
    v.section("weather", "rain or snow around the camera: falling streaks, splashes, wet terrain");
    v.field({"enabled", "", "draw rain or snow (off: no pass, no buffer, dry terrain)"}, s.enabled);
    v.choice({"kind", "", "rain: velocity streaks, splashes and wet ground; snow: slow swaying flakes"}, s.kind, kinds);
    v.field({"intensity", "", "share of max_density drawn; also streak opacity, splash rate and wetness"}, s.intensity, 0.0f, 1.0f);
    v.field({"max_density", "1/m^3", "drops per cubic metre at intensity 1"}, s.max_density, 0.01f, 50.0f);
    v.field({"radius_m", "m", "drops are drawn up to this distance (fading over its last quarter)"}, s.radius_m, 2.0f, 100.0f);
    v.field({"cell_m", "m", "side of a placement cell; each cell's drops come from a hash of its coordinates"}, s.cell_m, 0.5f, 8.0f);
    v.field({"near_fade_m", "m", "drops closer than this are left out; they fade in over the next near_fade_m"}, s.near_fade_m, 0.0f, 10.0f);
    v.field({"drop_speed_m_s", "m/s", "fall speed (rain 4..9, snow 0.5..1.5)"}, s.drop_speed_m_s, 0.1f, 50.0f);
    v.field({"drop_width_m", "m", "streak width (rain) or flake diameter (snow)"}, s.drop_width_m, 0.0005f, 0.1f);
    v.field({"streak_time_s", "s", "a streak spans the drop's motion relative to the camera over this time"}, s.streak_time_s, 0.0f, 0.5f);
    v.field({"brightness", "", "scale of the sun and sky light a drop sends back"}, s.brightness, 0.0f, 20.0f);
    v.field({"wind_from_clouds", "", "use the wind of [clouds.low] times wind_scale (off: wind_speed_m_s, wind_direction_deg)"}, s.wind_from_clouds);
    v.field({"wind_scale", "", "share of the low cloud layer's wind felt near the ground"}, s.wind_scale, 0.0f, 2.0f);
    v.field({"wind_speed_m_s", "m/s", "horizontal wind when wind_from_clouds is off"}, s.wind_speed_m_s, 0.0f, 100.0f);
    v.field({"wind_direction_deg", "deg", "heading the wind blows toward, clockwise from -z (wind_from_clouds off)"}, s.wind_direction_deg, -360.0f, 360.0f);
    v.field({"splashes", "", "rain: short-lived splashes on the terrain (weather.splash)"}, s.splashes);
    v.field({"splash_rate", "1/(m^2 s)", "splashes per square metre per second at intensity 1"}, s.splash_rate, 0.0f, 1000.0f);
    v.field({"splash_radius_m", "m", "splashes are drawn up to this distance"}, s.splash_radius_m, 1.0f, 50.0f);
    v.field({"splash_size_m", "m", "largest radius of a splash's crown"}, s.splash_size_m, 0.005f, 1.0f);
    v.field({"splash_life_s", "s", "a splash grows and fades over this time"}, s.splash_life_s, 0.01f, 2.0f);
    v.field({"wetness", "", "rain: how wet the terrain gets at intensity 0.5 and above (darker, glossier)"}, s.wetness, 0.0f, 1.0f);
}

}  // namespace vista
