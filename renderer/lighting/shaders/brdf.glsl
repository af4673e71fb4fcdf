// The BRDF every light uses (renderer/lighting/brdf.h documents it and mirrors it on the CPU):
//   f(l, v) = albedo * 21 / (20 pi) (1 - F0) (1 - (1 - n.l)^5) (1 - (1 - n.v)^5)   Shirley 1997 diffuse
//           + D(n.h) * V(n.l, n.v) * F(v.h)
//   D = a^2 / (pi * ((n.h)^2 (a^2 - 1) + 1)^2)                       GGX / Trowbridge-Reitz
//   V = 0.5 / (n.l * sqrt((n.v)^2 (1 - a^2) + a^2) + n.v * sqrt((n.l)^2 (1 - a^2) + a^2))
//                                                                     height-correlated Smith
//   F = F0 + (1 - F0) (1 - v.h)^5                                     Schlick
// with a = max(roughness, 0.045)^2. A light of irradiance E (at normal incidence) adds
// f * E * max(n.l, 0).
#ifndef VISTA_PI_DEFINED  // brdf.glsl and atmosphere.glsl both define it
#define VISTA_PI_DEFINED
const float PI = 3.14159265358979;
#endif

vec3 evalBrdf(vec3 albedo, float roughness, float f0, vec3 n, vec3 l, vec3 v) {
    float nl = min(dot(n, l), 1.0);
    if (nl <= 0.0) return vec3(0.0);
    float nv = clamp(dot(n, v), 1e-4, 1.0);  // clamped: pow(1 - x, 5) of x > 1 would be NaN
    vec3 h = safeNormalize(l + v);
    float nh = clamp(dot(n, h), 0.0, 1.0), vh = clamp(dot(v, h), 0.0, 1.0);
    float r = max(roughness, 0.045);
    float a2 = r * r * r * r;
    float d = nh * nh * (a2 - 1.0) + 1.0;
    float D = a2 / (PI * d * d);
    float V = 0.5 / (nl * sqrt(nv * nv * (1.0 - a2) + a2) + nv * sqrt(nl * nl * (1.0 - a2) + a2));
    float fw = pow(1.0 - vh, 5.0);
    float F = f0 + (1.0 - f0) * fw;
    float diffuse = 21.0 / (20.0 * PI) * (1.0 - f0) * (1.0 - pow(1.0 - nl, 5.0)) * (1.0 - pow(1.0 - nv, 5.0));
    return albedo * diffuse + vec3(D * V * F);
}
