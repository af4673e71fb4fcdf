// The moon's phase integral and the pre-exposure (sky/night_light.h).
#include "sky/night_light.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace vista {

double luxPerHdrUnit(double sun_illuminance) { return kSolarIlluminanceLux / std::max(sun_illuminance, 1e-30); }

double moonIlluminanceFraction(double elongation_rad) {
    // The visible hemisphere in disk coordinates (x, y) on the unit disk: its normal
    // n = (x, y, sqrt(1 - r^2)) towards the earth; the sun lights it from (sin e', 0, cos e')
    // with e' = pi - elongation (0 at full moon). Lommel-Seeliger radiance over albedo/pi is
    // 2 cos_i / (cos_i + cos_e), each disk element subtends (R/d)^2 dx dy of solid angle.
    const double phase = std::numbers::pi - std::clamp(elongation_rad, 0.0, std::numbers::pi);
    const glm::dvec3 sun(std::sin(phase), 0.0, std::cos(phase));
    constexpr int n = 96;  // midpoint grid: within 0.1% of the exact full-moon value
    double sum = 0.0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const double x = -1.0 + (i + 0.5) * 2.0 / n, y = -1.0 + (j + 0.5) * 2.0 / n;
            const double r2 = x * x + y * y;
            if (r2 >= 1.0) continue;
            const double cos_e = std::sqrt(1.0 - r2);
            const double cos_i = x * sun.x + cos_e * sun.z;
            if (cos_i > 0.0) sum += 2.0 * cos_i / (cos_i + cos_e);
        }
    const double radius = kMoonAngularRadiusDeg * std::numbers::pi / 180.0;
    return kMoonAlbedo / std::numbers::pi * sum * (2.0 / n) * (2.0 / n) * radius * radius;
}

double preExposure(double sky_lux) {
    if (!(sky_lux > 0.0)) return kMaxPreExposure;
    return std::clamp(kPreExposureLux / sky_lux, 1.0, kMaxPreExposure);
}

}  // namespace vista
