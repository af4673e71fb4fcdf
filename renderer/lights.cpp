// Light falloff, spot cones, bounding spheres, generation volumes and animation. The float
// functions are written the way the GLSL evaluates them, so CPU and GPU agree.
#include "renderer/lights.h"

#include "renderer/random.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace vista {
namespace {

constexpr double kDegToRad = std::numbers::pi / 180.0;
constexpr float kMinConeCos = 1e-4f;  // smallest cos_inner - cos_outer: a hard edge below this

glm::dvec3 axisOf(const Light& light) {
    glm::dvec3 d(light.direction);
    double len = glm::length(d);
    return len > 0.0 ? d / len : glm::dvec3(0.0, -1.0, 0.0);
}

// Fraction of a unit interval from 53 hashed bits.
double unit(std::uint64_t bits) { return double(bits >> 11) * (1.0 / 9007199254740992.0); }

}  // namespace

float falloff(float d2_m2, float radius_m) {
    if (!(radius_m > 0.0f)) return 0.0f;
    float x = d2_m2 / (radius_m * radius_m);
    float w = std::clamp(1.0f - x * x, 0.0f, 1.0f);
    return w * w / (d2_m2 + kFalloffEpsM2);
}

double falloffD(double d2_m2, double radius_m) {
    if (!(radius_m > 0.0)) return 0.0;
    double x = d2_m2 / (radius_m * radius_m);
    double w = std::clamp(1.0 - x * x, 0.0, 1.0);
    return w * w / (d2_m2 + double(kFalloffEpsM2));
}

SpotCone spotCone(float inner_deg, float outer_deg) {
    float outer = std::clamp(outer_deg, 0.0f, 180.0f);
    float inner = std::clamp(inner_deg, 0.0f, outer);
    float cos_outer = float(std::cos(double(outer) * kDegToRad));
    float cos_inner = float(std::cos(double(inner) * kDegToRad));
    SpotCone c;
    c.scale = 1.0f / std::max(cos_inner - cos_outer, kMinConeCos);
    c.offset = -cos_outer * c.scale;
    return c;
}

SpotCone spotCone(const Light& light) {
    return light.type == LightType::Spot ? spotCone(light.inner_deg, light.outer_deg) : SpotCone{};
}

float spotFactor(const SpotCone& cone, float cos_a) {
    float t = std::clamp(cos_a * cone.scale + cone.offset, 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

double attenuation(const Light& light, const glm::dvec3& p) {
    glm::dvec3 v = p - light.position;
    double d2 = glm::dot(v, v);
    double f = falloffD(d2, double(light.radius_m));
    if (f == 0.0 || light.type != LightType::Spot) return f;
    double d = std::sqrt(d2);
    double cos_a = d > 0.0 ? glm::dot(v / d, axisOf(light)) : 1.0;  // at the apex: on the axis
    return f * double(spotFactor(spotCone(light), float(cos_a)));
}

bool reaches(const Light& light, const glm::dvec3& p) { return attenuation(light, p) > 0.0; }

Sphere boundingSphere(const Light& light) {
    double r = std::max(0.0, double(light.radius_m));
    if (light.type != LightType::Spot || r == 0.0) return {light.position, r};
    double a = std::clamp(double(light.outer_deg), 0.0, 180.0) * kDegToRad;
    glm::dvec3 axis = axisOf(light);
    if (a < std::numbers::pi / 4.0) {
        double h = r / (2.0 * std::cos(a));
        return {light.position + axis * h, h};
    }
    if (a < std::numbers::pi / 2.0) return {light.position + axis * (r * std::cos(a)), r * std::sin(a)};
    return {light.position, r};
}

glm::vec3 hsvToRgb(float hue, float saturation, float value) {
    float h = hue - std::floor(hue);
    float s = std::clamp(saturation, 0.0f, 1.0f), v = std::clamp(value, 0.0f, 1.0f);
    auto channel = [&](float n) {  // the piecewise-linear HSV ramp, one channel at offset n
        float k = std::fmod(n + h * 6.0f, 6.0f);
        return v - v * s * std::clamp(std::min(k, 4.0f - k), 0.0f, 1.0f);
    };
    return {channel(5.0f), channel(3.0f), channel(1.0f)};
}

double lightSolidAngleSr(const Light& light) {
    if (light.type != LightType::Spot) return 4.0 * std::numbers::pi;
    const double outer = std::clamp(double(light.outer_deg), 0.0, 180.0);
    const double inner = std::clamp(double(light.inner_deg), 0.0, outer);
    return 2.0 * std::numbers::pi * (1.0 - 0.5 * (std::cos(inner * kDegToRad) + std::cos(outer * kDegToRad)));
}

double candela(const Light& light, double lux_per_hdr_unit) {
    const double v = std::max(double(light.intensity), 0.0);
    switch (light.unit) {
        case LightUnit::Candela: return v;
        case LightUnit::Lumen: {
            const double sr = lightSolidAngleSr(light);
            return sr > 0.0 ? v / sr : 0.0;
        }
        case LightUnit::Hdr: break;
    }
    return v * lux_per_hdr_unit;
}

double autoRadiusM(double cd, double max_channel, double cutoff_lux) {
    const double e1 = std::max(cd, 0.0) * std::max(max_channel, 0.0);  // lux at 1 m, brightest channel
    if (!(cutoff_lux > 0.0)) return kMaxLightRadiusM;
    return std::min(std::sqrt(std::max(e1 / cutoff_lux - double(kFalloffEpsM2), 0.0)), kMaxLightRadiusM);
}

Light resolveUnits(Light light, double lux_per_hdr_unit, double cutoff_lux) {
    const double cd = candela(light, lux_per_hdr_unit);
    if (light.radius_m < 0.0f)
        light.radius_m = float(autoRadiusM(cd, std::max({light.color.r, light.color.g, light.color.b}), cutoff_lux));
    if (light.unit != LightUnit::Hdr) light.intensity = float(cd / lux_per_hdr_unit);
    light.unit = LightUnit::Hdr;
    return light;
}

std::uint64_t lightCount(const LightVolume& volume) {
    if (volume.count.x < 1 || volume.count.y < 1 || volume.count.z < 1) return 0;
    return std::uint64_t(volume.count.x) * std::uint64_t(volume.count.y) * std::uint64_t(volume.count.z);
}

void generateLights(const LightVolume& volume, std::vector<Light>& out) {
    std::uint64_t n = lightCount(volume);
    if (n == 0) return;
    glm::dvec3 lo = glm::min(volume.min_m, volume.max_m), hi = glm::max(volume.min_m, volume.max_m);
    glm::dvec3 cell = (hi - lo) / glm::dvec3(volume.count);
    double jitter = std::clamp(double(volume.jitter), 0.0, 1.0);
    out.reserve(out.size() + n);
    std::uint64_t index = 0;
    for (int z = 0; z < volume.count.z; ++z)
        for (int y = 0; y < volume.count.y; ++y)
            for (int x = 0; x < volume.count.x; ++x, ++index) {
                Rng rng(hashIndex(volume.seed, index));
                Light l;
                l.color = hsvToRgb(volume.hue_min + (volume.hue_max - volume.hue_min) * float(rng.uniform()), volume.saturation,
                                   volume.value);
                glm::dvec3 j(rng.uniform(), rng.uniform(), rng.uniform());
                l.position = lo + (glm::dvec3(x, y, z) + 0.5 + (j - 0.5) * jitter) * cell;
                l.radius_m = volume.radius_m < 0.0f ? -1.0f : volume.radius_m;  // < 0: auto
                l.intensity = volume.intensity;
                l.unit = volume.unit;
                out.push_back(l);
            }
}

std::vector<Light> collectLights(std::span<const Light> explicit_lights, std::span<const LightVolume> volumes) {
    std::vector<Light> out(explicit_lights.begin(), explicit_lights.end());
    for (const LightVolume& v : volumes) generateLights(v, out);
    return out;
}

bool isAnimated(const LightAnimation& animation, std::uint64_t light_index) {
    if (animation.motion == LightMotion::None || !(animation.period_s > 0.0f)) return false;
    return unit(hashIndex(animation.seed, 2 * light_index)) < double(animation.fraction);
}

glm::dvec3 animatedPosition(const glm::dvec3& base, const LightAnimation& animation, double t_s,
                            std::uint64_t light_index) {
    if (!isAnimated(animation, light_index)) return base;
    double phase = unit(hashIndex(animation.seed, 2 * light_index + 1));
    double u = t_s / double(animation.period_s) + phase;  // double: stable for very long run times
    double phi = 2.0 * std::numbers::pi * (u - std::floor(u));
    double a = double(animation.amplitude_m);
    if (animation.motion == LightMotion::Circle) return base + glm::dvec3(a * std::cos(phi), 0.0, a * std::sin(phi));
    return base + glm::dvec3(0.0, a * std::sin(phi), 0.0);
}

void animateLights(std::span<const Light> base, const LightAnimation& animation, double t_s,
                   std::vector<Light>& out) {
    out.assign(base.begin(), base.end());
    if (animation.motion == LightMotion::None) return;
    for (std::size_t i = 0; i < out.size(); ++i) out[i].position = animatedPosition(base[i].position, animation, t_s, i);
}

}  // namespace vista
