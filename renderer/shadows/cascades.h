// Cascaded shadow maps for the sun, the maths without GL: PSSM split distances, a light-space
// basis, and cascades fitted to the bounding sphere of their view slice and snapped to whole
// texels relative to the world origin (MJP / Valient), so moving or turning the camera moves
// every shadow-map texel by whole texels and shadow edges do not shimmer.
//
// Light space: u = dot(p, right), v = dot(p, up), w = dot(p, dir) with dir towards the sun.
// A cascade is a box |u - u_c| <= r, |v - v_c| <= r, w in [w_c - r, w_c + r]; its matrix maps
// camera-relative world positions to clip x, y in [-1, 1] and depth (w_c + r - w) / (2r) in
// [0, 1] (0 nearest the sun). Casters between the box and the sun fall below depth 0 and are
// drawn with depth clamping ("pancaking"), so the box need not reach them.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <array>
#include <limits>

namespace vista {

constexpr int kMaxSunCascades = 5;  // 4 PSSM cascades + the far cascade (shadows.glsl has the same)

// PSSM split distances (view depth, m) for `count` slices between near and far:
// d_i = lambda * n (f/n)^(i/N) + (1 - lambda) (n + (f - n) i/N), i = 0..N (d_0 = n, d_N = f).
std::array<double, kMaxSunCascades + 1> pssmSplits(double near_m, double far_m, int count, double lambda);

struct LightBasis {
    glm::dvec3 right{1, 0, 0}, up{0, 0, 1}, dir{0, 1, 0};  // dir: unit vector towards the sun
};
// An orthonormal basis for a sun direction (any unit vector, straight up and down included).
// It depends on the direction only, never on the camera.
LightBasis lightBasis(const glm::dvec3& sun_dir);

// Smallest sphere around the part of a symmetric view frustum between view depths near and
// far: centre at `center_depth` along the view axis, radius `radius` (m).
struct SliceSphere {
    double center_depth = 0.0, radius = 0.0;
};
SliceSphere sliceSphere(double near_m, double far_m, double tan_half_fov_y, double aspect);

struct CascadeView {
    glm::dvec3 position{0.0};      // camera, world (m)
    glm::dvec3 forward{0, 0, -1};  // unit view direction
    glm::dvec3 up{0, 1, 0};        // unit camera up (unstabilised fits use the slice's corners)
    double tan_half_fov_y = 0.577;
    double aspect = 16.0 / 9.0;
};

struct ShadowCascade {
    double near_m = 0.0, far_m = 0.0;  // the view-depth slice it shadows
    glm::dvec3 center_world{0.0};      // box centre (world, m): u_c right + v_c up + w_c dir
    double radius_m = 0.0;             // half extent of the box in u, v and w
    double texel_m = 0.0;              // world size of one shadow-map texel
    glm::dmat4 matrix{1.0};            // camera-relative world -> (clip x, clip y, depth, 1)
};

// Fits the cascade for slice [near_m, far_m] of view at `resolution` texels per side.
// stabilize: sphere fit snapped to whole texels relative to the world origin (the default);
// off: the light-space bounding box of the slice's corners, unsnapped (what shimmers).
ShadowCascade fitCascade(const LightBasis& light, const CascadeView& view, double near_m, double far_m,
                         int resolution, bool stabilize);

// The same cascade for a camera at `camera` (its box stays in world space): frozen cascades
// follow the camera-relative origin of later frames.
glm::dmat4 cascadeMatrix(const LightBasis& light, const ShadowCascade& c, const glm::dvec3& camera);

// The planes (camera-relative, inward: dot(abc, p) + d >= 0) of the cascade's box with its
// sun-facing side moved `sun_reach_m` towards the sun, so they keep every caster between the box
// and the sun up to there (terrain/cdlod.h's Frustum layout: left, right, bottom, top, near =
// sun side, far). A ray towards the sun at elevation e climbs a terrain's height span H within
// H / sin(e) of the box: beyond that nothing can shadow it (infinity: keep everything).
std::array<glm::dvec4, 6> casterPlanes(const LightBasis& light, const ShadowCascade& c, const glm::dvec3& camera,
                                       double sun_reach_m = std::numeric_limits<double>::infinity());

// Whether a caster's box (camera-relative lo..hi) can shadow a receiver on the inner side of
// `plane` (camera-relative, unit normal: dot(n, p) + d >= 0): a shadow runs from the caster away
// from the sun (sun_dir, unit, y > 0) down to the lowest receiver (camera-relative height
// receivers_above_y; -infinity: no floor), so the box swept along it must reach that side. With
// the sun on the plane's inner side the shadow points out of it and the box alone decides.
bool casterReachesPlane(const glm::dvec3& lo, const glm::dvec3& hi, const glm::dvec4& plane, const glm::dvec3& sun_dir,
                        double receivers_above_y);
// The same for the receivers at view depth min_depth_m or more along the view's unit `forward`.
inline bool casterReachesDepth(const glm::dvec3& lo, const glm::dvec3& hi, const glm::dvec3& forward,
                               const glm::dvec3& sun_dir, double receivers_above_y, double min_depth_m) {
    return casterReachesPlane(lo, hi, glm::dvec4(forward, -min_depth_m), sun_dir, receivers_above_y);
}

// A view frustum widened for shadow casters: its planes whose half-space a step towards the sun
// leaves are dropped, so it holds everything that can cast a shadow into the view. Selecting the
// terrain with it and culling that selection per cascade (and by the view frustum for the main
// draw) gives casters and receivers one LOD.
std::array<glm::dvec4, 6> extrudeTowardsSun(const std::array<glm::dvec4, 6>& view_frustum, const glm::dvec3& sun_dir);

}  // namespace vista
