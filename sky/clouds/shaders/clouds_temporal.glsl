// "clouds.temporal": the clouds' march accumulated over frames (Schneider 2015, Hillaire 2016).
// Each texel's cloud point (its view ray at this frame's mean cloud distance, or far along the
// ray where this frame found none) is reprojected into the previous frame along the clouds'
// own depth, not the scene's (u_prev_clip: the previous frame's unjittered view-projection of
// points relative to this camera, from the CPU in double). The history found there is clamped
// to this frame's 3x3 neighbourhood box (premultiplied colour and coverage) and blended in
// with weight 1 - max(1 / frames, blend): a still camera averages up to 1 / blend frames of
// blue-noise offsets. History is rejected outside the previous image, where its distance
// disagrees with the reprojected one by more than a quarter (another cloud), on a camera cut
// and after a reset (u_params.y). In motion a history, reprojected along an estimated distance,
// lags by a share of its point's parallax (its motion on screen against the far sky) every frame:
// its sample count falls by e^(u_motion.x * parallax px) a frame, so that a sustained flight
// refreshes it instead of smearing it into radial streaks.
// Variant SUBSET, the subset march (u_shift.w = stride > 1, clouds_subset.glsl): the march is
// 1/stride of this target's size and holds one pixel per stride x stride block. That pixel blends
// its new sample into its history as above; every other pixel keeps its history (fetched
// Catmull-Rom, as it is resampled every frame), reprojected along its own distance of the last
// frame (its nearest marched pixel's where it has none), and takes the march upsampled
// (bilinearly between the marched pixels) where the reprojection fails or it has never been
// marched. No neighbourhood clamp: the marched pixels lie stride pixels apart, too far for a box
// of them to bound a pixel's history. Another cloud is told by parallax, not by the distance
// alone (see below).
#include "../../../renderer/shaders/fullscreen.glsl"

#ifdef FRAGMENT_SHADER
#include "../../../renderer/shaders/common.glsl"
layout(binding = BINDING_TEX_0) uniform sampler2D u_clouds;
layout(binding = BINDING_TEX_1) uniform sampler2D u_distance;
layout(binding = BINDING_TEX_2) uniform sampler2D u_history;
layout(binding = BINDING_TEX_3) uniform sampler2D u_history_distance;  // r distance (km), g frames accumulated
#include "clouds_temporal_block.glsl"
in vec2 v_uv;
layout(location = 0) out vec4 o_color;
layout(location = 1) out vec4 o_distance;

// Beyond the layers: where no cloud is found the point is reprojected as far away.
#define CLOUD_FAR_M 1.0e6

#ifdef SUBSET
#include "clouds_subset.glsl"
#include "../../../renderer/shaders/catmull_rom.glsl"
// A marched texel of the subset march, clamped to those that stand for a pixel of the target.
vec4 subsetTexel(sampler2D march, ivec2 q, ivec2 last) { return texelFetch(march, clamp(q, ivec2(0), last), 0); }
#endif

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    ivec2 last = textureSize(u_clouds, 0) - 1;
    vec4 current;
    float t;
#ifdef SUBSET
    // The march holds one pixel of each stride x stride block (u_shift.w = stride).
    int stride = int(u_shift.w);
    vec2 size = vec2(textureSize(u_history, 0));
    ivec2 offset = cloudSubsetOffset(stride, uint(u_time.z));
    last = min(last, (ivec2(size) - 1 - offset) / stride);
    vec2 f = vec2(p - offset) / float(stride);
    ivec2 nearest = clamp(ivec2(floor(f + 0.5)), ivec2(0), last);
    bool fresh = all(equal(p, nearest * stride + offset));  // marched this frame
    t = texelFetch(u_distance, nearest, 0).r;
    vec4 lo = vec4(-1e30), hi = vec4(1e30);
    if (fresh) {
        current = texelFetch(u_clouds, nearest, 0);
    } else {
        // Not marched: reprojected along its own distance of the last frame (at the same place
        // on screen), which is exact for a still camera, not its marched neighbour's, which may
        // be another cloud's.
        vec2 own = texelFetch(u_history_distance, p, 0).rg;
        if (own.y > 0.0) t = own.x * 1000.0;
        ivec2 q = ivec2(floor(f));
        vec2 w = f - vec2(q);
        current = mix(mix(subsetTexel(u_clouds, q, last), subsetTexel(u_clouds, q + ivec2(1, 0), last), w.x),
                      mix(subsetTexel(u_clouds, q + ivec2(0, 1), last), subsetTexel(u_clouds, q + 1, last), w.x), w.y);
    }
#else
    const bool fresh = true;
    vec2 size = vec2(textureSize(u_clouds, 0));
    current = texelFetch(u_clouds, p, 0);
    t = texelFetch(u_distance, p, 0).r;
    vec4 lo = current, hi = current;
    for (int y = -1; y <= 1; ++y)
        for (int x = -1; x <= 1; ++x) {
            vec4 c = texelFetch(u_clouds, clamp(p + ivec2(x, y), ivec2(0), last), 0);
            lo = min(lo, c);
            hi = max(hi, c);
        }
#endif
    vec2 uv = (vec2(p) + 0.5) / size;
    vec3 point = viewRay(uv) * (t > 0.0 ? t : CLOUD_FAR_M);
    vec4 prev = u_prev_clip * vec4(point, 1.0);
    bool valid = u_params.y < 0.5 && prev.w > 1e-6;
    // The point moved from its unjittered place (this texel's centre minus the jitter) to
    // prev.xy / prev.w; the history, accumulated at texel centres, moved by as much.
    vec2 prev_uv = valid ? (prev.xy / prev.w + u_params.zw) * 0.5 + 0.5 : vec2(-1.0);
    valid = valid && all(greaterThanEqual(prev_uv, vec2(0.0))) && all(lessThanEqual(prev_uv, vec2(1.0)));
    vec4 result = current;
    float frames = fresh ? 1.0 : 0.0, t_out = t;
    if (valid) {
        vec2 hd = texture(u_history_distance, prev_uv).rg;
        hd.x *= 1000.0;
#ifdef SUBSET
        // A pixel's history is resampled every frame and refreshed once a cycle: fetched sharply.
        vec4 history = textureCatmullRom(u_history, prev_uv, size);
        // Another cloud where the history's distance, put on this ray, would have come from more
        // than a pixel away: parallax, which a still or only turning camera never has, so the
        // noisy distances of one cloud do not reset a history that waits a cycle for each sample.
        bool other_cloud = false;
        if (t > 0.0 && hd.x > 0.0) {
            vec4 alt = u_prev_clip * vec4(viewRay(uv) * hd.x, 1.0);
            vec2 alt_uv = (alt.xy / max(alt.w, 1e-6) + u_params.zw) * 0.5 + 0.5;
            other_cloud = alt.w <= 1e-6 || any(greaterThan(abs(alt_uv - prev_uv) * size, vec2(1.0)));
        }
#else
        vec4 history = texture(u_history, prev_uv);
        float expected = length(point + u_shift.xyz);
        bool other_cloud = t > 0.0 && hd.x > 0.0 && abs(hd.x - expected) > 0.25 * expected;
#endif
        // Parallax: how far this cloud point moved on screen against a point at infinity. The
        // count stays above 0, which marks a pixel marched at least once.
        if (t > 0.0) {
            vec4 far_clip = u_prev_clip * vec4(viewRay(uv) * CLOUD_FAR_M, 1.0);
            vec2 far_uv = (far_clip.xy / max(far_clip.w, 1e-6) + u_params.zw) * 0.5 + 0.5;
            float parallax_px = length((prev_uv - far_uv) * size);
            hd.y = hd.y > 0.0 ? max(hd.y * exp(-u_motion.x * parallax_px), 0.01) : 0.0;
        }
        if (!other_cloud && fresh) {
            frames = min(hd.y + 1.0, 1.0 / u_params.x);
            result = mix(clamp(history, lo, hi), current, max(1.0 / frames, u_params.x));
            if (t <= 0.0) t_out = hd.x;
        } else if (!other_cloud && hd.y > 0.0) {  // not marched this frame: the history as it is
            frames = hd.y;
            result = history;
            t_out = hd.x;
        }
    }
    if (any(isnan(result)) || any(isinf(result))) result = current;
    o_color = result;
    o_distance = vec4(t_out * 1e-3, frames, 0.0, 0.0);
}
#endif
