// Cascade fitting (see cascades.h).
#include "renderer/shadows/cascades.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace vista {

std::array<double, kMaxSunCascades + 1> pssmSplits(double near_m, double far_m, int count, double lambda) {
    count = std::clamp(count, 1, kMaxSunCascades);
    std::array<double, kMaxSunCascades + 1> d{};
    d.fill(far_m);
    for (int i = 0; i <= count; ++i) {
        double t = double(i) / double(count);
        double log_split = near_m * std::pow(far_m / near_m, t);
        double uniform = near_m + (far_m - near_m) * t;
        d[std::size_t(i)] = lambda * log_split + (1.0 - lambda) * uniform;
    }
    d[0] = near_m;  // exact ends, whatever pow rounds to
    d[std::size_t(count)] = far_m;
    return d;
}

LightBasis lightBasis(const glm::dvec3& sun_dir) {
    LightBasis b;
    b.dir = glm::normalize(sun_dir);
    // Reference axis: world up, or north when the sun is (nearly) straight up or down.
    glm::dvec3 ref = std::abs(b.dir.y) < 0.999 ? glm::dvec3(0, 1, 0) : glm::dvec3(0, 0, -1);
    b.right = glm::normalize(glm::cross(ref, b.dir));
    b.up = glm::cross(b.dir, b.right);
    return b;
}

SliceSphere sliceSphere(double near_m, double far_m, double tan_half_fov_y, double aspect) {
    // Corners at depth z lie sqrt(k) z off the axis (k = tan_x^2 + tan_y^2). The centre z* with
    // equal distance to the near and far corners is (n + f)(1 + k)/2; past f, the far corners alone
    // decide (the near ones are then inside, as k (f + n) >= f - n there).
    double k = tan_half_fov_y * tan_half_fov_y * (1.0 + aspect * aspect);
    double z = std::min((near_m + far_m) * (1.0 + k) * 0.5, far_m);
    return {z, std::sqrt((far_m - z) * (far_m - z) + far_m * far_m * k)};
}

glm::dmat4 cascadeMatrix(const LightBasis& light, const ShadowCascade& c, const glm::dvec3& camera) {
    // Light-space centre relative to the camera, in double: small numbers even 10,000 km out.
    glm::dvec3 rel = c.center_world - camera;
    double u = glm::dot(rel, light.right), v = glm::dot(rel, light.up), w = glm::dot(rel, light.dir);
    double r = c.radius_m;
    glm::dmat4 m(0.0);  // column-major: m[column][row]
    for (int i = 0; i < 3; ++i) {
        m[i][0] = light.right[i] / r;
        m[i][1] = light.up[i] / r;
        m[i][2] = -light.dir[i] / (2.0 * r);
    }
    m[3][0] = -u / r;
    m[3][1] = -v / r;
    m[3][2] = (w + r) / (2.0 * r);
    m[3][3] = 1.0;
    return m;
}

ShadowCascade fitCascade(const LightBasis& light, const CascadeView& view, double near_m, double far_m,
                         int resolution, bool stabilize) {
    ShadowCascade c;
    c.near_m = near_m;
    c.far_m = far_m;
    if (stabilize) {
        // The sphere's radius depends on the slice and the field of view only, so turning the
        // camera keeps the texel size; its centre is snapped to whole texels in u and v (and w,
        // so depths do not drift either) relative to the world origin.
        SliceSphere s = sliceSphere(near_m, far_m, view.tan_half_fov_y, view.aspect);
        c.radius_m = s.radius;
        c.texel_m = 2.0 * s.radius / double(resolution);
        glm::dvec3 centre = view.position + view.forward * s.center_depth;
        auto snap = [&](double x) { return std::floor(x / c.texel_m + 0.5) * c.texel_m; };
        c.center_world = light.right * snap(glm::dot(centre, light.right)) + light.up * snap(glm::dot(centre, light.up)) +
                         light.dir * snap(glm::dot(centre, light.dir));
    } else {
        // The tight light-space box of the slice's 8 corners: its size and texel grid change
        // whenever the camera turns or moves.
        glm::dvec3 right = glm::normalize(glm::cross(view.forward, view.up));
        glm::dvec3 up = glm::cross(right, view.forward);
        glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
        for (double z : {near_m, far_m})
            for (double sx : {-1.0, 1.0})
                for (double sy : {-1.0, 1.0}) {
                    glm::dvec3 rel = view.forward * z + right * (sx * z * view.tan_half_fov_y * view.aspect) +
                                     up * (sy * z * view.tan_half_fov_y);
                    glm::dvec3 l(glm::dot(rel, light.right), glm::dot(rel, light.up), glm::dot(rel, light.dir));
                    lo = glm::min(lo, l);
                    hi = glm::max(hi, l);
                }
        glm::dvec3 mid = (lo + hi) * 0.5;
        c.radius_m = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z}) * 0.5;
        c.texel_m = 2.0 * c.radius_m / double(resolution);
        c.center_world = view.position + light.right * mid.x + light.up * mid.y + light.dir * mid.z;
    }
    c.matrix = cascadeMatrix(light, c, view.position);
    return c;
}

std::array<glm::dvec4, 6> casterPlanes(const LightBasis& light, const ShadowCascade& c, const glm::dvec3& camera,
                                       double sun_reach_m) {
    glm::dvec3 rel = c.center_world - camera;
    double r = c.radius_m;
    auto plane = [&](const glm::dvec3& n, double offset) {  // dot(n, p - rel) + offset >= 0
        return glm::dvec4(n, offset - glm::dot(n, rel));
    };
    return {plane(light.right, r), plane(-light.right, r), plane(light.up, r), plane(-light.up, r),
            std::isfinite(sun_reach_m) ? plane(-light.dir, r + sun_reach_m) : glm::dvec4(0, 0, 0, 1),  // casters above the box
            plane(light.dir, r)};    // nothing below the box's bottom can shadow inside it
}

bool casterReachesPlane(const glm::dvec3& lo, const glm::dvec3& hi, const glm::dvec4& plane, const glm::dvec3& sun_dir,
                        double receivers_above_y) {
    // Along the shadow p - t sun_dir (t >= 0, down to the floor: t <= (p.y - floor) / sun_dir.y)
    // the plane distance grows by t k, k = -dot(n, sun_dir). The farthest point of the swept box
    // is a swept corner: dist(p) + k max(p.y - floor, 0) / sun_dir.y is convex in p.
    const glm::dvec3 n(plane);
    const double k = std::max(-glm::dot(n, sun_dir), 0.0);
    if (k > 0.0 && !std::isfinite(receivers_above_y)) return true;
    for (int i = 0; i < 8; ++i) {
        const glm::dvec3 p((i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z);
        const double reach = k > 0.0 ? k * std::max(p.y - receivers_above_y, 0.0) / std::max(sun_dir.y, 1e-9) : 0.0;
        if (glm::dot(n, p) + plane.w + reach >= 0.0) return true;
    }
    return false;
}

std::array<glm::dvec4, 6> extrudeTowardsSun(const std::array<glm::dvec4, 6>& view_frustum, const glm::dvec3& sun_dir) {
    std::array<glm::dvec4, 6> out = view_frustum;
    for (glm::dvec4& p : out)
        if (glm::dot(glm::dvec3(p), sun_dir) < 0.0) p = glm::dvec4(0, 0, 0, 1);
    return out;
}

}  // namespace vista
