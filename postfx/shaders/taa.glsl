// "postfx.taa": temporal anti-aliasing after Karis ("High Quality Temporal Supersampling",
// SIGGRAPH 2014) and Playdead (INSIDE, GDC 2016), on the linear HDR image. Each pixel's place
// in the previous frame comes from the frame's motion vectors ("temporal.velocity",
// renderer/velocity.h: uv - velocity.xy, built in double on the CPU), the history is fetched there with a
// 5-tap Catmull-Rom filter, clipped towards this frame's 3x3 neighbourhood (mean +- gamma
// standard deviations in YCoCg), and blended with the current pixel. History is rejected
// (the current pixel alone) outside the previous image, where the previous frame saw
// something nearer at that place (a disocclusion), and on a camera cut (u_params.w).
// Outputs: 0 the image for the post chain (the history with an unsharp mask against its own
// bilinear fetch, so the sharpening is stable over frames; alpha passed through from this
// frame), 1 the new history (unsharpened),
// 2 this frame's depth for the next frame's disocclusion test.
#include "../../renderer/shaders/fullscreen.glsl"

#ifdef FRAGMENT_SHADER
#include "../../renderer/shaders/bindings.glsl"
layout(binding = BINDING_TEX_0) uniform sampler2D u_current;
layout(binding = BINDING_TEX_1) uniform sampler2D u_depth;
layout(binding = BINDING_TEX_2) uniform sampler2D u_history;
layout(binding = BINDING_TEX_3) uniform sampler2D u_prev_depth;
layout(binding = BINDING_TEX_4) uniform sampler2D u_velocity;  // rg uv motion, b previous depth, a valid
#include "taa_block.glsl"
layout(location = 0) out vec4 o_color;
layout(location = 1) out vec4 o_history;
layout(location = 2) out float o_depth;

vec3 toYCoCg(vec3 c) {
    return vec3(dot(c, vec3(0.25, 0.5, 0.25)), dot(c, vec3(0.5, 0.0, -0.5)), dot(c, vec3(-0.25, 0.5, -0.25)));
}
vec3 fromYCoCg(vec3 c) {
    return vec3(c.x + c.y - c.z, c.x + c.z, c.x - c.y - c.z);
}

#include "../../renderer/shaders/catmull_rom.glsl"

// Clips c towards the box's centre onto the box (Playdead): keeps the hue of the history.
vec3 clipToBox(vec3 c, vec3 lo, vec3 hi) {
    vec3 centre = 0.5 * (lo + hi), extent = max(0.5 * (hi - lo), vec3(1e-6));
    vec3 v = c - centre;
    vec3 a = abs(v / extent);
    float m = max(a.x, max(a.y, a.z));
    return m > 1.0 ? centre + v / m : c;
}

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    ivec2 last = textureSize(u_current, 0) - 1;
    vec2 size = vec2(textureSize(u_current, 0));
    vec4 current_texel = texelFetch(u_current, p, 0);
    vec3 current = max(current_texel.rgb, vec3(0.0));
    float depth = texelFetch(u_depth, p, 0).r;
    depth = (depth > 0.0 && !isnan(depth)) ? min(depth, 1.0) : 0.0;
    o_depth = depth;
    // The neighbourhood's moments in YCoCg.
    vec3 m1 = vec3(0.0), m2 = vec3(0.0);
    for (int y = -1; y <= 1; ++y)
        for (int x = -1; x <= 1; ++x) {
            vec3 c = toYCoCg(max(texelFetch(u_current, clamp(p + ivec2(x, y), ivec2(0), last), 0).rgb, vec3(0.0)));
            m1 += c;
            m2 += c * c;
        }
    m1 /= 9.0;
    vec3 sigma = sqrt(max(m2 / 9.0 - m1 * m1, vec3(0.0)));
    vec3 lo = m1 - u_params.y * sigma, hi = m1 + u_params.y * sigma;

    // This pixel's point, unjittered, in the previous frame: it moved by the velocity, and the
    // history texel under this pixel's centre moved by as much (the history is not jittered).
    vec4 velocity = texelFetch(u_velocity, p, 0);
    bool valid = u_params.w < 0.5 && velocity.a > 0.5;
    vec2 uv = vec2(-1.0);
    if (valid) {
        uv = gl_FragCoord.xy / size - velocity.xy;
        valid = all(greaterThanEqual(uv, vec2(0.0))) && all(lessThanEqual(uv, vec2(1.0)));
    }
    if (valid && depth > 0.0) {
        // Disoccluded: every previous depth around the point is nearer than the point was.
        float expected = u_jitter.z / max(velocity.z, 1e-30);
        vec2 q = uv * size - 0.5;
        ivec2 q0 = clamp(ivec2(floor(q)), ivec2(0), last), q1 = clamp(q0 + 1, ivec2(0), last);
        float d00 = texelFetch(u_prev_depth, q0, 0).r, d10 = texelFetch(u_prev_depth, ivec2(q1.x, q0.y), 0).r;
        float d01 = texelFetch(u_prev_depth, ivec2(q0.x, q1.y), 0).r, d11 = texelFetch(u_prev_depth, q1, 0).r;
        float farthest_depth = min(min(d00, d10), min(d01, d11));  // reversed-Z: the smallest is the farthest
        float farthest = farthest_depth > 0.0 ? u_jitter.z / farthest_depth : 1e30;
        if (farthest < expected * (1.0 - u_jitter.w)) valid = false;
    }
    vec3 result = current, display = current;
    if (valid) {
        vec3 history = textureCatmullRom(u_history, uv, size).rgb;
        vec3 clipped = fromYCoCg(clipToBox(toYCoCg(history), lo, hi));
        result = mix(clipped, current, u_params.x);
        // Unsharp mask of the history against its bilinear fetch, limited to the neighbourhood.
        vec3 soft = texture(u_history, uv).rgb;
        vec3 sharp = result + u_params.z * (history - soft);
        vec3 r = toYCoCg(result);
        display = fromYCoCg(clamp(toYCoCg(sharp), min(lo, r), max(hi, r)));
        display = max(display, vec3(0.0));
    }
    if (any(isnan(result)) || any(isinf(result))) result = current, display = current;
    // Alpha is this frame's, never resolved: it carries the scene's coverage (0 where nothing
    // was drawn) and debug values such as the terrain error view's screen error, which HDR
    // captures and tests read per frame.
    o_color = vec4(display, current_texel.a);
    o_history = vec4(result, 1.0);
}
#endif
