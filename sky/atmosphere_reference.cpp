// Double-precision reference integrator for the atmosphere model.
//
// Radiance along a view ray from x_0, with the sun as one directional light of irradiance E
// (the radiative transfer integral as written in Hillaire 2020, "A Scalable and Production
// Ready Sky and Atmosphere Rendering Technique", EGSR, in its section on the atmosphere model):
//   L = int_0^D T(x_0, x_t) J(x_t) dt,    T(a, b) = exp(-int_a^b sigma_t),
//   J(x) = E [ (sigma_s^R(x) P_R(nu) + sigma_s^M(x) P_M(nu)) V(x) T_sun(x) + sigma_s(x) psi_ms(x) ],
// where V is 0 in the planet's shadow and T_sun is the transmittance from x to the top of the
// atmosphere towards the sun. The first term is single scattering (Bruneton & Neyret 2008,
// "Precomputed Atmospheric Scattering"; Bruneton 2017, functions.glsl "Single scattering"),
// integrated exactly up to quadrature. The second is Hillaire 2020's multiple-scattering
// approximation (its "multiple scattering LUT" section): every order from the second on is
// isotropic, and the light reaching a point's neighbourhood is that reaching the point, so
// with p_u = 1 / (4 pi):
//   L'(x, w)   = T(x, x_g) L_ground + int sigma_s(y) V(y) T_sun(y) p_u dt   (y = x + t w),
//   L_2nd(x)   = int_sphere L'(x, w) p_u dw,
//   f_ms(x)    = int_sphere [ int sigma_s(y) T(x, y) dt ] p_u dw,
//   psi_ms(x)  = L_2nd F_ms,   F_ms = 1 + f_ms + f_ms^2 + ... = 1 / (1 - f_ms),
// with L_ground = albedo / pi * T_sun(x_g) max(mu_s(x_g), 0) the sunlight a Lambertian ground
// reflects. psi_ms depends only on (r, mu_s), as in Hillaire's 2D LUT. (The paper's section
// and equation numbers could not be checked from here, so they are cited by name.)
//
// Quadrature. Each ray integral is split at its perigee (where the altitude turns), where the
// ozone tent bends (10, 25, 40 km) and where it crosses the edge of the planet's shadow (the
// cylinder of radius R behind the planet, where V jumps); on each piece the altitude is
// monotone and the integrand smooth. The step budget is shared evenly by the pieces. A piece
// is sampled at t = length * u^2 from its lower end (or mirrored), u uniform, and integrated by
// composite Simpson; the optical depth to every node comes from 4-point (cubic) interval
// formulas on the same nodes, so the whole scheme is fourth order in the step and needs no
// sub-stepping. At the shadow edge the lit side takes the grazing transmittance limit, so no
// node straddles the jump.
#include "sky/atmosphere_reference.h"

#include <glm/exponential.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <thread>
#include <vector>

namespace vista {

namespace {

constexpr double kPi = std::numbers::pi;

// A ray in (r, mu, mu_s, nu) form (Bruneton 2017): origin radius, cos of the view zenith angle,
// cos of the sun zenith angle at the origin, cos of the angle between the ray and the sun.
struct RayState {
    double r, mu, mu_s, nu;
};

double radiusAt(const RayState& s, double t) { return std::sqrt(std::max(s.r * s.r + t * (2.0 * s.r * s.mu + t), 0.0)); }

double muSAt(const RayState& s, double t, double r_t) {
    return std::clamp((s.r * s.mu_s + t * s.nu) / r_t, -1.0, 1.0);
}

int evenAtLeast(int n, int lo) {
    n = std::max(n, lo);
    return n + (n & 1);
}

// A piece [a, b] of a ray sampled densely at its lower-altitude end.
struct Piece {
    double a, b;
    bool dense_at_a;
};

void mapPiece(const Piece& pc, double u, double& t, double& dt_du) {
    double len = pc.b - pc.a;
    if (pc.dense_at_a) {
        t = pc.a + len * u * u;
        dt_du = 2.0 * len * u;
    } else {
        double v = 1.0 - u;
        t = pc.b - len * v * v;
        dt_du = 2.0 * len * v;
    }
}

// Where a ray's integrand has a kink or a jump, as sorted distances in [0, length] (both ends
// included): the perigee (the altitude turns), the spheres where the ozone tent bends, and
// optionally the crossings of the planet's shadow, the cylinder |x - (x.s) s| = R with x.s < 0:
// (1 - nu^2) t^2 + 2 r (mu - mu_s nu) t + (r^2 (1 - mu_s^2) - R^2) = 0. Between two cuts the
// altitude is monotone and the integrand smooth.
struct Cuts {
    std::array<double, 12> t;
    int count = 0;
    void add(double v, double length) {
        if (v > 0.0 && v < length) t[count++] = v;
    }
};

Cuts rayCuts(const AtmosphereParams& p, const RayState& s, double length, bool shadow) {
    const double R = p.bottom_radius;
    Cuts c;
    c.t[c.count++] = 0.0;
    c.add(-s.r * s.mu, length);
    if (p.ozone_half_width > 0.0)
        for (double h : {p.ozone_center_altitude - p.ozone_half_width, p.ozone_center_altitude,
                         p.ozone_center_altitude + p.ozone_half_width}) {
            double rho = R + h;
            double disc = (rho - s.r) * (rho + s.r) + (s.r * s.mu) * (s.r * s.mu);
            if (h <= 0.0 || disc <= 0.0) continue;
            c.add(-s.r * s.mu - std::sqrt(disc), length);
            c.add(-s.r * s.mu + std::sqrt(disc), length);
        }
    double qa = 1.0 - s.nu * s.nu;
    if (shadow && qa > 1e-12) {
        double qb = s.r * (s.mu - s.mu_s * s.nu);
        double qc = (s.r - R) * (s.r + R) - (s.r * s.mu_s) * (s.r * s.mu_s);
        double disc = qb * qb - qa * qc;
        if (disc > 0.0) {
            double sq = std::sqrt(disc);
            for (double t : {(-qb - sq) / qa, (-qb + sq) / qa})
                if (s.r * s.mu_s + t * s.nu < 0.0) c.add(t, length);
        }
    }
    std::sort(c.t.begin(), c.t.begin() + c.count);
    c.t[c.count++] = length;
    return c;
}

// The pieces between cuts, each to be sampled densely at its lower-altitude end.
int rayPieces(const RayState& s, const Cuts& c, double length, std::array<Piece, 12>& pieces) {
    int n = 0;
    for (int i = 0; i + 1 < c.count; ++i) {
        double a = c.t[i], b = c.t[i + 1];
        if (b - a <= 1e-9 * length) continue;
        pieces[n++] = {a, b, radiusAt(s, a) <= radiusAt(s, b)};
    }
    return n;
}

// Optical depth along a ray that does not go below the ground (mu >= horizonMu), over
// [0, length]: composite Simpson on each piece.
glm::dvec3 opticalDepthAlong(const AtmosphereParams& p, double r, double mu, double length, int steps) {
    if (!(length > 0.0)) return glm::dvec3(0.0);
    RayState s{r, mu, 0.0, 0.0};
    std::array<Piece, 12> pieces;
    int count = rayPieces(s, rayCuts(p, s, length, false), length, pieces);
    int n = evenAtLeast((steps + count - 1) / std::max(count, 1), 2);
    double h = 1.0 / n;
    glm::dvec3 od(0.0);
    for (int i = 0; i < count; ++i) {
        glm::dvec3 sum(0.0);
        for (int k = 0; k <= n; ++k) {
            double t, dt_du;
            mapPiece(pieces[i], k * h, t, dt_du);
            double w = (k == 0 || k == n) ? 1.0 : (k % 2 ? 4.0 : 2.0);
            sum += w * dt_du * sampleMedium(p, radiusAt(s, t) - p.bottom_radius).extinction;
        }
        od += sum * (h / 3.0);
    }
    return od;
}

// Transmittance to the top of the atmosphere towards the sun from (r, mu_s). With
// ignore_ground the ray is held at the horizon (the lit-side limit at the shadow's edge).
glm::dvec3 transmittanceToSun(const AtmosphereParams& p, double r, double mu_s, int steps, bool ignore_ground) {
    r = std::clamp(r, p.bottom_radius, p.top_radius);
    if (!ignore_ground && rayIntersectsGround(p, r, mu_s)) return glm::dvec3(0.0);
    mu_s = std::max(mu_s, horizonMu(p, r));
    return glm::exp(-opticalDepthAlong(p, r, mu_s, distanceToTop(p, r, mu_s), steps));
}

struct RaySums {
    glm::dvec3 optical_depth{0.0};  // to the end of the ray
    glm::dvec3 a{0.0}, b{0.0};      // int T(0, t) source_a(t) dt and the same for source_b
};

// Integrates two sources along a ray against the transmittance from its origin. The source is
// called as source(r_t, mu_s_t, medium, lit, a, b) and writes a and b (per metre).
template <class Source>
RaySums integrateRay(const AtmosphereParams& p, const RayState& s, double length, int steps, Source&& source) {
    RaySums out;
    if (!(length > 0.0)) return out;
    const double R = p.bottom_radius;

    std::array<Piece, 12> pieces;
    int n_pieces = rayPieces(s, rayCuts(p, s, length, true), length, pieces);
    const int n = evenAtLeast((steps + n_pieces - 1) / std::max(n_pieces, 1), 4);
    const double h = 1.0 / n;

    std::vector<glm::dvec3> ext(n + 1), ja(n + 1), jb(n + 1);
    for (int i = 0; i < n_pieces; ++i) {
        const Piece& pc = pieces[i];
        double t_mid = 0.5 * (pc.a + pc.b), r_mid = radiusAt(s, t_mid);
        bool lit = !rayIntersectsGround(p, r_mid, muSAt(s, t_mid, r_mid));
        for (int k = 0; k <= n; ++k) {
            double t, dt_du;
            mapPiece(pc, k * h, t, dt_du);
            double r_t = radiusAt(s, t);
            MediumSample m = sampleMedium(p, r_t - R);
            glm::dvec3 a(0.0), b(0.0);
            source(r_t, muSAt(s, t, r_t), m, lit, a, b);
            ext[k] = m.extinction * dt_du;
            ja[k] = a * dt_du;
            jb[k] = b * dt_du;
        }
        // Transmittance from the ray's origin to each node, then Simpson on T * J.
        glm::dvec3 od = out.optical_depth;
        for (int k = 0; k <= n; ++k) {
            glm::dvec3 tr = glm::exp(-od);
            double w = (k == 0 || k == n) ? 1.0 : (k % 2 ? 4.0 : 2.0);
            out.a += (w * h / 3.0) * tr * ja[k];
            out.b += (w * h / 3.0) * tr * jb[k];
            if (k == n) break;
            glm::dvec3 interval;
            if (k == 0)
                interval = 9.0 * ext[0] + 19.0 * ext[1] - 5.0 * ext[2] + ext[3];
            else if (k == n - 1)
                interval = ext[n - 3] - 5.0 * ext[n - 2] + 19.0 * ext[n - 1] + 9.0 * ext[n];
            else
                interval = -ext[k - 1] + 13.0 * ext[k] + 13.0 * ext[k + 1] - ext[k + 2];
            od += glm::max(interval * (h / 24.0), glm::dvec3(0.0));
        }
        out.optical_depth = od;
    }
    return out;
}


}  // namespace

void gaussLegendre01(int n, std::vector<double>& x, std::vector<double>& w) {
    x.assign(n, 0.0);
    w.assign(n, 0.0);
    for (int i = 0; i < n; ++i) {
        double z = std::cos(kPi * (i + 0.75) / (n + 0.5)), dp = 1.0;
        for (int it = 0; it < 100; ++it) {
            double p0 = 1.0, p1 = 0.0;
            for (int j = 1; j <= n; ++j) {
                double p2 = p1;
                p1 = p0;
                p0 = ((2.0 * j - 1.0) * z * p1 - (j - 1.0) * p2) / j;
            }
            dp = n * (z * p0 - p1) / (z * z - 1.0);
            double dz = p0 / dp;
            z -= dz;
            if (std::abs(dz) < 1e-15) break;
        }
        x[i] = 0.5 * (1.0 - z);
        w[i] = 1.0 / ((1.0 - z * z) * dp * dp);  // 2 / ((1 - z^2) P'^2), halved for [0, 1]
    }
}

glm::dvec3 opticalDepth(const AtmosphereParams& p, double r, double mu, int steps) {
    r = std::clamp(r, p.bottom_radius, p.top_radius);
    mu = std::clamp(mu, -1.0, 1.0);
    double length = rayIntersectsGround(p, r, mu) ? distanceToGround(p, r, mu) : distanceToTop(p, r, mu);
    return opticalDepthAlong(p, r, mu, length, steps);
}

glm::dvec3 transmittance(const AtmosphereParams& p, double r, double mu, int steps) {
    return transmittanceToSun(p, r, std::clamp(mu, -1.0, 1.0), steps, false);
}

glm::dvec3 multipleScattering(const AtmosphereParams& p, double r, double mu_s, const IntegrationSteps& steps) {
    const double R = p.bottom_radius;
    r = std::clamp(r, R, p.top_radius);
    mu_s = std::clamp(mu_s, -1.0, 1.0);
    const double sin_s = std::sqrt(std::max(1.0 - mu_s * mu_s, 0.0));

    std::vector<double> gx, gw;
    gaussLegendre01(std::max(steps.ms_polar, 1), gx, gw);
    const int n_az = std::max(steps.ms_azimuth, 1);
    const double az_weight = 2.0 * kPi / n_az;  // midpoint over [0, pi], doubled by symmetry

    auto source = [&](double r_t, double mu_s_t, const MediumSample& m, bool lit, glm::dvec3& a, glm::dvec3& b) {
        b = m.scattering();
        if (lit) a = b * transmittanceToSun(p, r_t, mu_s_t, steps.ms_transmittance, true) * kIsotropicPhase;
    };

    glm::dvec3 l_2nd(0.0), f_ms(0.0);
    // Polar nodes, in three ranges whose edges are where the ray integrals have square-root
    // edges (horizontal, tangent to the ground); each map puts a double zero at such an edge so
    // Gauss-Legendre sees a smooth integrand there:
    //   up:            mu = w^2
    //   down, sky:     perigee radius r_p = r sin(theta) = R + (r - R) w^2 (3 - 2 w); this also
    //                  cancels the 1 / sqrt edge of d mu / d r_p at the horizontal
    //   down, ground:  mu = mu_h - (1 + mu_h) w^2, from the ground's horizon to the nadir
    const double mu_h = horizonMu(p, r);
    for (int range = 0; range < 3; ++range) {
        if (range == 1 && r <= R) continue;
        for (std::size_t i = 0; i < gx.size(); ++i) {
            double w = gx[i], mu, d_mu;
            if (range == 0) {
                mu = w * w;
                d_mu = gw[i] * 2.0 * w;
            } else if (range == 1) {
                double r_p = R + (r - R) * w * w * (3.0 - 2.0 * w);
                double dr_p = (r - R) * 6.0 * w * (1.0 - w);
                double root = std::sqrt(std::max((r - r_p) * (r + r_p), 0.0));  // r |mu|
                if (!(root > 0.0)) continue;
                mu = -root / r;
                d_mu = gw[i] * dr_p * r_p / (r * root);
            } else {
                mu = mu_h - (1.0 + mu_h) * w * w;
                d_mu = gw[i] * 2.0 * (1.0 + mu_h) * w;
            }
            double sin_v = std::sqrt(std::max(1.0 - mu * mu, 0.0));
            bool ground = range == 2;
            double length = ground ? distanceToGround(p, r, mu) : distanceToTop(p, r, mu);
            for (int j = 0; j < n_az; ++j) {
                double phi = (j + 0.5) * kPi / n_az;
                double nu = std::clamp(sin_v * sin_s * std::cos(phi) + mu * mu_s, -1.0, 1.0);
                RayState s{r, mu, mu_s, nu};
                RaySums sums = integrateRay(p, s, length, steps.ms_ray, source);
                glm::dvec3 l_prime = sums.a;
                if (ground) {
                    double mu_s_g = std::clamp((r * mu_s + length * nu) / R, -1.0, 1.0);
                    if (mu_s_g > 0.0)
                        l_prime += glm::exp(-sums.optical_depth) * (p.ground_albedo / kPi) * mu_s_g *
                                   transmittanceToSun(p, R, mu_s_g, steps.ms_transmittance, false);
                }
                double weight = d_mu * az_weight * kIsotropicPhase;
                l_2nd += weight * l_prime;
                f_ms += weight * sums.b;
            }
        }
    }
    return l_2nd / (glm::dvec3(1.0) - glm::min(f_ms, glm::dvec3(0.999)));
}

MultipleScatteringTable::MultipleScatteringTable(const AtmosphereParams& p, const IntegrationSteps& steps,
                                                 int altitude_size, int mu_s_size)
    : bottom_radius_(p.bottom_radius),
      top_radius_(p.top_radius),
      altitude_size_(std::max(altitude_size, 2)),
      mu_s_size_(std::max(mu_s_size, 2)),
      values_(std::size_t(altitude_size_) * std::size_t(mu_s_size_)) {
    auto row = [&](int i) {
        double x = double(i) / (altitude_size_ - 1);
        double r = bottom_radius_ + x * x * (top_radius_ - bottom_radius_);
        for (int j = 0; j < mu_s_size_; ++j) {
            double mu_s = -1.0 + 2.0 * j / (mu_s_size_ - 1);
            glm::dvec3 psi = multipleScattering(p, r, mu_s, steps);
            values_[std::size_t(i) * mu_s_size_ + j] = glm::log(glm::max(psi, glm::dvec3(1e-300)));
        }
    };
    unsigned workers = std::max(1u, std::min(std::thread::hardware_concurrency(), unsigned(altitude_size_)));
    std::vector<std::thread> threads;
    for (unsigned w = 0; w < workers; ++w)
        threads.emplace_back([&, w] {
            for (int i = int(w); i < altitude_size_; i += int(workers)) row(i);
        });
    for (std::thread& t : threads) t.join();
}

glm::dvec3 MultipleScatteringTable::operator()(double r, double mu_s) const {
    double h = std::clamp((r - bottom_radius_) / (top_radius_ - bottom_radius_), 0.0, 1.0);
    double fx = std::sqrt(h) * (altitude_size_ - 1), fy = (std::clamp(mu_s, -1.0, 1.0) + 1.0) * 0.5 * (mu_s_size_ - 1);
    int x0 = std::min(int(fx), altitude_size_ - 2), y0 = std::min(int(fy), mu_s_size_ - 2);
    double ax = fx - x0, ay = fy - y0;
    auto at = [&](int i, int j) { return values_[std::size_t(i) * mu_s_size_ + j]; };
    glm::dvec3 log_psi = (1.0 - ax) * ((1.0 - ay) * at(x0, y0) + ay * at(x0, y0 + 1)) +
                         ax * ((1.0 - ay) * at(x0 + 1, y0) + ay * at(x0 + 1, y0 + 1));
    return glm::exp(log_psi);
}

ViewRayResult integrateViewRay(const AtmosphereParams& p, glm::dvec3 camera_pos, glm::dvec3 view_dir,
                               glm::dvec3 sun_dir, double max_distance, const IntegrationSteps& steps,
                               const MultipleScatteringTable* ms) {
    ViewRayResult result;
    glm::dvec3 o = planetFromWorld(p, camera_pos);
    glm::dvec3 d = glm::normalize(view_dir), sun = glm::normalize(sun_dir);
    AtmosphereSegment seg = atmosphereSegment(p, o, d);
    if (!seg.hit || max_distance <= seg.t_enter) {
        result.distance = seg.hit ? max_distance : seg.t_enter;
        return result;
    }
    glm::dvec3 x0 = o + seg.t_enter * d;
    double r0 = std::clamp(glm::length(x0), p.bottom_radius, p.top_radius);
    double end = std::min(seg.t_exit, max_distance);
    RayState s{r0, std::clamp(glm::dot(x0, d) / r0, -1.0, 1.0), std::clamp(glm::dot(x0, sun) / r0, -1.0, 1.0),
               std::clamp(glm::dot(d, sun), -1.0, 1.0)};
    const double phase_r = rayleighPhase(s.nu), phase_m = miePhase(p, s.nu);

    auto source = [&](double r_t, double mu_s_t, const MediumSample& m, bool lit, glm::dvec3& a, glm::dvec3&) {
        glm::dvec3 psi = ms ? (*ms)(r_t, mu_s_t) : multipleScattering(p, r_t, mu_s_t, steps);
        a = m.scattering() * psi;
        if (lit)
            a += (m.rayleigh_scattering * phase_r + m.mie_scattering * phase_m) *
                 transmittanceToSun(p, r_t, mu_s_t, steps.transmittance, true);
    };
    RaySums sums = integrateRay(p, s, end - seg.t_enter, steps.view, source);
    result.radiance = sums.a * p.solar_irradiance;
    result.transmittance = glm::exp(-sums.optical_depth);
    result.hits_ground = seg.ends_on_ground && seg.t_exit <= max_distance;
    result.distance = end;
    return result;
}

glm::dvec3 skyRadiance(const AtmosphereParams& p, glm::dvec3 camera_pos, glm::dvec3 view_dir, glm::dvec3 sun_dir,
                       const IntegrationSteps& steps, const MultipleScatteringTable* ms) {
    return integrateViewRay(p, camera_pos, view_dir, sun_dir, std::numeric_limits<double>::infinity(), steps, ms)
        .radiance;
}

glm::dvec3 sunTransmittance(const AtmosphereParams& p, glm::dvec3 pos, glm::dvec3 sun_dir, int steps) {
    glm::dvec3 x = planetFromWorld(p, pos), s = glm::normalize(sun_dir);
    double r = glm::length(x), mu_s = std::clamp(glm::dot(x, s) / r, -1.0, 1.0);
    // Fraction of the disk above the horizon: the area of a circle of angular radius a above a
    // (locally straight) horizon line at angular distance e below its centre.
    double a = std::max(p.sun_angular_radius, 1e-9);
    double e = std::clamp((std::asin(mu_s) - std::asin(horizonMu(p, r))) / a, -1.0, 1.0);
    double visible = 1.0 - (std::acos(e) - e * std::sqrt(1.0 - e * e)) / kPi;
    if (visible <= 0.0) return glm::dvec3(0.0);
    // The sun's ray held at the horizon when the disk's centre has set.
    glm::dvec3 dir = s;
    if (mu_s < horizonMu(p, r)) {
        glm::dvec3 up = x / r, side = s - glm::dot(s, up) * up;
        double side_len = glm::length(side);
        glm::dvec3 h = side_len > 0.0 ? side / side_len : glm::dvec3(1.0, 0.0, 0.0);
        double mu_h = horizonMu(p, r);
        dir = mu_h * up + std::sqrt(std::max(1.0 - mu_h * mu_h, 0.0)) * h;
    }
    AtmosphereSegment seg = atmosphereSegment(p, x, dir);
    if (!seg.hit) return glm::dvec3(visible);
    glm::dvec3 entry = x + seg.t_enter * dir;
    double re = std::clamp(glm::length(entry), p.bottom_radius, p.top_radius);
    double mu = std::max(std::clamp(glm::dot(entry, dir) / re, -1.0, 1.0), horizonMu(p, re));
    return visible * transmittanceToSun(p, re, mu, steps, true);
}

glm::dvec3 sunIrradiance(const AtmosphereParams& p, glm::dvec3 pos, glm::dvec3 sun_dir, int steps) {
    return p.solar_irradiance * sunTransmittance(p, pos, sun_dir, steps);
}

glm::dvec3 skyIrradianceUp(const AtmosphereParams& p, glm::dvec3 pos, glm::dvec3 sun_dir, const IntegrationSteps& steps,
                           const MultipleScatteringTable* ms, int polar_nodes, int azimuth_nodes) {
    glm::dvec3 up = glm::normalize(planetFromWorld(p, pos)), s = glm::normalize(sun_dir);
    glm::dvec3 e1 = s - glm::dot(s, up) * up;
    if (glm::length(e1) < 1e-9) e1 = std::abs(up.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 0, 1);
    e1 = glm::normalize(e1 - glm::dot(e1, up) * up);
    glm::dvec3 e2 = glm::cross(up, e1);
    std::vector<double> gx, gw;
    gaussLegendre01(std::max(polar_nodes, 1), gx, gw);
    int n_az = std::max(azimuth_nodes, 1);
    glm::dvec3 e(0.0);
    for (std::size_t i = 0; i < gx.size(); ++i) {
        double mu = gx[i], sin_t = std::sqrt(std::max(1.0 - mu * mu, 0.0));
        for (int j = 0; j < n_az; ++j) {
            double phi = (j + 0.5) * kPi / n_az;
            glm::dvec3 w = mu * up + sin_t * (std::cos(phi) * e1 + std::sin(phi) * e2);
            e += (gw[i] * mu * 2.0 * kPi / n_az) * skyRadiance(p, pos, w, s, steps, ms);
        }
    }
    return e;
}

}  // namespace vista
