// The CPU reference image of what "sky.atmosphere" draws for a view (sky radiance from the
// double-precision reference, plus the sunlit ground where a ray meets the planet), and the
// PSNR the GL test and `vista bench sky` compare the GPU with. No GL.
#pragma once

#include "renderer/camera.h"
#include "sky/atmosphere_reference.h"
#include "sky/sky_settings.h"

#include <cstdint>
#include <vector>

namespace vista {

// Linear radiance per pixel (RGB, HDR units: transfer factor * sun_illuminance, the sky's
// in-scattering through skyColourMatrix() as the sky pass draws it), top row
// first. Pixels within the sun disk (plus 1.5 px) are NaN: the reference has no disk.
// The camera sits above the planet centre (as on the GPU): only its altitude counts.
std::vector<glm::vec3> referenceSkyImage(const SkySettings& sky, const ViewParams& view,
                                         const MultipleScatteringTable& ms, const IntegrationSteps& steps = {32, 32});

// PSNR in dB of an RGBA half-float image (top row first) against the reference, over the
// linear radiance normalised by the reference's maximum: 10 log10(1 / mean((gpu - ref)^2 /
// max(ref)^2)) over every non-NaN reference pixel and RGB channel.
double skyPsnrDb(const std::vector<std::uint16_t>& hdr, const std::vector<glm::vec3>& reference);

}  // namespace vista
