// Glow around lamps in fog: the light of each local light scattered once by the air and the
// height fog between the camera and the first surface, added to the HDR image ("lights.glow").
//
// The medium near a light is taken as homogeneous: scattering sigma_s (RGB, 1/m) and extinction
// sigma_t (grey, 1/m) of the sky's medium (Rayleigh, aerosols, [sky] height_fog) at the light's
// altitude; the phase function is isotropic (1 / 4 pi). For a ray from the camera along the unit
// direction v, a light of intensity I (irradiance I / d^2 at distance d, lights.h) at
// camera-relative position p scatters towards the camera
//     L = sigma_s I / (4 pi) * integral over t of exp(-sigma_t (t + d(t))) / d(t)^2 dt,
//     d(t)^2 = |t v - p|^2 + eps   (eps = kFalloffEpsM2: the falloff's bulb of ~10 cm).
// With t_c = v.p (the ray's closest approach) and h = sqrt(|p|^2 - t_c^2 + eps), substituting
// t = t_c + h tan(theta) and xi = pi/4 + theta/2 (Sun, Ramamoorthi, Narasimhan & Nayar 2005, "A
// practical analytic single scattering model for real time rendering") turns t + d into
// t_c + h tan(xi) and dt / d^2 into 2 dxi / h:
//     L = sigma_s I / (2 pi h) * exp(-sigma_t t_c) * (F(sigma_t h, xi1) - F(sigma_t h, xi0)),
//     F(u, x) = integral from 0 to x of exp(-u tan(xi)) dxi,  xi(t) = pi/4 + atan((t - t_c) / h) / 2,
// over the part [t0, t1] of the ray in front of the surface (t < the pixel's distance) and inside
// the light's radius (where its falloff is not 0). F has no closed form; it is tabulated once
// (glowTable, kGlowTableU x kGlowTableV texels, bilinear) over u / (1 + u) and x / (pi / 2).
// The falloff's window (1 - (d/r)^4)^2 enters as its mean over the segment, exact without
// extinction (glowWindowIntegral), so the halo fades out at the radius instead of ending in a
// visible dome. Approximations, each said where it is made: that mean's weighting ignores the
// extinction along the segment; a spot light glows as a point light of the flux its cone lets out (the
// solid-angle fraction of a cone at the mean of its inner and outer angles), a halo, not a beam;
// the glow is not shadowed.
//
// Selection (CPU, each frame): a light glows when its bounding sphere meets the view frustum and
// the medium's optical depth across its radius (sigma_s r) reaches kGlowMinOpticalDepth (clear
// air does not: a lamp's halo there is below a thousandth of what it lights); the brightest
// [lights] glow_max_lights of them (I * sigma_s / distance) are drawn. No glowing light: no pass,
// no memory (the feature is a FeatureSlot).
#pragma once

#include "renderer/frame_graph.h"
#include "renderer/gl/objects.h"
#include "renderer/lighting/light_settings.h"
#include "renderer/lights.h"
#include "renderer/program_key.h"
#include "renderer/render_context.h"
#include "renderer/scene_targets.h"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace vista {

struct SkySettings;  // config/settings.h ([sky]: the medium)

inline constexpr int kGlowTableU = 128;             // texels along u / (1 + u)
inline constexpr int kGlowTableV = 256;             // texels along x / (pi / 2)
inline constexpr double kGlowMinOpticalDepth = 1e-3;  // sigma_s * radius below which a light does not glow

// The medium around a light (homogeneous over its radius).
struct GlowMedium {
    glm::dvec3 scattering{0.0};  // 1/m, RGB
    double extinction = 0.0;     // 1/m, grey (the mean of the RGB extinction)
};
// The sky's medium ([sky]: Rayleigh, aerosols, ozone, height fog) at an altitude (m).
GlowMedium glowMedium(const SkySettings& sky, double altitude_m);

// F(u, x) = integral from 0 to x of exp(-u tan xi) dxi, u >= 0, 0 <= x <= pi/2, by adaptive
// Simpson quadrature (the reference the table is made from).
double glowF(double u, double x);
// The table the shader reads: kGlowTableU x kGlowTableV floats, row j (x = j / (V - 1) * pi/2)
// after row j - 1, texel i of a row at u / (1 + u) = i / (U - 1).
std::vector<float> glowTable();
// F read from the table as the GPU's bilinear filter reads it (texel centres at the samples).
double glowTableF(std::span<const float> table, double u, double x);

// The radiance (per unit sigma_s * I, so that L = sigma_s * I * glowTransfer) a point light at p
// (camera-relative m, radius r) scatters towards the camera along the unit ray dir up to the
// distance t_end, by the closed form with F from `f` (glowF or a table read). With `window`
// (as the shader) times the mean of the falloff's window over the segment, weighted as the
// integral weighs it without extinction (dt / d^2 = dtheta / h): exact in clear air, an
// approximation with extinction.
template <class F>
double glowTransfer(const glm::dvec3& p, const glm::dvec3& dir, double t_end, double radius, double extinction, F f,
                    bool window = true);
// The same integral marched numerically with the light's real falloff (lights.h falloffD,
// window included), for tests: the reference the closed form approximates.
double glowTransferReference(const glm::dvec3& p, const glm::dvec3& dir, double t_end, double radius, double extinction,
                             bool window);

// Share of a light's flux its cone lets out (1 for a point light).
double glowConeFraction(const Light& light);

struct GlowStats {
    std::uint64_t glowing = 0;  // lights drawn this frame
    std::uint64_t dropped = 0;  // would glow, beyond [lights] glow_max_lights
};

// One light as the shader reads it (std430, lamp_glow.glsl).
struct GlowLight {
    glm::vec4 position_radius;       // camera-relative m, radius m
    glm::vec4 scatter_extinction;    // sigma_s * I * colour * cone share * pre-exposure / (2 pi), sigma_t (1/m)
    glm::vec4 rect;                  // the sphere's screen rectangle, NDC x0 y0 x1 y1 (the quad drawn)
};
// A rectangle (NDC x0 y0 x1 y1) holding a sphere's image (camera-relative centre, radius m): the
// hull of the projected corners of its bounding cube, the whole screen when it reaches the
// near plane.
glm::vec4 sphereScreenRect(const glm::dvec3& center_rel, double radius, const ViewParams& view, const ViewMatrices& m);

// The lights a frame's glow draws (the CPU side, no GL).
std::vector<GlowLight> selectGlowLights(std::span<const Light> lights, const SkySettings& sky, const ViewParams& view,
                                        const ViewMatrices& m, int max_lights, double radiance_scale, GlowStats& stats);

class LampGlow {
public:
    LampGlow();
    // False when no light glows this frame (add no pass).
    bool prepare(std::span<const Light> lights, const LightsSettings& s, const SkySettings& sky, const ViewParams& view,
                 const ViewMatrices& m, double radiance_scale);
    // "lights.glow": adds the glow of the prepared lights to targets.hdr (reads targets.depth).
    void addPass(FrameGraph& graph, const RenderContext& rc, SceneTargets& targets);
    const GlowStats& stats() const { return stats_; }
    std::size_t gpuMemoryBytes() const;
    void release(GlDevice&) {}

private:
    gl::Texture table_;
    gl::Buffer lights_buf_;
    std::vector<GlowLight> lights_;
    GlowStats stats_;
};

ProgramList lampGlowPrograms();  // for FrameRenderer::allPrograms()

// ---- implementation of the template ----
// Antiderivative in theta of the falloff's window (1 - q^4 sec^4 theta)^2 (q = h / r), written
// with a = (t - t_c) / r = q tan theta: theta - 2 q^4 (tan + tan^3 / 3) + q^8 (tan + tan^3 +
// 3 tan^5 / 5 + tan^7 / 7), every power of tan paired with q so that none overflows.
inline double glowWindowIntegral(double theta, double a, double q) {
    const double q2 = q * q, a2 = a * a, q3 = q2 * q, q5 = q3 * q2, q7 = q5 * q2;
    return theta - 2.0 * (q3 * a + q * a * a2 / 3.0) + (q7 * a + q5 * a * a2 + 0.6 * q3 * a * a2 * a2 + q * a * a2 * a2 * a2 / 7.0);
}

template <class F>
double glowTransfer(const glm::dvec3& p, const glm::dvec3& dir, double t_end, double radius, double extinction, F f,
                    bool window) {
    const double tc = glm::dot(dir, p);
    const double h2 = std::max(glm::dot(p, p) - tc * tc, 0.0);
    if (!(h2 < radius * radius) || !(t_end > 0.0)) return 0.0;
    const double half_chord = std::sqrt(radius * radius - h2);
    const double t0 = std::max(tc - half_chord, 0.0), t1 = std::min(tc + half_chord, t_end);
    if (!(t1 > t0)) return 0.0;
    const double h = std::sqrt(h2 + double(kFalloffEpsM2));
    constexpr double kQuarterPi = 0.78539816339744831;
    const double th0 = std::atan((t0 - tc) / h), th1 = std::atan((t1 - tc) / h);
    const double x0 = kQuarterPi + 0.5 * th0, x1 = kQuarterPi + 0.5 * th1;
    const double u = extinction * h;
    constexpr double kInvTwoPi = 0.15915494309189535;
    // t + d(t) grows along the ray, so exp(-sigma_t (t0 + d(t0))) (x1 - x0) bounds the integral:
    // it keeps a table's rounding from being magnified by exp(-sigma_t t_c) > 1 (light behind).
    const double d0 = std::sqrt((t0 - tc) * (t0 - tc) + h * h);
    const double bound = std::exp(-extinction * (t0 + d0)) * (x1 - x0);
    const double integral = std::max(std::min(std::exp(-extinction * tc) * (f(u, x1) - f(u, x0)), bound), 0.0);
    if (!window) return kInvTwoPi / h * integral;
    // The window's mean over the segment in theta (exact without extinction: dt / d^2 = dtheta / h).
    const double q = h / radius;
    const double mean = th1 - th0 > 1e-3 ? (glowWindowIntegral(th1, (t1 - tc) / radius, q) -
                                            glowWindowIntegral(th0, (t0 - tc) / radius, q)) / (th1 - th0)
                                         : std::pow(std::max(1.0 - q * q * q * q, 0.0), 2.0);
    return kInvTwoPi / h * integral * std::clamp(mean, 0.0, 1.0);
}

}  // namespace vista
