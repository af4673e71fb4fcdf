// "lights.glow": each prepared light's single scattering along the view rays of the pixels its
// sphere covers (one quad per light, its sphere's screen rectangle), up to the first surface
// (the sky: no end), added to the HDR target. The closed form, its window factor and its table
// are in renderer/lighting/lamp_glow.h (glowTransfer mirrors glowOf() below on the CPU).
#include "../../shaders/bindings.glsl"

struct GlowLight {
    vec4 position_radius;     // camera-relative m, radius m
    vec4 scatter_extinction;  // sigma_s * I * colour * cone share / (2 pi) (pre-exposed), sigma_t (1/m)
    vec4 rect;                // the sphere's screen rectangle, NDC x0 y0 x1 y1
};
layout(std430, binding = BINDING_AUX) readonly buffer GlowLights { GlowLight g_lights[]; };

#ifdef VERTEX_SHADER
out vec2 v_uv;
flat out uint v_light;
void main() {
    vec4 r = g_lights[gl_InstanceID].rect;
    vec2 p = vec2((gl_VertexID & 1) != 0 ? r.z : r.x, (gl_VertexID & 2) != 0 ? r.w : r.y);
    v_uv = p * 0.5 + 0.5;
    v_light = uint(gl_InstanceID);
    gl_Position = vec4(p, 0.0, 1.0);
}
#endif

#ifdef FRAGMENT_SHADER
#include "../../shaders/common.glsl"
#include "../../shaders/gbuffer.glsl"
layout(binding = BINDING_TEX_0) uniform sampler2D u_depth;
layout(binding = BINDING_TEX_1) uniform sampler2D u_glow_table;  // F(u, x): u / (1 + u) across, x / (pi/2) down

in vec2 v_uv;
flat in uint v_light;
layout(location = 0) out vec4 o_color;

const float kQuarterPi = 0.78539816;
const float kFalloffEps = 0.01;  // m^2, renderer/lights.h kFalloffEpsM2
const vec2 kTableSize = vec2(128.0, 256.0);  // kGlowTableU, kGlowTableV

float glowF(float u, float x) {
    vec2 f = vec2(u / (1.0 + u), x / (2.0 * kQuarterPi));
    return texture(u_glow_table, (f * (kTableSize - 1.0) + 0.5) / kTableSize).r;
}

// Antiderivative in theta of the falloff's window (1 - q^4 sec^4 theta)^2, q = h / r, written
// with a = (t - t_c) / r = q tan theta so that no power of tan overflows (lamp_glow.h).
float windowIntegral(float theta, float a, float q) {
    float q2 = q * q, a2 = a * a;
    float q3 = q2 * q, q5 = q3 * q2, q7 = q5 * q2;
    return theta - 2.0 * (q3 * a + q * a * a2 / 3.0) +
           (q7 * a + q5 * a * a2 + 0.6 * q3 * a * a2 * a2 + q * a * a2 * a2 * a2 / 7.0);
}

vec3 glowOf(GlowLight light, vec3 dir, float t_end) {
    vec3 p = light.position_radius.xyz;
    float r = light.position_radius.w;
    float tc = dot(dir, p);
    float h2 = max(dot(p, p) - tc * tc, 0.0);
    float half_chord = sqrt(max(r * r - h2, 0.0));
    float t0 = max(tc - half_chord, 0.0), t1 = min(tc + half_chord, t_end);
    if (h2 >= r * r || t1 <= t0) return vec3(0.0);
    float h = sqrt(h2 + kFalloffEps);
    float sigma = light.scatter_extinction.w;
    float th0 = atan((t0 - tc) / h), th1 = atan((t1 - tc) / h);
    float x0 = kQuarterPi + 0.5 * th0, x1 = kQuarterPi + 0.5 * th1;
    float u = sigma * h;
    // t + d(t) grows along the ray: this bound keeps the table's rounding from being
    // magnified by exp(-sigma t_c) > 1 (a light behind the ray's closest approach).
    float d0 = sqrt((t0 - tc) * (t0 - tc) + h * h);
    float bound = exp(-sigma * (t0 + d0)) * (x1 - x0);
    float integral = max(min(exp(-sigma * tc) * (glowF(u, x1) - glowF(u, x0)), bound), 0.0);
    // The window's mean over the segment (exact without extinction).
    float q = h / r;
    float window = th1 - th0 > 1e-3
        ? (windowIntegral(th1, (t1 - tc) / r, q) - windowIntegral(th0, (t0 - tc) / r, q)) / (th1 - th0)
        : pow(max(1.0 - q * q * q * q, 0.0), 2.0);
    return light.scatter_extinction.rgb * (integral * clamp(window, 0.0, 1.0) / h);
}

void main() {
    float depth = texelFetch(u_depth, ivec2(gl_FragCoord.xy), 0).r;
    vec3 dir = viewRay(v_uv);
    float t_end = depth > 0.0 ? length(positionFromDepth(v_uv, depth)) : 3.0e38;
    o_color = vec4(min(glowOf(g_lights[v_light], dir, t_end), vec3(60000.0)), 0.0);  // in half-float range
}
#endif
