// Atmosphere model: profiles, phase functions, planet-frame ray geometry and the solar position.
// The geometry follows Bruneton 2017 (atmosphere/functions.glsl, "Transmittance, Computation"):
// a ray is (r, mu) and distances come from the roots of t^2 + 2 r mu t + r^2 - R^2 = 0, in the
// forms that do not cancel (the discriminant as (R - r)(R + r) + (r mu)^2, the near root as
// c / (-b + sqrt(disc))), which keeps metre accuracy from the ground to 36,000 km.
#include "sky/atmosphere_model.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace vista {

namespace {

constexpr double kPi = std::numbers::pi;

double safeSqrt(double x) { return std::sqrt(std::max(x, 0.0)); }

}  // namespace

double rayleighDensity(const AtmosphereParams& p, double altitude_m) {
    return std::exp(-std::max(altitude_m, 0.0) / p.rayleigh_scale_height);
}

double mieDensity(const AtmosphereParams& p, double altitude_m) {
    return std::exp(-std::max(altitude_m, 0.0) / p.mie_scale_height);
}

double ozoneDensity(const AtmosphereParams& p, double altitude_m) {
    if (p.ozone_half_width <= 0.0) return 0.0;
    return std::max(0.0, 1.0 - std::abs(altitude_m - p.ozone_center_altitude) / p.ozone_half_width);
}

MediumSample sampleMedium(const AtmosphereParams& p, double altitude_m) {
    double rayleigh = rayleighDensity(p, altitude_m), mie = mieDensity(p, altitude_m);
    double ozone = ozoneDensity(p, altitude_m);
    MediumSample m;
    m.rayleigh_scattering = p.rayleigh_scattering * rayleigh;
    m.mie_scattering = p.mie_scattering * mie;
    m.extinction = m.rayleigh_scattering + p.mie_extinction * mie + p.ozone_absorption * ozone;
    return m;
}

// Rayleigh: 3 / (16 pi) (1 + cos^2).
double rayleighPhase(double cos_theta) { return 3.0 / (16.0 * kPi) * (1.0 + cos_theta * cos_theta); }

// Cornette & Shanks 1992: 3/(8 pi) (1 - g^2)(1 + cos^2) / ((2 + g^2)(1 + g^2 - 2 g cos)^1.5).
double cornetteShanksPhase(double g, double cos_theta) {
    double k = 3.0 / (8.0 * kPi) * (1.0 - g * g) / (2.0 + g * g);
    double denom = std::max(1.0 + g * g - 2.0 * g * cos_theta, 1e-12);
    return k * (1.0 + cos_theta * cos_theta) / (denom * std::sqrt(denom));
}

// Henyey & Greenstein 1941: (1 - g^2) / (4 pi (1 + g^2 - 2 g cos)^1.5).
double henyeyGreensteinPhase(double g, double cos_theta) {
    double denom = std::max(1.0 + g * g - 2.0 * g * cos_theta, 1e-12);
    return (1.0 - g * g) / (4.0 * kPi * denom * std::sqrt(denom));
}

double miePhase(const AtmosphereParams& p, double cos_theta) {
    return p.mie_phase == MiePhase::HenyeyGreenstein ? henyeyGreensteinPhase(p.mie_g, cos_theta)
                                                      : cornetteShanksPhase(p.mie_g, cos_theta);
}

bool rayIntersectsGround(const AtmosphereParams& p, double r, double mu) {
    double R = p.bottom_radius;
    return mu < 0.0 && (R - r) * (R + r) + (r * mu) * (r * mu) >= 0.0;
}

double distanceToGround(const AtmosphereParams& p, double r, double mu) {
    double R = p.bottom_radius;
    double disc = (R - r) * (R + r) + (r * mu) * (r * mu);
    double far_b = -r * mu + safeSqrt(disc);  // > 0 for a downward ray
    if (far_b <= 0.0) return 0.0;
    return std::max((r - R) * (r + R) / far_b, 0.0);  // the near root, without cancellation
}

double distanceToTop(const AtmosphereParams& p, double r, double mu) {
    double Rt = p.top_radius;
    double disc = (Rt - r) * (Rt + r) + (r * mu) * (r * mu);
    return std::max(-r * mu + safeSqrt(disc), 0.0);  // the far root: a sum of non-negative terms inside
}

double horizonMu(const AtmosphereParams& p, double r) {
    double R = p.bottom_radius;
    double rr = std::max(r, R);
    return -safeSqrt((rr - R) * (rr + R)) / rr;
}

glm::dvec3 clampToGround(const AtmosphereParams& p, glm::dvec3 planet_pos_m) {
    double r = glm::length(planet_pos_m);
    if (r >= p.bottom_radius) return planet_pos_m;
    if (!(r > 0.0)) return {0.0, p.bottom_radius, 0.0};
    return planet_pos_m * (p.bottom_radius / r);
}

glm::dvec3 planetFromWorld(const AtmosphereParams& p, glm::dvec3 world_pos_m) {
    return clampToGround(p, world_pos_m + glm::dvec3(0.0, p.bottom_radius, 0.0));
}

AtmosphereSegment atmosphereSegment(const AtmosphereParams& p, glm::dvec3 origin, glm::dvec3 dir) {
    AtmosphereSegment s;
    origin = clampToGround(p, origin);
    double r = glm::length(origin);
    double mu = std::clamp(glm::dot(origin, dir) / r, -1.0, 1.0);
    double Rt = p.top_radius;
    if (r > Rt) {
        // From above the atmosphere: the near root of the top sphere, if the ray goes towards it.
        double disc = (Rt - r) * (Rt + r) + (r * mu) * (r * mu);
        if (mu >= 0.0 || disc < 0.0) return s;
        s.t_enter = (r - Rt) * (r + Rt) / (-r * mu + std::sqrt(disc));
        glm::dvec3 entry = origin + s.t_enter * dir;
        mu = std::clamp(glm::dot(entry, dir) / glm::length(entry), -1.0, 1.0);
        r = Rt;
    }
    s.ends_on_ground = rayIntersectsGround(p, r, mu);
    double length = s.ends_on_ground ? distanceToGround(p, r, mu) : distanceToTop(p, r, mu);
    s.t_exit = s.t_enter + length;
    s.hit = length > 0.0;
    return s;
}

// Spencer, J. W. (1971), "Fourier series representation of the position of the sun", Search 2(5):
// the day angle gamma = 2 pi (day - 1) / 365 and a 7-term series for the declination (max error
// 0.0006 rad) and a 5-term one for the equation of time (max error ~35 s), as used by NOAA's
// "General Solar Position Calculations".
double solarDeclinationRad(double day) {
    double g = 2.0 * kPi * (day - 1.0) / 365.0;
    return 0.006918 - 0.399912 * std::cos(g) + 0.070257 * std::sin(g) - 0.006758 * std::cos(2.0 * g) +
           0.000907 * std::sin(2.0 * g) - 0.002697 * std::cos(3.0 * g) + 0.00148 * std::sin(3.0 * g);
}

double equationOfTimeMinutes(double day) {
    double g = 2.0 * kPi * (day - 1.0) / 365.0;
    return 229.18 * (0.000075 + 0.001868 * std::cos(g) - 0.032077 * std::sin(g) - 0.014615 * std::cos(2.0 * g) -
                     0.040849 * std::sin(2.0 * g));
}

// Local east/north/up components of the unit vector to the sun from the hour angle H (positive
// in the afternoon), declination d and latitude phi:
//   east = -cos d sin H,  north = cos phi sin d - sin phi cos d cos H,  up = sin phi sin d + cos phi cos d cos H.
// vista's world has east = +x, up = +y, north = -z.
SunPosition sunPosition(double latitude_deg, double day_of_year, double solar_time_h) {
    double phi = std::clamp(latitude_deg, -90.0, 90.0) * kPi / 180.0;
    double decl = solarDeclinationRad(day_of_year + (solar_time_h - 12.0) / 24.0);
    double hour_angle = (solar_time_h - 12.0) * (kPi / 12.0);
    double east = -std::cos(decl) * std::sin(hour_angle);
    double north = std::cos(phi) * std::sin(decl) - std::sin(phi) * std::cos(decl) * std::cos(hour_angle);
    double up = std::sin(phi) * std::sin(decl) + std::cos(phi) * std::cos(decl) * std::cos(hour_angle);
    SunPosition s;
    s.direction = glm::normalize(glm::dvec3(east, up, -north));
    s.elevation_deg = std::asin(std::clamp(s.direction.y, -1.0, 1.0)) * 180.0 / kPi;
    double az = std::atan2(east, north) * 180.0 / kPi;
    s.azimuth_deg = az < 0.0 ? az + 360.0 : az;
    return s;
}

}  // namespace vista
