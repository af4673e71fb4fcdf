// The window panel's frame rate, from the wall time between presented frames (not from the
// animation step, which is clamped to 0.25 s and so reads 4 fps or more at any frame time).
#pragma once

namespace vista {

class FrameRateMeter {
public:
    // One frame's wall time in seconds (input, update, render, swap: the whole loop).
    void addFrame(double wall_s);
    // Frames per second over the smoothed frame time; 0 before the first frame.
    double fps() const { return frame_s_ > 0.0 ? 1.0 / frame_s_ : 0.0; }
    double frameMs() const { return frame_s_ * 1000.0; }

private:
    double frame_s_ = 0.0;  // exponential mean of the frame time (seeded by the first frame)
};

}  // namespace vista
