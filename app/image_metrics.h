// Image error against a reference for `vista quality`: PSNR, SSIM (Wang et al. 2004) and the
// largest error, in double, on single-channel planes. No GL.
//
// The report's two domains:
//  - LDR: the final sRGB image, 8-bit values / 255. PSNR over R, G and B with peak 1; SSIM on
//    the luma 0.2126 R' + 0.7152 G' + 0.0722 B' of the sRGB-encoded values (L = 1); max error
//    the largest channel difference in 8-bit levels.
//  - HDR: the scene's linear HDR target before the post chain, as log2 luminance (stops),
//    log2(max(Y, 2^-16)) with Y = 0.2126 R + 0.7152 G + 0.0722 B, less the reference's darkest
//    pixel (so the reference spans 0..range). PSNR and SSIM take that range (its brightest
//    minus its darkest pixel, in stops) as the peak / L; max error is in stops.
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

namespace vista {

// One channel, row-major, width * height values.
struct Plane {
    int width = 0, height = 0;
    std::vector<double> v;
};

// 10 log10(peak^2 / mse); +infinity when mse is 0.
double psnrFromMse(double mse, double peak);

struct SsimOptions {
    int window = 11;     // window side (clamped to the image's sides)
    double sigma = 1.5;  // Gaussian weights' sigma in pixels; <= 0: uniform weights
    double k1 = 0.01, k2 = 0.03;
};

// Mean SSIM over every window position fully inside both planes (Wang et al. 2004, eq. 13,
// with weighted means, variances and covariance), dynamic range l. Planes of equal size.
double ssim(const Plane& a, const Plane& b, double l, const SsimOptions& options = {});

// Planes from captured frames (RGBA, top row first).
Plane lumaFromSrgb8(const std::vector<unsigned char>& rgba, int width, int height);  // 0..1
Plane log2LuminanceFromHalf(const std::vector<std::uint16_t>& rgba, int width, int height);
inline constexpr double kLog2LuminanceFloor = -16.0;

// The darkest log2 luminance over frames (RGBA half) and the range up to the brightest (at least 1 stop).
struct StopsRange {
    double lo = 0.0, range = 1.0;
};
// Error of a run's frames against the reference's, pooled over frames: PSNR from the mean
// squared error over every frame, SSIM the mean of the frames', max error the largest.
struct ImageError {
    double psnr_db = std::numeric_limits<double>::infinity();
    double ssim = 1.0;
    double max_error = 0.0;
};

class ErrorAccumulator {
public:
    // LDR: RGBA8 sRGB frames.
    void addLdr(const std::vector<unsigned char>& run, const std::vector<unsigned char>& reference, int width, int height);
    // HDR: RGBA half frames; range is the reference's (the same for every frame of a report).
    void addHdr(const std::vector<std::uint16_t>& run, const std::vector<std::uint16_t>& reference, int width,
                int height, const StopsRange& range);
    ImageError result() const;

private:
    double peak_ = 1.0;
    double squared_ = 0.0, samples_ = 0.0, ssim_sum_ = 0.0, max_ = 0.0;
    int frames_ = 0;
};

StopsRange log2LuminanceRange(const std::vector<std::vector<std::uint16_t>>& frames, int width, int height);

}  // namespace vista
