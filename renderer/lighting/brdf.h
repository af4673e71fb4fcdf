// The BRDF of vista's deferred and forward lighting, mirrored from
// renderer/lighting/shaders/brdf.glsl for reference tests.
//
//   f(l, v) = albedo * 21 / (20 pi) (1 - F0) (1 - (1 - n.l)^5) (1 - (1 - n.v)^5)
//           + D(n.h) * V(n.l, n.v) * F(v.h)
//   D(n.h)  = a^2 / (pi ((n.h)^2 (a^2 - 1) + 1)^2)          GGX (Trowbridge-Reitz) distribution
//   V       = 0.5 / (n.l sqrt((n.v)^2 (1 - a^2) + a^2) + n.v sqrt((n.l)^2 (1 - a^2) + a^2))
//             the height-correlated Smith visibility term G / (4 n.l n.v) (Heitz 2014)
//   F(v.h)  = F0 + (1 - F0) (1 - v.h)^5                      Schlick's Fresnel
//   a       = max(roughness, 0.045)^2                         perceptual roughness squared
//
// The diffuse lobe is Shirley et al. 1997's coupled diffuse: it takes what the surface's Fresnel
// reflection leaves, on the way in and out, so its directional albedo is
// (1 - F0)(1 - (1 - n.v)^5) and diffuse + specular stays <= 1 for albedo <= 1 at every view and
// roughness (Monte Carlo in tests/unit/brdf_test.cpp). A plain (1 - F(v.h)) Lambert weighting
// does not: it reflected up to 1.3x the incoming energy at grazing views (same test). Single-
// scattering GGX loses some energy at high roughness (no multiple-scattering compensation).
//
// Lighting: a light whose irradiance at normal incidence is E adds L = f * E * max(n.l, 0) of
// radiance toward the eye. The sun's E is [sky] sun_illuminance times its transmittance; a point
// or spot light's E is colour * intensity * falloff * spot (renderer/lights.h). Ambient light
// (renderer/lighting/shaders/sun.glsl) is a hemisphere: irradiance E(n) = mix(E_ground, E_sky, 0.5 + 0.5 n.y)
// from the sky irradiance on an up-facing surface and the ground's bounce; it adds
// (1 - F_r) albedo / pi * E(n) + F_r / pi * E(r), r the mirror direction and
// F_r = F0 + (1 - F0)(1 - n.v)^5 (1 - roughness), times ambient occlusion when present.
#pragma once

#include <glm/vec3.hpp>

namespace vista {

inline constexpr double kMinRoughness = 0.045;  // below it highlights alias and overflow half floats

// f(l, v) as above; n, l, v unit vectors (l toward the light, v toward the eye). 0 for n.l <= 0.
glm::dvec3 evalBrdf(const glm::dvec3& albedo, double roughness, double f0, const glm::dvec3& n, const glm::dvec3& l,
                    const glm::dvec3& v);

}  // namespace vista
