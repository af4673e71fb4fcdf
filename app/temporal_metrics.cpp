// Temporal error measures. The flicker reprojection follows what the temporal passes do on the
// GPU (camera-relative points, the camera's translation in double: renderer/temporal.h), so a
// static scene seen by a moving camera changes by nothing but the renderer's own noise.
#include "app/temporal_metrics.h"

#include "app/image_metrics.h"
#include "renderer/temporal.h"

#include <glm/matrix.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace vista {
namespace {

const std::array<double, 256>& srgbToLinear() {
    static const std::array<double, 256> table = [] {
        std::array<double, 256> t{};
        for (int i = 0; i < 256; ++i) {
            const double c = i / 255.0;
            t[std::size_t(i)] = c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
        }
        return t;
    }();
    return table;
}

unsigned char linearToSrgb8(double v) {
    v = std::clamp(v, 0.0, 1.0);
    const double c = v <= 0.0031308 ? v * 12.92 : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
    return static_cast<unsigned char>(std::lround(c * 255.0));
}

// A point this far away stands for the sky (depth 0, at infinity): far enough that the camera's
// translation between frames moves it by well under a pixel, near enough to stay finite.
constexpr double kSkyDistanceM = 1.0e6;
constexpr double kOcclusionTolerance = 0.05;  // relative distance difference still "the same surface"

}  // namespace

ConvergedImage::ConvergedImage(int width, int height, int factor)
    : width_(std::max(width, 1)), height_(std::max(height, 1)), factor_(std::max(factor, 1)),
      sum_(std::size_t(width_) * std::size_t(height_) * 3, 0.0) {}

void ConvergedImage::add(const std::vector<unsigned char>& rgba) {
    const int big_w = width_ * factor_;
    if (rgba.size() < std::size_t(big_w) * std::size_t(height_ * factor_) * 4) return;
    const auto& lin = srgbToLinear();
    for (int y = 0; y < height_ * factor_; ++y)
        for (int x = 0; x < big_w; ++x) {
            const unsigned char* p = &rgba[(std::size_t(y) * std::size_t(big_w) + std::size_t(x)) * 4];
            double* s = &sum_[(std::size_t(y / factor_) * std::size_t(width_) + std::size_t(x / factor_)) * 3];
            for (int c = 0; c < 3; ++c) s[c] += lin[p[c]];
        }
    ++frames_;
}

std::vector<unsigned char> ConvergedImage::result() const {
    if (frames_ == 0) return {};
    std::vector<unsigned char> out(std::size_t(width_) * std::size_t(height_) * 4, 255);
    const double n = double(frames_) * double(factor_) * double(factor_);
    for (std::size_t i = 0; i < std::size_t(width_) * std::size_t(height_); ++i)
        for (int c = 0; c < 3; ++c) out[i * 4 + std::size_t(c)] = linearToSrgb8(sum_[i * 3 + std::size_t(c)] / n);
    return out;
}

std::vector<double> reprojectedLumaChange(const SequenceFrame& previous, const SequenceFrame& current) {
    const int w = current.view.width, h = current.view.height;
    std::vector<double> changes;
    const std::size_t pixels = std::size_t(w) * std::size_t(h);
    if (w != previous.view.width || h != previous.view.height || current.ldr.size() < pixels * 4 ||
        previous.ldr.size() < pixels * 4 || current.depth.size() < pixels || previous.depth.size() < pixels)
        return changes;
    const Plane now = lumaFromSrgb8(current.ldr, w, h), before = lumaFromSrgb8(previous.ldr, w, h);
    const ViewMatrices m = viewMatrices(current.view);
    const glm::dmat4 inv = glm::inverse(glm::dmat4(m.view_proj));
    const glm::dmat4 to_previous = previousClipFromRelative(previous.view, current.view);
    const double near_m = std::max(current.view.near_m, 1e-6);
    const double sky_depth = near_m / kSkyDistanceM;
    changes.reserve(pixels);
    for (int r = 0; r < h; ++r)
        for (int x = 0; x < w; ++x) {
            const float d = current.depth[std::size_t(r) * std::size_t(w) + std::size_t(x)];
            const bool sky = !(d > 0.0f);
            const glm::dvec4 ndc(2.0 * (x + 0.5) / w - 1.0, 1.0 - 2.0 * (r + 0.5) / h, sky ? sky_depth : double(d), 1.0);
            const glm::dvec4 p = inv * ndc;
            if (!(std::abs(p.w) > 0.0)) continue;
            const glm::dvec4 clip = to_previous * glm::dvec4(glm::dvec3(p) / p.w, 1.0);
            if (!(clip.w > 0.0)) continue;  // behind the previous camera
            const double px = (clip.x / clip.w + 1.0) * 0.5 * w - 0.5, py = (1.0 - clip.y / clip.w) * 0.5 * h - 0.5;
            if (!(px >= 0.0 && py >= 0.0 && px <= w - 1.0 && py <= h - 1.0)) continue;
            // Occlusion: the previous frame saw this point only if its depth there is the point's.
            const int nx = int(std::lround(px)), ny = int(std::lround(py));
            const double seen = previous.depth[std::size_t(ny) * std::size_t(w) + std::size_t(nx)];
            if (sky) {
                if (seen > 0.0) continue;
            } else {
                const double expected = clip.z / clip.w;  // reversed-Z: near / distance
                if (!(seen > 0.0) || std::abs(expected / seen - 1.0) > kOcclusionTolerance) continue;
            }
            const int x0 = std::min(int(px), w - 2 < 0 ? 0 : w - 2), y0 = std::min(int(py), h - 2 < 0 ? 0 : h - 2);
            const int x1 = std::min(x0 + 1, w - 1), y1 = std::min(y0 + 1, h - 1);
            const double fx = std::clamp(px - x0, 0.0, 1.0), fy = std::clamp(py - y0, 0.0, 1.0);
            auto at = [&](int xx, int yy) { return before.v[std::size_t(yy) * std::size_t(w) + std::size_t(xx)]; };
            const double sampled = (at(x0, y0) * (1 - fx) + at(x1, y0) * fx) * (1 - fy) + (at(x0, y1) * (1 - fx) + at(x1, y1) * fx) * fy;
            changes.push_back(std::abs(now.v[std::size_t(r) * std::size_t(w) + std::size_t(x)] - sampled) * 255.0);
        }
    return changes;
}

FlickerStats flickerStats(std::vector<double> changes) {
    FlickerStats s;
    s.samples = changes.size();
    if (changes.empty()) return s;
    double sum = 0.0;
    for (double c : changes) sum += c;
    s.mean = sum / double(changes.size());
    const std::size_t k = std::min(changes.size() - 1, std::size_t(std::ceil(0.99 * double(changes.size()))) - 1);
    std::nth_element(changes.begin(), changes.begin() + std::ptrdiff_t(k), changes.end());
    s.p99 = changes[k];
    return s;
}

int framesUntilConverged(const std::vector<double>& psnr_db, double tolerance_db) {
    if (psnr_db.empty()) return -1;
    const double converged = psnr_db.back();
    int first = int(psnr_db.size()) - 1;
    for (int i = first; i >= 0; --i) {
        const double v = psnr_db[std::size_t(i)];
        if (!(v >= converged - tolerance_db)) break;  // better than the converged value counts as there
        first = i;
    }
    return first;
}

}  // namespace vista
