// The image metrics of `vista quality` against cases with an exact answer: identical images,
// a uniform offset (closed-form PSNR), constant planes (closed-form SSIM), a 2x2 SSIM worked
// by hand, and an HDR image one stop brighter.
#include "app/image_metrics.h"

#include <doctest/doctest.h>

#include <glm/gtc/packing.hpp>

#include <cmath>
#include <random>

using namespace vista;

namespace {

std::vector<unsigned char> noiseImage(int w, int h, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> d(10, 245);
    std::vector<unsigned char> img(std::size_t(w * h * 4));
    for (auto& c : img) c = (unsigned char)d(rng);
    return img;
}

Plane plane(int w, int h, std::vector<double> v) { return Plane{w, h, std::move(v)}; }

std::uint16_t half(float f) { return glm::packHalf1x16(f); }

}  // namespace

TEST_CASE("metrics: identical images give SSIM 1, infinite PSNR and no error") {
    const auto img = noiseImage(40, 30, 1);
    ErrorAccumulator e;
    e.addLdr(img, img, 40, 30);
    e.addLdr(img, img, 40, 30);
    const ImageError r = e.result();
    CHECK(std::isinf(r.psnr_db));
    CHECK(r.psnr_db > 0.0);
    CHECK(r.ssim == doctest::Approx(1.0).epsilon(1e-12));
    CHECK(r.max_error == 0.0);
    CHECK(std::isinf(psnrFromMse(0.0, 1.0)));
    CHECK(ErrorAccumulator{}.result().ssim == 1.0);  // nothing compared: no error
}

TEST_CASE("metrics: a uniform offset of 3 levels has PSNR 20 log10(255 / 3) and max error 3") {
    const auto ref = noiseImage(33, 17, 2);
    auto run = ref;
    for (std::size_t i = 0; i < run.size(); ++i)
        if (i % 4 != 3) run[i] = (unsigned char)(run[i] + ((i / 4) % 2 ? 3 : -3));  // +-3 alternating, no clipping
    ErrorAccumulator e;
    e.addLdr(run, ref, 33, 17);
    const ImageError r = e.result();
    CHECK(r.psnr_db == doctest::Approx(20.0 * std::log10(255.0 / 3.0)).epsilon(1e-12));
    CHECK(r.psnr_db == doctest::Approx(38.58837851428586));
    CHECK(r.max_error == doctest::Approx(3.0));
    CHECK(r.ssim < 1.0);
    CHECK(r.ssim > 0.9);
    CHECK(psnrFromMse(0.01, 1.0) == doctest::Approx(20.0));
}

TEST_CASE("metrics: SSIM of constant planes is the luminance term (2ab + C1) / (a^2 + b^2 + C1)") {
    const double a = 0.3, b = 0.6, c1 = 0.01 * 0.01;
    const Plane pa = plane(24, 20, std::vector<double>(24 * 20, a)), pb = plane(24, 20, std::vector<double>(24 * 20, b));
    const double expected = (2 * a * b + c1) / (a * a + b * b + c1);
    CHECK(ssim(pa, pb, 1.0) == doctest::Approx(expected).epsilon(1e-12));                // Gaussian 11x11
    CHECK(ssim(pa, pb, 1.0, {8, 0.0}) == doctest::Approx(expected).epsilon(1e-12));      // uniform 8x8
    CHECK(ssim(pa, pa, 1.0) == doctest::Approx(1.0));
}

TEST_CASE("metrics: SSIM of a 2x2 image with a uniform 2x2 window, worked by hand") {
    // x = 0.2 0.4 / 0.6 0.8, y = 0.2 0.4 / 0.6 1.0, L = 1: mu_x = 0.5, mu_y = 0.55,
    // var_x = 0.3 - 0.25 = 0.05, var_y = 0.39 - 0.3025 = 0.0875, cov = 0.34 - 0.275 = 0.065,
    // C1 = 1e-4, C2 = 9e-4: SSIM = (0.5501 * 0.1309) / (0.5526 * 0.1384) = 0.94153034316.
    const Plane x = plane(2, 2, {0.2, 0.4, 0.6, 0.8}), y = plane(2, 2, {0.2, 0.4, 0.6, 1.0});
    CHECK(ssim(x, y, 1.0, {2, 0.0}) == doctest::Approx(0.9415303431597137).epsilon(1e-12));
    CHECK(ssim(y, x, 1.0, {2, 0.0}) == doctest::Approx(0.9415303431597137).epsilon(1e-12));  // symmetric
    // The window is clamped to the image: the 11x11 default on 2x2 uses the 2x2 centre of the Gaussian,
    // which is uniform by symmetry.
    CHECK(ssim(x, y, 1.0) == doctest::Approx(0.9415303431597137).epsilon(1e-12));
    // Inverted structure: negative correlation drives SSIM below 0.
    const Plane inv = plane(2, 2, {0.8, 0.6, 0.4, 0.2});
    CHECK(ssim(x, inv, 1.0, {2, 0.0}) < 0.0);
}

TEST_CASE("metrics: an HDR image one stop brighter has max error 1 stop and PSNR 20 log10(range)") {
    const int w = 16, h = 12;
    std::vector<std::uint16_t> ref(std::size_t(w * h * 4)), run(ref.size());
    for (int i = 0; i < w * h; ++i) {
        const float y = std::exp2(float(i % 9) - 4.0f);  // 2^-4 .. 2^4: range 8 stops
        for (int c = 0; c < 3; ++c) {
            ref[std::size_t(4 * i + c)] = half(y);
            run[std::size_t(4 * i + c)] = half(2.0f * y);
        }
    }
    const StopsRange range = log2LuminanceRange({ref}, w, h);
    CHECK(range.lo == doctest::Approx(-4.0).epsilon(1e-3));
    CHECK(range.range == doctest::Approx(8.0).epsilon(1e-3));
    ErrorAccumulator e;
    e.addHdr(run, ref, w, h, range);
    const ImageError r = e.result();
    CHECK(r.max_error == doctest::Approx(1.0).epsilon(1e-3));
    CHECK(r.psnr_db == doctest::Approx(20.0 * std::log10(range.range)).epsilon(1e-3));
    ErrorAccumulator same;
    same.addHdr(ref, ref, w, h, range);
    CHECK(std::isinf(same.result().psnr_db));
    // Black and NaN pixels sit on the floor, not NaN.
    std::vector<std::uint16_t> odd(4 * 2, 0);
    odd[4] = 0x7e00;  // NaN
    const Plane p = log2LuminanceFromHalf(odd, 2, 1);
    CHECK(p.v[0] == kLog2LuminanceFloor);
    CHECK(p.v[1] == kLog2LuminanceFloor);
}
