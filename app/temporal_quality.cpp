// Rendering for the temporal error figures. Every sequence starts from resetHistory() and gives
// each frame its sequence index, so a run's figures do not depend on what rendered before it.
#include "app/temporal_quality.h"

#include "app/image_metrics.h"

#include <algorithm>
#include <cmath>

namespace vista {

namespace {

void fixExposure(Settings& s, double exposure_scale) {
    if (exposure_scale <= 0.0) return;
    s.exposure.mode = ExposureMode::Manual;
    s.exposure.ev = float(std::clamp(std::log2(exposure_scale), -20.0, 20.0));
}

}  // namespace

std::vector<unsigned char> renderConvergedReference(FrameRenderer& renderer, Settings s, const ViewParams& view,
                                                    double time_s, double exposure_scale,
                                                    const TemporalQualityOptions& o) {
    const int factor = std::max(o.supersample, 1);
    ConvergedImage image(view.width, view.height, factor);
    // History-free: every frame is an independent estimate, so their mean converges (an
    // exponential history would keep the first frames' error and TAA would jitter on its own).
    s.taa.enabled = false;
    s.clouds.temporal = false;
    fixExposure(s, exposure_scale);
    ViewParams big = view;
    big.width = view.width * factor;
    big.height = view.height * factor;
    std::vector<unsigned char> ldr;
    FrameRequest request;
    request.capture_ldr = &ldr;
    request.animate_screen_noise = true;  // SSAO and the shadow kernels average over the frames too
    for (int i = 0; i < o.converge_frames; ++i) {
        renderer.resetHistory();
        request.sequence_frame = i;  // a different blue-noise offset every frame
        renderer.render(s, big, time_s, request);
        image.add(ldr);
    }
    renderer.timers().collect(/*wait=*/true);  // not the run's timings
    renderer.resetHistory();
    return image.result();
}


std::vector<double> renderCutCurve(FrameRenderer& renderer, Settings s, const ViewParams& view, double time_s,
                                   double exposure_scale, const std::vector<unsigned char>& converged,
                                   const TemporalQualityOptions& o) {
    std::vector<double> curve;
    if (converged.empty() || o.cut_frames <= 0) return curve;
    fixExposure(s, exposure_scale);
    std::vector<unsigned char> ldr;
    FrameRequest request;
    request.capture_ldr = &ldr;
    renderer.resetHistory();
    ViewParams away = view;  // the previous view: turned around, so no pixel of it belongs to `view`
    away.yaw_deg += 180.0;
    for (int i = 0; i < o.settle_frames; ++i) {
        request.sequence_frame = i;
        renderer.render(s, away, time_s, request);
    }
    for (int i = 0; i < o.cut_frames; ++i) {
        request.sequence_frame = o.settle_frames + i;
        renderer.render(s, view, time_s, request);
        ErrorAccumulator e;
        e.addLdr(ldr, converged, view.width, view.height);
        curve.push_back(e.result().psnr_db);
    }
    renderer.timers().collect(/*wait=*/true);
    return curve;
}

}  // namespace vista
