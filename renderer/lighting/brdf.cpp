// CPU mirror of renderer/lighting/shaders/brdf.glsl.
#include "renderer/lighting/brdf.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace vista {

glm::dvec3 evalBrdf(const glm::dvec3& albedo, double roughness, double f0, const glm::dvec3& n, const glm::dvec3& l,
                    const glm::dvec3& v) {
    double nl = std::min(glm::dot(n, l), 1.0);
    if (nl <= 0.0) return glm::dvec3(0.0);
    double nv = std::clamp(glm::dot(n, v), 1e-4, 1.0);
    glm::dvec3 h = glm::normalize(l + v);
    double nh = std::clamp(glm::dot(n, h), 0.0, 1.0), vh = std::clamp(glm::dot(v, h), 0.0, 1.0);
    double r = std::max(roughness, kMinRoughness);
    double a2 = r * r * r * r;
    double d = nh * nh * (a2 - 1.0) + 1.0;
    double D = a2 / (std::numbers::pi * d * d);
    double V = 0.5 / (nl * std::sqrt(nv * nv * (1.0 - a2) + a2) + nv * std::sqrt(nl * nl * (1.0 - a2) + a2));
    double F = f0 + (1.0 - f0) * std::pow(1.0 - vh, 5.0);
    double diffuse = 21.0 / (20.0 * std::numbers::pi) * (1.0 - f0) * (1.0 - std::pow(1.0 - nl, 5.0)) *
                     (1.0 - std::pow(1.0 - nv, 5.0));
    return albedo * diffuse + glm::dvec3(D * V * F);
}

}  // namespace vista
