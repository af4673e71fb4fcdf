// [postfx.exposure]: manual, auto or camera exposure (postfx/exposure.h).
// describe() is the one description of the keys; config/settings.h gathers them into Settings.
#pragma once

#include "config/visitor.h"

namespace vista {

enum class ExposureMode : int { Manual, Auto, Camera };

//! Exposure: a scale 2^ev (manual), or one that brings the metered average luminance to middle
//! grey (0.18) times 2^ev (auto), metered from a log-luminance histogram and adapted over time,
//! or a physical camera's (camera): EV100 = log2(N^2 / t * 100 / S) from the lens's f-number N
//! ([postfx.dof] f_stop), the shutter time t ([postfx.motion_blur] shutter_deg / 360 / frame_rate)
//! and the sensitivity S (iso), whether or not depth of field and motion blur are on; a luminance
//! of 1.2 * 2^EV100 cd/m^2 (the sensor's saturation, ISO 12232) maps to 1, times 2^ev.
struct ExposureSettings {
    bool enabled = true;
    ExposureMode mode = ExposureMode::Auto;
    float ev = 0.0f;              //!< stops of compensation (manual: scale = 2^ev), -20..20
    float min_ev = -32.0f;        //!< auto: lowest metered log2 luminance (darker scenes stay darker; -32: a moonless night), -40..20
    float max_ev = 16.0f;         //!< auto: highest metered log2 luminance, -40..20
    //! auto: stops darker than middle grey once the adapted luminance is scotopic (below
    //! 0.005 cd/m^2; none above 5 cd/m^2, log-smooth between): night reads as night, 0..10
    float night_ev = 2.5f;
    float low_percent = 40.0f;    //!< auto: darkest pixels left out of the average, % of the histogram, 0..99
    float high_percent = 95.0f;   //!< auto: pixels above this percentile left out (highlights), 1..100
    float speed_up = 3.0f;        //!< auto: adaptation rate towards a brighter scene, stops settle by e per 1/rate s, 0.01..100
    float speed_down = 1.0f;      //!< auto: adaptation rate towards a darker scene, 1/s, 0.01..100
    float iso = 100.0f;           //!< camera: sensitivity S (ISO arithmetic), 1..1e6
};

// Lists the keys of ExposureSettings to v, in file order.
void describe(SettingsVisitor& v, ExposureSettings& s);

}  // namespace vista
