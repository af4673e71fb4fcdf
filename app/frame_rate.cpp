// Smoothing the frame time, not the rate: a mean of 1/dt is dominated by the shortest frames
// (one 1 ms frame beside 5 s frames read as hundreds of fps), a mean of dt is not.
#include "app/frame_rate.h"

#include <algorithm>

namespace vista {

void FrameRateMeter::addFrame(double wall_s) {
    wall_s = std::max(wall_s, 1e-6);
    if (frame_s_ <= 0.0) {
        frame_s_ = wall_s;
        return;
    }
    // A slow frame (> 0.5 s) replaces the mean at once: at a few frames a minute a running mean
    // would lag by minutes.
    const double weight = wall_s > 0.5 ? 1.0 : 0.1;
    frame_s_ += (wall_s - frame_s_) * weight;
}

}  // namespace vista
