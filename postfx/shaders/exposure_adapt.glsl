// "postfx.exposure.adapt": the histogram's average log2 luminance between two percentiles
// (black pixels left out), clamped to [min_ev, max_ev], then moved towards from the last
// frame's value exponentially in time: frame-rate independent, exp(-dt * rate).
#ifdef COMPUTE_SHADER
#include "postfx_bindings.glsl"
layout(local_size_x = 1) in;
layout(std430, binding = POSTFX_BINDING_HISTOGRAM) readonly buffer Histogram {
    uint bins[EXPOSURE_BINS];
};
layout(std430, binding = POSTFX_BINDING_EXPOSURE) buffer ExposureState {
    float adapted_log2;
    float scale;
    float target_log2;
    float valid;
};
#include "exposure_block.glsl"

void main() {
    float total = 0.0;
    for (int i = 1; i < EXPOSURE_BINS; ++i) total += float(bins[i]);
    float low = total * u_percent.x, high = total * u_percent.y;
    float sum = 0.0, weight = 0.0, below = 0.0;
    const float bin_width = (EXPOSURE_LOG_MAX - EXPOSURE_LOG_MIN) / float(EXPOSURE_BINS - 2);
    for (int i = 1; i < EXPOSURE_BINS; ++i) {
        float n = float(bins[i]);
        float w = clamp(below + n, low, high) - clamp(below, low, high);
        sum += w * (EXPOSURE_LOG_MIN + float(i - 1) * bin_width);
        weight += w;
        below += n;
    }
    bool first = u_reset > 0.5 || valid < 0.5;
    float previous = first ? clamp(0.0, u_ev_range.x, u_ev_range.y) : adapted_log2;
    float target = weight > 0.0 ? clamp(sum / weight - u_units.x, u_ev_range.x, u_ev_range.y) : previous;
    float rate = target > previous ? u_speed.x : u_speed.y;
    float adapted = first ? target : target + (previous - target) * exp(-max(u_dt, 0.0) * rate);
    adapted_log2 = adapted;
    target_log2 = target;
    // Below mesopic levels the eye does not bring a scene to middle grey: night_ev stops darker
    // at scotopic adaptation (0.005 cd/m^2 and below), none from 5 cd/m^2 up (the CIE mesopic
    // range), smooth in log luminance between.
    float log10_cd = (adapted + u_units.y) * 0.30103;
    float night = smoothstep(0.0, 1.0, (0.69897 - log10_cd) / 3.0);  // log10(5) = 0.69897
    scale = 0.18 * u_compensation * exp2(-adapted - u_units.x - u_units.z * night);
    valid = 1.0;
}
#endif
