// Glow around lamps in fog (see lamp_glow.h for the model and its approximations).
#include "renderer/lighting/lamp_glow.h"

#include "renderer/bindings.h"
#include "renderer/lighting/local_lights.h"
#include "renderer/pass_kit.h"
#include "sky/atmosphere.h"
#include "sky/atmosphere_model.h"
#include "sky/sky_settings.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <numbers>

namespace vista {

namespace {

constexpr const char* kGlowProgram = "renderer/lighting/shaders/lamp_glow.glsl";
constexpr double kGlowHalfPi = std::numbers::pi / 2.0;

// Simpson's rule on [a, b] refined where it disagrees with its halves (tolerance eps).
template <class G>
double glowSimpson(G g, double a, double b, double fa, double fm, double fb, double whole, double eps, int depth) {
    const double m = 0.5 * (a + b), lm = 0.5 * (a + m), rm = 0.5 * (m + b);
    const double flm = g(lm), frm = g(rm);
    const double left = (m - a) / 6.0 * (fa + 4.0 * flm + fm), right = (b - m) / 6.0 * (fm + 4.0 * frm + fb);
    if (depth <= 0 || std::abs(left + right - whole) <= 15.0 * eps) return left + right + (left + right - whole) / 15.0;
    return glowSimpson(g, a, m, fa, flm, fm, left, 0.5 * eps, depth - 1) +
           glowSimpson(g, m, b, fm, frm, fb, right, 0.5 * eps, depth - 1);
}

template <class G>
double glowQuadrature(G g, double a, double b, double eps) {
    if (!(b > a)) return 0.0;
    const double fa = g(a), fb = g(b), fm = g(0.5 * (a + b));
    return glowSimpson(g, a, b, fa, fm, fb, (b - a) / 6.0 * (fa + 4.0 * fm + fb), eps, 30);
}

}  // namespace

GlowMedium glowMedium(const SkySettings& sky, double altitude_m) {
    const MediumSample m = sampleMedium(atmosphereParams(sky), std::max(altitude_m, 0.0));
    // The height fog as the sky's shaders add it (atmosphere.glsl fogExtinction): grey, pure
    // scattering, the exponent capped at 30.
    double fog = 0.0;
    if (sky.height_fog && sky.fog_density_per_km > 0.0f)
        fog = double(sky.fog_density_per_km) * 1e-3 *
              std::exp(std::min((double(sky.fog_base_m) - altitude_m) / double(sky.fog_falloff_m), 30.0));
    return {m.scattering() + glm::dvec3(fog), (m.extinction.x + m.extinction.y + m.extinction.z) / 3.0 + fog};
}

// The integral of exp(-u tan xi) over [a, b] within [0, pi/2]. The integrand is 0 at pi/2 for
// u > 0 (1 for u = 0); stopping 1e-12 short of the pole keeps tan finite and leaves out less
// than 1e-12.
double glowIntegral(double u, double a, double b) {
    const double end = std::min(b, kGlowHalfPi - 1e-12);
    const double part = glowQuadrature([u](double xi) { return std::exp(-u * std::tan(xi)); }, a, end, 1e-12);
    return part + (u == 0.0 ? std::max(b - std::max(end, a), 0.0) : 0.0);
}

double glowF(double u, double x) { return glowIntegral(u, 0.0, std::clamp(x, 0.0, kGlowHalfPi)); }

std::vector<float> glowTable() {
    std::vector<float> table(std::size_t(kGlowTableU) * kGlowTableV);
    for (int i = 0; i < kGlowTableU; ++i) {
        const double a = double(i) / (kGlowTableU - 1);  // u / (1 + u); the last column is u = infinity
        const double u = i == kGlowTableU - 1 ? 1e12 : a / (1.0 - a);
        double f = 0.0, x = 0.0;  // F(u, x) accumulated row by row
        for (int j = 1; j < kGlowTableV; ++j) {
            const double next = double(j) / (kGlowTableV - 1) * kGlowHalfPi;
            f += glowIntegral(u, x, next);
            x = next;
            table[std::size_t(j) * kGlowTableU + std::size_t(i)] = float(f);
        }
    }
    return table;
}

double glowTableF(std::span<const float> table, double u, double x) {
    const double fu = std::clamp(u / (1.0 + u), 0.0, 1.0) * (kGlowTableU - 1);
    const double fx = std::clamp(x / kGlowHalfPi, 0.0, 1.0) * (kGlowTableV - 1);
    const int i = std::min(int(fu), kGlowTableU - 2), j = std::min(int(fx), kGlowTableV - 2);
    const double s = fu - i, t = fx - j;
    auto at = [&](int ii, int jj) { return double(table[std::size_t(jj) * kGlowTableU + std::size_t(ii)]); };
    return (1.0 - t) * ((1.0 - s) * at(i, j) + s * at(i + 1, j)) + t * ((1.0 - s) * at(i, j + 1) + s * at(i + 1, j + 1));
}

double glowTransferReference(const glm::dvec3& p, const glm::dvec3& dir, double t_end, double radius, double extinction,
                             bool window) {
    // Only where the light reaches (d < radius) is there anything to integrate.
    const double tc = glm::dot(dir, p);
    const double h2 = std::max(glm::dot(p, p) - tc * tc, 0.0);
    if (!(h2 < radius * radius)) return 0.0;
    const double half_chord = std::sqrt(radius * radius - h2);
    const double t0 = std::max(tc - half_chord, 0.0), t1 = std::min(tc + half_chord, t_end);
    auto g = [&](double t) {
        const glm::dvec3 x = t * dir - p;
        const double d2 = glm::dot(x, x);
        const double falloff = window ? falloffD(d2, radius) : 1.0 / (d2 + double(kFalloffEpsM2));
        return std::exp(-extinction * (t + std::sqrt(d2 + double(kFalloffEpsM2)))) * falloff;
    };
    // Split at the closest approach, where the integrand peaks; the tolerance is relative to the
    // integral's size without extinction (about pi / h).
    const double mid = std::clamp(tc, t0, std::max(t1, t0));
    const double eps = 1e-10 / std::sqrt(h2 + double(kFalloffEpsM2));
    return (glowQuadrature(g, t0, mid, eps) + glowQuadrature(g, mid, t1, eps)) / (4.0 * std::numbers::pi);
}

double glowConeFraction(const Light& light) {
    if (light.type != LightType::Spot) return 1.0;
    const double mean_deg = 0.5 * (double(std::min(light.inner_deg, light.outer_deg)) + double(light.outer_deg));
    return 0.5 * (1.0 - std::cos(glm::radians(mean_deg)));
}

glm::vec4 sphereScreenRect(const glm::dvec3& center_rel, double radius, const ViewParams& view, const ViewMatrices& m) {
    const glm::dvec3 c{glm::dot(center_rel, m.right), glm::dot(center_rel, m.up), glm::dot(center_rel, m.forward)};
    const double r = radius * (1.0 + 1e-4) + 1e-4 * glm::length(center_rel);  // as sphereMeetsView pads
    if (c.z - r <= view.near_m) return glm::vec4(-1.0f, -1.0f, 1.0f, 1.0f);
    const double ty = std::tan(glm::radians(view.fov_deg) * 0.5), tx = ty * double(view.width) / double(view.height);
    // The cube lies in front of the camera: its image is the hull of its corners' images, and the
    // extremes of x / z over the corners are among (c.x +- r) / (c.z +- r).
    double x0 = 1e30, x1 = -1e30, y0 = 1e30, y1 = -1e30;
    for (double dz : {-r, r})
        for (double d : {-r, r}) {
            x0 = std::min(x0, (c.x + d) / (c.z + dz)), x1 = std::max(x1, (c.x + d) / (c.z + dz));
            y0 = std::min(y0, (c.y + d) / (c.z + dz)), y1 = std::max(y1, (c.y + d) / (c.z + dz));
        }
    auto ndc = [](double v, double t) { return float(std::clamp(v / t, -1.0, 1.0)); };
    return glm::vec4(ndc(x0, tx), ndc(y0, ty), ndc(x1, tx), ndc(y1, ty));
}

std::vector<GlowLight> selectGlowLights(std::span<const Light> lights, const SkySettings& sky, const ViewParams& view,
                                        const ViewMatrices& m, int max_lights, double radiance_scale, GlowStats& stats) {
    struct Candidate {
        double score;
        GlowLight light;
    };
    std::vector<Candidate> candidates;
    for (const Light& light : lights) {
        const double r = double(light.radius_m);
        if (!(r > 0.0) || !(light.intensity > 0.0f)) continue;
        const glm::dvec3 rel = light.position - view.position;
        if (!sphereMeetsView(rel, r, view, m)) continue;  // the glow lies inside the light's radius
        const GlowMedium medium = glowMedium(sky, light.position.y);
        const double sigma = glm::dot(medium.scattering, glm::dvec3(0.2126, 0.7152, 0.0722));
        if (sigma * r < kGlowMinOpticalDepth) continue;
        const glm::dvec3 scatter = medium.scattering * glm::dvec3(light.color) * double(light.intensity) *
                                   glowConeFraction(light) * radiance_scale / (2.0 * std::numbers::pi);
        const double brightness = glm::dot(scatter, glm::dvec3(0.2126, 0.7152, 0.0722));
        candidates.push_back({brightness / std::max(glm::length(rel), 1.0),
                              {glm::vec4(glm::vec3(rel), float(r)), glm::vec4(glm::vec3(scatter), float(medium.extinction)),
                               sphereScreenRect(rel, r, view, m)}});
    }
    const std::size_t keep = std::min(candidates.size(), std::size_t(std::max(max_lights, 0)));
    std::partial_sort(candidates.begin(), candidates.begin() + std::ptrdiff_t(keep), candidates.end(),
                      [](const Candidate& a, const Candidate& b) { return a.score > b.score; });
    stats.glowing = keep;
    stats.dropped = candidates.size() - keep;
    std::vector<GlowLight> out(keep);
    for (std::size_t i = 0; i < keep; ++i) out[i] = candidates[i].light;
    return out;
}

LampGlow::LampGlow() {
    const std::vector<float> table = glowTable();
    table_ = gl::Texture::create2D(kGlowTableU, kGlowTableV, GL_R32F, 1, "lights.glow table F(u, x)");
    glTextureSubImage2D(table_.id(), 0, 0, 0, kGlowTableU, kGlowTableV, GL_RED, GL_FLOAT, table.data());
    glTextureParameteri(table_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(table_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(table_.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(table_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

bool LampGlow::prepare(std::span<const Light> lights, const LightsSettings& s, const SkySettings& sky,
                       const ViewParams& view, const ViewMatrices& m, double radiance_scale) {
    lights_ = selectGlowLights(lights, sky, view, m, s.glow_max_lights, radiance_scale, stats_);
    if (lights_.empty()) return false;
    // Grown, never shrunk.
    const std::size_t bytes = lights_.size() * sizeof(GlowLight);
    if (std::size_t(lights_buf_.size()) < bytes)
        lights_buf_ = gl::Buffer::create(GLsizeiptr(bytes), nullptr, GL_DYNAMIC_STORAGE_BIT, "lights.glow lights");
    glNamedBufferSubData(lights_buf_.id(), 0, GLsizeiptr(bytes), lights_.data());
    return true;
}

void LampGlow::addPass(FrameGraph& graph, const RenderContext& rc, SceneTargets& targets) {
    addOverHdrPass(graph, rc, "lights.glow", targets, [this, &rc] {
        glUseProgram(rc.shaders.id(kGlowProgram));
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kAux, lights_buf_.id());
        glBindTextureUnit(binding::kTex1, table_.id());
        glEnable(GL_BLEND);
        glBlendFunc(GL_ONE, GL_ONE);  // in-scattered light adds to what is behind
        glBindVertexArray(rc.empty_vao);
        glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, GLsizei(lights_.size()));  // a quad per light
        glDisable(GL_BLEND);
    });
}

std::size_t LampGlow::gpuMemoryBytes() const { return table_.bytes() + std::size_t(lights_buf_.size()); }

ProgramList lampGlowPrograms() { return {{kGlowProgram, {}}}; }

}  // namespace vista
