// Blue noise for every jittered estimator (clouds, aerial perspective, SSAO, SSR, shadow
// kernels): a tileable threshold map made by vista with Ulichney's void-and-cluster method
// (1993), so its error has no low frequencies and averages out under any blur, and a
// golden-ratio shift per frame that makes each pixel's sequence over time low-discrepancy
// (Wolfe et al. 2022, "spatiotemporal blue noise", their additive-R1 variant). The GLSL side
// is renderer/shaders/blue_noise.glsl; docs/temporal.md describes it.
#pragma once

#include "renderer/gl/objects.h"

#include <cstdint>
#include <vector>

namespace vista {

inline constexpr int kBlueNoiseSize = 64;  // texels per side (mirrored as BLUE_NOISE_SIZE in blue_noise.glsl)

// The void-and-cluster rank of every texel of a size x size torus (row-major): a permutation of
// 0 .. size^2 - 1 whose every threshold set {rank < k} is evenly spread. sigma: the Gaussian
// energy filter's width in texels (Ulichney: 1.5). Deterministic for a seed.
std::vector<std::uint32_t> voidAndClusterRanks(int size, double sigma = 1.5, std::uint32_t seed = 1);

// Radially averaged power spectrum of a size x size field (mean removed): entry r is the mean
// |DFT|^2 over frequencies with round(|f|) = r, r = 0 .. size / 2. For the spectrum test.
std::vector<double> radialPowerSpectrum(const std::vector<double>& field, int size);

// The map on the GPU: an R16 (unorm) texture of (rank + 0.5) / size^2, made once.
class BlueNoiseTexture {
public:
    BlueNoiseTexture();
    GLuint id() const { return texture_.id(); }
    std::size_t bytes() const { return texture_.bytes(); }

private:
    gl::Texture texture_;
};

}  // namespace vista
