// "postfx.motion_blur.gather": McGuire et al. 2012's reconstruction. Taps along the neighbourhood's
// longest half vector vn (t in [-1, 1], jittered per pixel by interleaved gradient noise); a tap
// Y counts for pixel X when Y is in front and its own blur reaches X (cone of Y's velocity), when
// Y is behind and X's blur reaches it (cone of X's velocity), and both blurred over each other
// (two cylinders). In front / behind blend over depth_extent of relative view distance. NaN and
// Inf colours count as 0. Where the neighbourhood is still (|vn| < 0.5 px) the pixel is copied.
#include "../../renderer/shaders/fullscreen.glsl"

#ifdef FRAGMENT_SHADER
#include "../../renderer/shaders/bindings.glsl"
layout(binding = BINDING_TEX_0) uniform sampler2D u_image;
layout(binding = BINDING_TEX_1) uniform sampler2D u_velocity;   // rg half vector (px), b view distance
layout(binding = BINDING_TEX_2) uniform sampler2D u_neighbors;  // longest half vector around each tile
#include "motion_blur_block.glsl"
layout(location = 0) out vec4 o_color;

vec3 colourAt(ivec2 p) {
    vec3 c = texelFetch(u_image, p, 0).rgb;
    return (any(isnan(c)) || any(isinf(c))) ? vec3(0.0) : clamp(c, vec3(-65504.0), vec3(65504.0));
}

float cone(float dist, float len) { return clamp(1.0 - dist / len, 0.0, 1.0); }
float cylinder(float dist, float len) { return 1.0 - smoothstep(0.95 * len, 1.05 * len, dist); }
// 1 when a is in front of b (or within the extent), 0 when clearly behind.
float inFront(float a, float b) { return clamp(1.0 - (a - b) / (u_gather.y * min(a, b)), 0.0, 1.0); }

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    ivec2 size = textureSize(u_image, 0);
    vec4 src = texelFetch(u_image, p, 0);
    vec2 vn = texelFetch(u_neighbors, p / int(u_gather.z), 0).rg;
    if (dot(vn, vn) < 0.25) {
        o_color = vec4(colourAt(p), src.a);
        return;
    }
    vec4 vx = texelFetch(u_velocity, p, 0);
    float lx = max(length(vx.xy), 0.5);
    float weight = 1.0 / lx;
    vec3 sum = colourAt(p) * weight;
    int taps = int(u_gather.x);
    float jitter = fract(52.9829189 * fract(dot(vec2(p), vec2(0.06711056, 0.00583715)))) - 0.5;
    for (int i = 0; i < taps; ++i) {
        float t = mix(-1.0, 1.0, (float(i) + jitter + 1.0) / float(taps + 1));
        ivec2 y = clamp(p + ivec2(round(vn * t)), ivec2(0), size - 1);
        if (y == p) continue;
        vec4 vy = texelFetch(u_velocity, y, 0);
        float ly = max(length(vy.xy), 0.5);
        float dist = length(vec2(y - p));
        float f = inFront(vy.b, vx.b), b = inFront(vx.b, vy.b);
        float a = f * cone(dist, ly) + b * cone(dist, lx) + cylinder(dist, ly) * cylinder(dist, lx) * 2.0;
        sum += colourAt(y) * a;
        weight += a;
    }
    o_color = vec4(sum / weight, src.a);
}
#endif
