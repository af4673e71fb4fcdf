// The sun's transmittance through the atmosphere and the clouds (sky/clouds/sun_visibility.h).
#include "sky/clouds/sun_visibility.h"

#include "sky/clouds/cloud_model.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace vista {

namespace {

// Rec. 709 luminance of the renderer's RGB samples (read as linear sRGB, as the passes do).
double luminance(const glm::dvec3& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

double smoothstep(double e0, double e1, double x) {
    const double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

}  // namespace

double cloudExtinction(const CloudLayerSettings& layer, double coverage, const glm::dvec3& p_cells, double h01) {
    if (h01 <= 0.0 || h01 >= 1.0) return 0.0;
    const double cut = 1.0 - coverage + 0.35 * h01 * h01;
    // The GPU skips octaves once the sum can no longer pass the cut; the full sum gives the
    // same density (0 below the cut either way).
    const double n = 0.5 + 2.0 * (cloudFbm(p_cells, layer.octaves, std::uint32_t(layer.seed)) - 0.5);
    return double(layer.density) * std::clamp((n - cut) * 4.0, 0.0, 1.0) * smoothstep(0.0, 0.12, h01);
}

double cloudTransmittanceAlong(const CloudsSettings& clouds, const SkySettings& sky, const glm::dvec3& camera_world_m,
                               const glm::dvec3& dir, double time_s, int steps) {
    if (!cloudsActive(clouds)) return 1.0;
    // As Clouds::prepare and clouds.glsl: the planet's centre below the camera, the ground at y = 0.
    const double ground_r = double(sky.planet_radius_km) * 1e3;
    const double r = ground_r + std::max(camera_world_m.y, 0.0);
    const double mu = dir.y;
    const double max_distance = double(clouds.max_distance_km) * 1e3, fade_start = 0.6 * max_distance;
    const glm::dvec2 camera_xz(camera_world_m.x, camera_world_m.z);
    double tau = 0.0;
    for (const CloudLayerSettings* layer : {&clouds.low, &clouds.high}) {
        if (!cloudLayerActive(*layer)) continue;
        const double r_bottom = ground_r + double(layer->base_m), thickness = double(layer->thickness_m);
        const ShellSegment seg = cloudShellSegment(r, mu, ground_r, r_bottom, r_bottom + thickness);
        const double t1 = std::min(seg.t1, max_distance);
        if (!seg.hit || t1 <= seg.t0) continue;
        const glm::dvec2 origin = cloudNoiseOrigin(*layer, camera_xz, time_s);
        const double cells = 1.0 / double(layer->scale_m), coverage = cloudCoverage(*layer, clouds, time_s);
        const double dt = (t1 - seg.t0) / double(steps);
        for (int k = 0; k < steps; ++k) {
            const double t = seg.t0 + (double(k) + 0.5) * dt;
            const glm::dvec3 p = glm::dvec3(0.0, r, 0.0) + t * dir;
            const double h01 = (glm::length(p) - r_bottom) / thickness;
            const glm::dvec3 cell(origin.x + t * dir.x * cells, h01 * thickness * cells, origin.y + t * dir.z * cells);
            tau += cloudExtinction(*layer, coverage, cell, h01) * (1.0 - smoothstep(fade_start, max_distance, t)) * dt;
        }
    }
    return std::exp(-tau);
}

SunVisibility sunVisibility(const SkyLighting& lighting, const SkySettings& sky, const CloudsSettings& clouds,
                            const glm::dvec3& camera_world_m, double time_s) {
    SunVisibility v;
    const double top = double(sky.sun_illuminance);
    v.atmosphere = top > 0.0 ? std::clamp(luminance(lighting.sun_illuminance) / top, 0.0, 1.0) : 0.0;
    v.clouds = v.atmosphere > 0.0 ? cloudTransmittanceAlong(clouds, sky, camera_world_m, lighting.sun_direction, time_s)
                                  : 1.0;
    return v;
}

}  // namespace vista
