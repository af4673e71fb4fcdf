// Void-and-cluster (Ulichney 1993). Energy of a texel: the sum over the pattern's ones of a
// toroidal Gaussian of their distance. Start from a random 10 % pattern and swap its tightest
// cluster (the one with the highest energy) into the largest void (the zero with the lowest)
// until that changes nothing; then rank: remove tightest clusters from a copy of it (ranks
// below its count, downwards), and fill largest voids into another copy (ranks upwards) until
// every texel is one. Ulichney's third phase (tightest cluster of zeros beyond half-full) is
// the same choice as the largest void here, since the filter sums to the same value at every
// texel of the torus.
#include "renderer/blue_noise.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <random>

namespace vista {

namespace {

struct Energy {
    int size;
    std::vector<double> kernel;  // Gaussian of the toroidal offset (dx, dy), row-major
    std::vector<double> value;

    Energy(int n, double sigma) : size(n), kernel(std::size_t(n) * std::size_t(n)), value(kernel.size(), 0.0) {
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                const int dx = std::min(x, n - x), dy = std::min(y, n - y);
                kernel[std::size_t(y * n + x)] = std::exp(-double(dx * dx + dy * dy) / (2.0 * sigma * sigma));
            }
    }
    // Adds (sign +1) or removes (-1) a one at texel i.
    void splat(int i, double sign) {
        const int px = i % size, py = i / size;
        for (int y = 0; y < size; ++y) {
            const int ky = ((y - py) % size + size) % size;
            for (int x = 0; x < size; ++x) {
                const int kx = ((x - px) % size + size) % size;
                value[std::size_t(y * size + x)] += sign * kernel[std::size_t(ky * size + kx)];
            }
        }
    }
    // The one with the highest energy (want = true) or the zero with the lowest (want = false).
    int extreme(const std::vector<char>& bits, bool want) const {
        int best = -1;
        for (int i = 0; i < int(bits.size()); ++i) {
            if (bool(bits[std::size_t(i)]) != want) continue;
            if (best < 0 || (want ? value[std::size_t(i)] > value[std::size_t(best)]
                                  : value[std::size_t(i)] < value[std::size_t(best)]))
                best = i;
        }
        return best;
    }
};

}  // namespace

std::vector<std::uint32_t> voidAndClusterRanks(int size, double sigma, std::uint32_t seed) {
    const int n = size * size;
    std::vector<std::uint32_t> rank(std::size_t(n), 0);
    if (n <= 1) return rank;
    // The initial pattern: 10 % ones at random (raw mt19937 output: the same on every library).
    std::mt19937 rng(seed);
    const int ones = std::max(1, n / 10);
    std::vector<char> bits(std::size_t(n), 0);
    for (int placed = 0; placed < ones;) {
        const int i = int(rng() % std::uint32_t(n));
        if (!bits[std::size_t(i)]) bits[std::size_t(i)] = 1, ++placed;
    }
    Energy e(size, sigma);
    for (int i = 0; i < n; ++i)
        if (bits[std::size_t(i)]) e.splat(i, 1.0);
    // Spread it: move the tightest cluster into the largest void until that is where it came from.
    for (int guard = 0; guard < 4 * n; ++guard) {
        const int cluster = e.extreme(bits, true);
        bits[std::size_t(cluster)] = 0;
        e.splat(cluster, -1.0);
        const int hole = e.extreme(bits, false);
        bits[std::size_t(hole)] = 1;
        e.splat(hole, 1.0);
        if (hole == cluster) break;
    }
    // Phase 1: ranks below `ones`, removing tightest clusters.
    {
        std::vector<char> b = bits;
        Energy pe = e;
        for (int r = ones - 1; r >= 0; --r) {
            const int cluster = pe.extreme(b, true);
            b[std::size_t(cluster)] = 0;
            pe.splat(cluster, -1.0);
            rank[std::size_t(cluster)] = std::uint32_t(r);
        }
    }
    // Phases 2 and 3: ranks from `ones` up, filling largest voids.
    for (int r = ones; r < n; ++r) {
        const int hole = e.extreme(bits, false);
        bits[std::size_t(hole)] = 1;
        e.splat(hole, 1.0);
        rank[std::size_t(hole)] = std::uint32_t(r);
    }
    return rank;
}

std::vector<double> radialPowerSpectrum(const std::vector<double>& field, int size) {
    double mean = 0.0;
    for (double v : field) mean += v;
    mean /= double(field.size());
    // A separable DFT: rows, then columns (size^3 operations).
    const std::size_t n = std::size_t(size);
    std::vector<std::complex<double>> twiddle(n), rows(n * n), full(n * n);
    for (std::size_t k = 0; k < n; ++k) twiddle[k] = std::polar(1.0, -2.0 * std::numbers::pi * double(k) / double(size));
    for (std::size_t y = 0; y < n; ++y)
        for (std::size_t fx = 0; fx < n; ++fx) {
            std::complex<double> acc = 0.0;
            for (std::size_t x = 0; x < n; ++x) acc += (field[y * n + x] - mean) * twiddle[(fx * x) % n];
            rows[y * n + fx] = acc;
        }
    for (std::size_t fy = 0; fy < n; ++fy)
        for (std::size_t fx = 0; fx < n; ++fx) {
            std::complex<double> acc = 0.0;
            for (std::size_t y = 0; y < n; ++y) acc += rows[y * n + fx] * twiddle[(fy * y) % n];
            full[fy * n + fx] = acc;
        }
    std::vector<double> sum(std::size_t(size / 2 + 1), 0.0), count(sum.size(), 0.0);
    for (int fy = 0; fy < size; ++fy)
        for (int fx = 0; fx < size; ++fx) {
            const int sx = fx <= size / 2 ? fx : fx - size, sy = fy <= size / 2 ? fy : fy - size;
            const int r = int(std::lround(std::sqrt(double(sx * sx + sy * sy))));
            if (r > size / 2) continue;
            sum[std::size_t(r)] += std::norm(full[std::size_t(fy) * n + std::size_t(fx)]) / double(size * size);
            count[std::size_t(r)] += 1.0;
        }
    for (std::size_t r = 0; r < sum.size(); ++r) sum[r] = count[r] > 0.0 ? sum[r] / count[r] : 0.0;
    return sum;
}

BlueNoiseTexture::BlueNoiseTexture() {
    const std::vector<std::uint32_t> ranks = voidAndClusterRanks(kBlueNoiseSize);
    std::vector<std::uint16_t> texels(ranks.size());
    const double n = double(ranks.size());
    for (std::size_t i = 0; i < ranks.size(); ++i)
        texels[i] = std::uint16_t(std::lround((double(ranks[i]) + 0.5) / n * 65535.0));
    texture_ = gl::Texture::create2D(kBlueNoiseSize, kBlueNoiseSize, GL_R16, 1, "blue noise (void-and-cluster)");
    glTextureSubImage2D(texture_.id(), 0, 0, 0, kBlueNoiseSize, kBlueNoiseSize, GL_RED, GL_UNSIGNED_SHORT, texels.data());
    glTextureParameteri(texture_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(texture_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTextureParameteri(texture_.id(), GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTextureParameteri(texture_.id(), GL_TEXTURE_WRAP_T, GL_REPEAT);
}

}  // namespace vista
