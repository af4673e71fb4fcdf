// PSNR, SSIM and max error in double. SSIM filters x, y, x^2, y^2 and xy with the separable
// window over its valid positions, then averages the SSIM map.
#include "app/image_metrics.h"

#include "renderer/half.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace vista {
namespace {

std::vector<double> weights1d(int n, double sigma) {
    std::vector<double> w(std::size_t(n), 1.0);
    if (sigma > 0.0) {
        const double c = 0.5 * (n - 1);
        for (int i = 0; i < n; ++i) w[std::size_t(i)] = std::exp(-0.5 * (i - c) * (i - c) / (sigma * sigma));
    }
    double sum = 0.0;
    for (double x : w) sum += x;
    for (double& x : w) x /= sum;
    return w;
}

// Valid-mode separable filter of p (pw x ph) with wx along x and wy along y.
std::vector<double> filterValid(const std::vector<double>& p, int pw, int ph, const std::vector<double>& wx,
                                const std::vector<double>& wy) {
    const int nx = int(wx.size()), ny = int(wy.size());
    const int ow = pw - nx + 1, oh = ph - ny + 1;
    std::vector<double> rows(std::size_t(ow) * std::size_t(ph));
    for (int y = 0; y < ph; ++y)
        for (int x = 0; x < ow; ++x) {
            double s = 0.0;
            for (int i = 0; i < nx; ++i) s += wx[std::size_t(i)] * p[std::size_t(y) * std::size_t(pw) + std::size_t(x + i)];
            rows[std::size_t(y) * std::size_t(ow) + std::size_t(x)] = s;
        }
    std::vector<double> out(std::size_t(ow) * std::size_t(oh));
    for (int y = 0; y < oh; ++y)
        for (int x = 0; x < ow; ++x) {
            double s = 0.0;
            for (int j = 0; j < ny; ++j) s += wy[std::size_t(j)] * rows[std::size_t(y + j) * std::size_t(ow) + std::size_t(x)];
            out[std::size_t(y) * std::size_t(ow) + std::size_t(x)] = s;
        }
    return out;
}

double srgb8(unsigned char c) { return c / 255.0; }

double log2Luminance(const std::uint16_t* rgba) {
    double y = 0.2126 * halfToFloat(rgba[0]) + 0.7152 * halfToFloat(rgba[1]) + 0.0722 * halfToFloat(rgba[2]);
    if (std::isinf(y) && y > 0.0) y = 65504.0;
    if (!(y > std::exp2(kLog2LuminanceFloor))) return kLog2LuminanceFloor;  // also NaN
    return std::log2(y);
}

}  // namespace

double psnrFromMse(double mse, double peak) {
    if (mse <= 0.0) return std::numeric_limits<double>::infinity();
    return 10.0 * std::log10(peak * peak / mse);
}

double ssim(const Plane& a, const Plane& b, double l, const SsimOptions& o) {
    assert(a.width == b.width && a.height == b.height);
    if (a.width <= 0 || a.height <= 0) return 1.0;
    const std::vector<double> wx = weights1d(std::min(o.window, a.width), o.sigma);
    const std::vector<double> wy = weights1d(std::min(o.window, a.height), o.sigma);
    const std::size_t n = a.v.size();
    std::vector<double> aa(n), bb(n), ab(n);
    for (std::size_t i = 0; i < n; ++i) {
        aa[i] = a.v[i] * a.v[i];
        bb[i] = b.v[i] * b.v[i];
        ab[i] = a.v[i] * b.v[i];
    }
    const std::vector<double> mu_a = filterValid(a.v, a.width, a.height, wx, wy);
    const std::vector<double> mu_b = filterValid(b.v, a.width, a.height, wx, wy);
    const std::vector<double> e_aa = filterValid(aa, a.width, a.height, wx, wy);
    const std::vector<double> e_bb = filterValid(bb, a.width, a.height, wx, wy);
    const std::vector<double> e_ab = filterValid(ab, a.width, a.height, wx, wy);
    const double c1 = (o.k1 * l) * (o.k1 * l), c2 = (o.k2 * l) * (o.k2 * l);
    double sum = 0.0;
    for (std::size_t i = 0; i < mu_a.size(); ++i) {
        const double ma = mu_a[i], mb = mu_b[i];
        const double va = e_aa[i] - ma * ma, vb = e_bb[i] - mb * mb, cov = e_ab[i] - ma * mb;
        sum += (2.0 * ma * mb + c1) * (2.0 * cov + c2) / ((ma * ma + mb * mb + c1) * (va + vb + c2));
    }
    return sum / double(mu_a.size());
}

Plane lumaFromSrgb8(const std::vector<unsigned char>& rgba, int width, int height) {
    Plane p{width, height, std::vector<double>(std::size_t(width) * std::size_t(height))};
    for (std::size_t i = 0; i < p.v.size(); ++i)
        p.v[i] = 0.2126 * srgb8(rgba[4 * i]) + 0.7152 * srgb8(rgba[4 * i + 1]) + 0.0722 * srgb8(rgba[4 * i + 2]);
    return p;
}

Plane log2LuminanceFromHalf(const std::vector<std::uint16_t>& rgba, int width, int height) {
    Plane p{width, height, std::vector<double>(std::size_t(width) * std::size_t(height))};
    for (std::size_t i = 0; i < p.v.size(); ++i) p.v[i] = log2Luminance(&rgba[4 * i]);
    return p;
}

StopsRange log2LuminanceRange(const std::vector<std::vector<std::uint16_t>>& frames, int width, int height) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const auto& f : frames)
        for (double v : log2LuminanceFromHalf(f, width, height).v) {
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
    if (frames.empty()) return {};
    return {lo, std::max(1.0, hi - lo)};
}

void ErrorAccumulator::addLdr(const std::vector<unsigned char>& run, const std::vector<unsigned char>& reference,
                              int width, int height) {
    peak_ = 1.0;
    const std::size_t pixels = std::size_t(width) * std::size_t(height);
    for (std::size_t i = 0; i < pixels; ++i)
        for (std::size_t c = 0; c < 3; ++c) {
            const double d = srgb8(run[4 * i + c]) - srgb8(reference[4 * i + c]);
            squared_ += d * d;
            max_ = std::max(max_, std::abs(d) * 255.0);
        }
    samples_ += 3.0 * double(pixels);
    ssim_sum_ += ssim(lumaFromSrgb8(run, width, height), lumaFromSrgb8(reference, width, height), 1.0);
    ++frames_;
}

void ErrorAccumulator::addHdr(const std::vector<std::uint16_t>& run, const std::vector<std::uint16_t>& reference,
                              int width, int height, const StopsRange& range) {
    peak_ = range.range;
    Plane a = log2LuminanceFromHalf(run, width, height), b = log2LuminanceFromHalf(reference, width, height);
    for (double& v : a.v) v -= range.lo;
    for (double& v : b.v) v -= range.lo;
    for (std::size_t i = 0; i < a.v.size(); ++i) {
        const double d = a.v[i] - b.v[i];
        squared_ += d * d;
        max_ = std::max(max_, std::abs(d));
    }
    samples_ += double(a.v.size());
    ssim_sum_ += ssim(a, b, range.range);
    ++frames_;
}

ImageError ErrorAccumulator::result() const {
    ImageError e;
    if (frames_ == 0) return e;
    e.psnr_db = psnrFromMse(squared_ / samples_, peak_);
    e.ssim = ssim_sum_ / frames_;
    e.max_error = max_;
    return e;
}

}  // namespace vista
