// Local lights (point and spot): their description, the falloff and cone functions the
// shaders mirror, bounding spheres for culling, generation volumes (002's "light generation
// volumes": a box filled with a grid of lights of random hue) and a simple animation that
// moves lights along closed paths so dynamic updates are exercised.
//
// Units: positions in world metres (double, y up), radii in metres, angles in degrees,
// colours linear RGB. A light adds colour * intensity * falloff(d, radius) * spot(cos) *
// BRDF * max(dot(n, l), 0) at distance d; well inside the radius falloff ~ 1 / d^2, so
// intensity is the irradiance (HDR units, like [sky] sun_illuminance) at 1 m from the light.
//
// Photometric units (issue 23). A scene gives a light's strength in one of three units
// (LightUnit): Candela, its luminous intensity (a spot: on its axis); Lumen, its luminous flux,
// spread over the solid angle its cone covers (lightSolidAngleSr); or Hdr, the renderer's
// irradiance at 1 m above (the old `intensity`, kept so older scenes render as before). Candela
// and lumens are for colour 1 1 1: the colour filters them (a light of colour c gives c * I lux
// at 1 m in each channel). resolveUnits() turns them into Hdr through the lux per HDR unit the
// sun sets (sky/night_light.h luxPerHdrUnit: I cd give I lux at 1 m, I / luxPerHdrUnit HDR
// units). A radius below 0 is "auto": the distance where the light's brightest channel's
// illuminance I * max(c) / (d^2 + eps) (the falloff before its window) drops to cutoff_lux,
//     r = sqrt(max(I * max(c) / cutoff_lux - eps, 0)),
// so the windowed falloff takes it smoothly to 0 there (autoRadiusM).
//
// Falloff (windowed inverse square, after Karis 2013, "Real shading in Unreal Engine 4"):
//     falloff(d, r) = saturate(1 - (d / r)^4)^2 / (d^2 + eps),   eps = kFalloffEpsM2 = 0.01 m^2
// It is 0 for every d >= r (exactly: (d/r)^4 >= 1), at most 1 / eps = 100 at d = 0 (a bulb of
// about 10 cm rather than a singular point), and non-increasing in d. It is evaluated from d^2
// only (x = d^2 / r^2, w = saturate(1 - x^2)), so the shader needs no square root. A light with
// radius <= 0 reaches nothing (falloff 0 everywhere).
//
// Spot cone: spot(cos_a) = smoothstep(cos_outer, cos_inner, cos_a), with cos_a the cosine of the
// angle between the spot axis and the direction from the light to the point, written for the
// shader as t = saturate(cos_a * scale + offset), spot = t * t * (3 - 2t), with
// scale = 1 / max(cos_inner - cos_outer, 1e-4), offset = -cos_outer * scale (SpotCone). The inner
// angle is clamped to [0, outer]; an inner angle equal to the outer one is a hard edge. The cone is
// 0 at and beyond the outer angle.
#pragma once

#include <glm/vec3.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace vista {

inline constexpr float kFalloffEpsM2 = 0.01f;  // m^2, eps of the falloff

enum class LightType : int { Point, Spot };
// What Light::intensity counts: HDR irradiance at 1 m (the old unit), candela or lumens.
enum class LightUnit : int { Hdr, Candela, Lumen };

struct Light {
    LightType type = LightType::Point;
    glm::dvec3 position{0.0};          // m, world
    float radius_m = 10.0f;            // m, influence radius: the falloff is 0 from here on; < 0: auto (autoRadiusM)
    glm::vec3 color{1.0f};             // linear RGB
    float intensity = 10.0f;           // in `unit` (see the header comment); >= 0
    LightUnit unit = LightUnit::Hdr;   // Hdr: irradiance scale at 1 m; Candela; Lumen
    glm::vec3 direction{0, -1, 0};     // spot axis (world, normalised on use); point lights ignore it
    float inner_deg = 20.0f;           // deg, spot half-angle of full intensity, [0, outer_deg]
    float outer_deg = 30.0f;           // deg, spot half-angle where the light ends, [0, 180]
    bool shadow = true;                // may cast a shadow: spot ([shadows] spot_*), point ([shadows] point_*)
    float ground_m = -1.0f;            // m: >= 0 puts the light this high above the terrain (y is then ignored); < 0: off

    bool operator==(const Light&) const = default;
};

// Windowed inverse-square falloff from the squared distance (m^2) and the radius (m).
float falloff(float d2_m2, float radius_m);
double falloffD(double d2_m2, double radius_m);  // the same in double, for references

// Spot cone as the shader evaluates it: spot = smoothstep over t = saturate(cos_a * scale + offset).
struct SpotCone {
    float scale = 0.0f;
    float offset = 1.0f;  // scale 0, offset 1: no cone (point light), spot = 1
};
SpotCone spotCone(float inner_deg, float outer_deg);
SpotCone spotCone(const Light& light);  // point lights: the no-cone value
float spotFactor(const SpotCone& cone, float cos_a);

// falloff * spot for a point p (world m), in double. 0 where the light does not reach.
double attenuation(const Light& light, const glm::dvec3& p);
// Whether the light reaches p at all (attenuation > 0): d < radius and, for a spot, the angle
// to the axis is below the outer angle. This is what the `lights.exact` counter counts.
bool reaches(const Light& light, const glm::dvec3& p);

struct Sphere {
    glm::dvec3 center{0.0};  // m, world
    double radius = 0.0;     // m; 0: reaches nothing
};
// Smallest sphere around everything the light reaches. A point light: its own sphere. A spot
// with outer half-angle a and radius r bounds the spherical sector: for a < 45 deg the sphere
// through the apex and the rim circle (centre r / (2 cos a) along the axis, same radius); for
// 45 <= a < 90 deg the rim circle's sphere (centre r cos a along the axis, radius r sin a);
// wider cones use the point sphere. Each contains the apex, the rim and the cap.
Sphere boundingSphere(const Light& light);

// Photometry (see the header comment). The solid angle (sr) a light's cone covers, weighted by
// its cone function: 4 pi for a point light; a spot, integrating spot(cos a) over the sphere
// (the smoothstep in cos a integrates to half its width), 2 pi (1 - (cos inner + cos outer) / 2).
double lightSolidAngleSr(const Light& light);
// The light's luminous intensity (cd, for colour 1 1 1; a spot: on its axis) from its unit:
// Candela as is, Lumen / lightSolidAngleSr, Hdr times lux_per_hdr_unit.
double candela(const Light& light, double lux_per_hdr_unit);
// The auto radius (m) for a light of cd candela with brightest channel max_channel:
// sqrt(max(cd * max_channel / cutoff_lux - kFalloffEpsM2, 0)), at most kMaxLightRadiusM (also
// for cutoff_lux <= 0).
double autoRadiusM(double cd, double max_channel, double cutoff_lux);
inline constexpr double kMaxLightRadiusM = 1e5;
// The light in the renderer's units: intensity in Hdr (candela / lux_per_hdr_unit) and, where
// the radius is auto, autoRadiusM(candela, max colour, cutoff_lux). Hdr lights keep their value.
Light resolveUnits(Light light, double lux_per_hdr_unit, double cutoff_lux);

// HSV (each in [0, 1]; hue wraps) to RGB, applied to linear values.
glm::vec3 hsvToRgb(float hue, float saturation, float value);

// 002's light generation volume: count.x * count.y * count.z point lights on a regular grid at
// the cell centres of the box [min_m, max_m], of one radius and intensity, each with a random
// hue in [hue_min, hue_max] at the given saturation and value. jitter moves each light by up to +-jitter/2 of a cell
// per axis (0: exact grid). Deterministic: light i's colour and offset depend only on seed and
// i (x fastest, then y, then z), through splitmix64, on every platform.
struct LightVolume {
    glm::dvec3 min_m{-50.0, 0.0, -50.0};  // m, world, box corner
    glm::dvec3 max_m{50.0, 10.0, 50.0};   // m, world, opposite corner (min/max per axis are sorted on use)
    glm::ivec3 count{4, 1, 4};            // lights per axis, >= 1 (a volume of count 0 adds none)
    float radius_m = 15.0f;               // m; < 0: auto, as Light::radius_m
    float intensity = 20.0f;              // as Light::intensity
    LightUnit unit = LightUnit::Hdr;      // as Light::unit
    float saturation = 0.7f;              // HSV saturation of the random hue, [0, 1]
    float value = 1.0f;                   // HSV value, [0, 1]
    float jitter = 0.0f;                  // fraction of a cell, [0, 1]
    std::uint32_t seed = 23;
    float hue_min = 0.0f, hue_max = 1.0f; // the random hue's range, fractions of the colour wheel, [0, 1]
    float ground_m = -1.0f;               // m: >= 0 puts every light this high above the terrain
                                          // (the box's y range is then ignored); < 0: off

    bool operator==(const LightVolume&) const = default;
};
// Number of lights the volume makes (0 if any count is below 1).
std::uint64_t lightCount(const LightVolume& volume);
// Appends the volume's lights to out.
void generateLights(const LightVolume& volume, std::vector<Light>& out);
// Explicit lights, then each volume's lights in order.
std::vector<Light> collectLights(std::span<const Light> explicit_lights, std::span<const LightVolume> volumes);

// Motion of animated lights around their base positions: Circle runs a horizontal circle of
// radius amplitude_m (x/z plane), Bob moves up and down by +-amplitude_m; one loop per period_s.
// Which lights move (a `fraction` of them) and each one's phase depend on seed and the light's
// index only. Position at time t (s): base + A * (cos phi, 0, sin phi) (Circle) or
// base + (0, A sin phi, 0) (Bob), phi = 2 pi * fract(t / period + phase).
enum class LightMotion : int { None, Circle, Bob };
struct LightAnimation {
    LightMotion motion = LightMotion::None;
    float amplitude_m = 2.0f;  // m, circle radius or bob height; >= 0
    float period_s = 10.0f;    // s per loop; <= 0: still
    float fraction = 1.0f;     // share of the lights that move, [0, 1]
    std::uint32_t seed = 1;

    bool operator==(const LightAnimation&) const = default;
};
bool isAnimated(const LightAnimation& animation, std::uint64_t light_index);
glm::dvec3 animatedPosition(const glm::dvec3& base, const LightAnimation& animation, double t_s,
                            std::uint64_t light_index);
// out = base with each animated light moved to its position at t_s (out is resized to match).
void animateLights(std::span<const Light> base, const LightAnimation& animation, double t_s,
                   std::vector<Light>& out);

}  // namespace vista
