// The temporal columns of `vista quality` and `vista bench temporal` (docs/temporal.md,
// "Temporal error"): renders the converged, supersampled reference of a frame and the frames
// after a camera cut; app/temporal_metrics.h does the arithmetic.
#pragma once

#include "app/frame.h"
#include "app/temporal_metrics.h"

#include <vector>

namespace vista {

// The converged reference of one frame: options.converge_frames frames at options.supersample
// times the size, each after resetHistory() with TAA and temporal clouds off and a different
// blue-noise index, averaged in linear light and box-filtered down. exposure_scale > 0 fixes the
// exposure (manual) at that scale: the auto exposure the reference run had at that frame, which
// history-free frames would otherwise meter anew. Leaves the renderer's history reset.
std::vector<unsigned char> renderConvergedReference(FrameRenderer& renderer, Settings settings, const ViewParams& view,
                                                    double time_s, double exposure_scale,
                                                    const TemporalQualityOptions& options);

// The camera-cut sequence: resetHistory(), settle_frames frames at `view` turned 180 degrees,
// then cut_frames frames at `view`; returns each of those frames' LDR PSNR against `converged`.
// exposure_scale > 0 fixes the exposure (manual) at the run's own: time stands still here, so
// auto exposure would keep the turned-away view's metering and hide the history's convergence.
std::vector<double> renderCutCurve(FrameRenderer& renderer, Settings settings, const ViewParams& view, double time_s,
                                   double exposure_scale, const std::vector<unsigned char>& converged,
                                   const TemporalQualityOptions& options);

}  // namespace vista
