// Reference sky images, evaluated on all cores (each pixel is an independent ray).
#include "sky/sky_reference_image.h"

#include "sky/atmosphere.h"
#include "sky/atmosphere_spectral.h"

#include <glm/geometric.hpp>
#include <glm/gtc/packing.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <thread>

namespace vista {

std::vector<glm::vec3> referenceSkyImage(const SkySettings& sky, const ViewParams& view,
                                         const MultipleScatteringTable& ms, const IntegrationSteps& steps) {
    const AtmosphereParams p = atmosphereParams(sky);
    const glm::dvec3 sun = sunDirection(sky);
    const glm::dvec3 camera{0.0, std::max(view.position.y, 0.0), 0.0};
    const glm::dmat4 inv(viewMatrices(view).inv_view_proj);
    const double pixel_rad = glm::radians(view.fov_deg) / view.height;
    const double disk_cos = std::cos(p.sun_angular_radius + 1.5 * pixel_rad);
    // The sky pass's conversion of the in-scattered samples to linear sRGB (skyRgb() in
    // sky/shaders/atmosphere.glsl); the sunlit ground's path (view ray, then to the sun) through
    // sunlightRgb(), as sky.glsl lights it.
    const glm::dmat3 colour = skyColourMatrix(sun.y);
    const SunlightConversion sunlight = sunlightConversion(p);
    const int w = view.width, h = view.height;
    std::vector<glm::vec3> out(std::size_t(w) * std::size_t(h));
    auto row = [&](int y) {
        for (int x = 0; x < w; ++x) {
            glm::dvec2 uv((x + 0.5) / w, 1.0 - (y + 0.5) / h);
            glm::dvec4 q = inv * glm::dvec4(uv * 2.0 - 1.0, 0.5, 1.0);
            glm::dvec3 d = glm::normalize(glm::dvec3(q) / q.w);
            glm::vec3& o = out[std::size_t(y) * std::size_t(w) + std::size_t(x)];
            ViewRayResult v =
                integrateViewRay(p, camera, d, sun, std::numeric_limits<double>::infinity(), steps, &ms);
            glm::dvec3 l = colour * v.radiance;
            if (v.hits_ground) {
                glm::dvec3 g = planetFromWorld(p, camera) + v.distance * d;
                double mu_s = glm::dot(glm::normalize(g), sun);
                if (mu_s > 0.0)
                    l += (p.ground_albedo / std::numbers::pi) * mu_s *
                         sunlightRgb(sunlight, v.transmittance * transmittance(p, p.bottom_radius, mu_s, steps.transmittance));
            } else if (glm::dot(d, sun) > disk_cos) {
                o = glm::vec3(std::numeric_limits<float>::quiet_NaN());
                continue;
            }
            // The conversion can leave the gamut (a deep red horizon has a negative green); the
            // sky pass clamps its output at 0.
            o = glm::vec3(glm::max(l, glm::dvec3(0.0)) * double(sky.sun_illuminance));
        }
    };
    unsigned workers = std::max(1u, std::thread::hardware_concurrency());
    std::vector<std::thread> threads;
    for (unsigned t = 0; t < workers; ++t)
        threads.emplace_back([&, t] {
            for (int y = int(t); y < h; y += int(workers)) row(y);
        });
    for (auto& t : threads) t.join();
    return out;
}

double skyPsnrDb(const std::vector<std::uint16_t>& hdr, const std::vector<glm::vec3>& reference) {
    double peak = 0.0;
    for (const glm::vec3& r : reference)
        if (!std::isnan(r.x)) peak = std::max({peak, double(r.x), double(r.y), double(r.z)});
    if (!(peak > 0.0) || hdr.size() < reference.size() * 4) return 0.0;
    double sum = 0.0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < reference.size(); ++i) {
        if (std::isnan(reference[i].x)) continue;
        for (int c = 0; c < 3; ++c) {
            double g = double(glm::unpackHalf1x16(hdr[i * 4 + std::size_t(c)]));
            double e = (g - double(reference[i][c])) / peak;
            sum += std::isfinite(e) ? e * e : 1.0;
            ++n;
        }
    }
    if (n == 0) return 0.0;
    double mse = sum / double(n);
    return mse > 0.0 ? 10.0 * std::log10(1.0 / mse) : 200.0;
}

}  // namespace vista
