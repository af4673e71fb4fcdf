// [postfx.dof]: depth of field (postfx/dof.h).
// describe() is the one description of the keys; config/settings.h gathers them into Settings.
#pragma once

#include "config/visitor.h"

namespace vista {

//! Depth of field: a thin-lens circle of confusion from the focus distance, focal length and
//! f-stop (postfx/dof.h has the formula), autofocus on the screen centre smoothed over time, and
//! a gather blur with a separate near field so that the foreground bleeds over what is in focus.
struct DofSettings {
    bool enabled = false;
    float focus_distance_m = 50.0f;  //!< m, focus distance when autofocus is off, 0.1..1e6
    float focal_length_mm = 50.0f;   //!< mm, lens focal length, 1..2000
    float f_stop = 2.8f;             //!< f-number N (aperture diameter = focal length / N), 0.5..64
    float sensor_height_mm = 24.0f;  //!< mm, sensor height (maps the CoC to pixels of the image height), 1..100
    bool autofocus = true;           //!< focus on the screen centre (median of 5 depth samples)
    float autofocus_rate = 4.0f;     //!< 1/s, the focus (in diopters) closes the gap by e in 1/rate s, 0.01..100
    float max_coc_px = 16.0f;        //!< px, largest blur radius, 1..64
    int samples = 32;                //!< gather taps per pixel (Vogel disk), 4..256
    bool debug = false;              //!< the CoC replaces the final image: red far, green near, blue in focus
};

// Lists the keys of DofSettings to v, in file order.
void describe(SettingsVisitor& v, DofSettings& s);

}  // namespace vista
