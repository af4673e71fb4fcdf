// Temporal error of a frame sequence for `vista quality` and `vista bench temporal`
// (docs/temporal.md, "Temporal error"): a converged, supersampled reference image, flicker
// (per-pixel luminance change between consecutive frames after reprojecting one onto the
// other) and the frames a camera cut takes to converge. No GL: frames are CPU copies.
#pragma once

#include "renderer/camera.h"

#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace vista {

// Averages frames rendered at `factor` times the size in linear light (sRGB decoded), every
// factor x factor block into one pixel: the converged reference is the mean of many history-free
// frames with different blue-noise offsets, each supersampled.
class ConvergedImage {
public:
    ConvergedImage(int width, int height, int factor);
    // One RGBA8 sRGB frame of (width * factor) x (height * factor), top row first.
    void add(const std::vector<unsigned char>& rgba);
    int frames() const { return frames_; }
    // RGBA8 sRGB at width x height (alpha 255); empty before the first frame.
    std::vector<unsigned char> result() const;

private:
    int width_, height_, factor_, frames_ = 0;
    std::vector<double> sum_;  // linear R, G, B per output pixel
};

// One frame as the flicker measure sees it: the final image, the reversed-Z depth (0: sky; one
// float a pixel, top row first, as FrameRequest::depth) and the unjittered camera.
struct SequenceFrame {
    std::vector<unsigned char> ldr;  // RGBA8 sRGB, top row first
    std::vector<float> depth;
    ViewParams view;
};

// |luma(current) - luma(previous at the reprojected position)| in 8-bit levels (Rec. 709 luma of
// the sRGB values), for every pixel of `current` whose point (from its depth; sky as a point
// 10^6 m away) lands inside `previous` and is not occluded there (the previous frame's depth
// at that texel within 5 % of the reprojected distance). The previous image is sampled bilinearly.
std::vector<double> reprojectedLumaChange(const SequenceFrame& previous, const SequenceFrame& current);

struct FlickerStats {
    double mean = 0.0, p99 = 0.0;  // 8-bit luma levels
    std::size_t samples = 0;       // reprojected pixels over every frame pair
};
FlickerStats flickerStats(std::vector<double> changes);

// The first index from which no later value is more than tolerance_db below the last one (the
// converged value): frames after a camera cut (index 0 is the cut frame) until the image is as
// close to the reference as it gets. -1 for an empty curve.
int framesUntilConverged(const std::vector<double>& psnr_db, double tolerance_db = 1.0);

// How `vista quality` measures the temporal figures (app/temporal_quality.h).
struct TemporalQualityOptions {
    int settle_frames = 8;     // frames at the turned-away view before the cut (history to forget)
    int cut_frames = 16;       // frames after the cut (0: no ghosting figure)
    int converge_frames = 16;  // history-free frames averaged into the converged reference (0: none)
    int supersample = 2;       // the converged reference's frames at this many times the size, box-filtered
};

// A run's temporal figures. The flicker of the reference sequence is the reference run's own.
struct TemporalFigures {
    double single_psnr_db = std::numeric_limits<double>::quiet_NaN();  // first measured frame vs converged (NaN: not measured)
    FlickerStats flicker;                                              // over the measured frames' consecutive pairs
    int ghost_frames = -1;                                             // frames after the cut until within 1 dB (-1: not measured)
    double converged_psnr_db = std::numeric_limits<double>::quiet_NaN();  // the cut curve's last value
    std::vector<double> cut_psnr_db;                                   // every frame after the cut against the converged reference
};

}  // namespace vista
