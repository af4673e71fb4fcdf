// "sky.transmittance": transmittance to the top of the atmosphere over Bruneton's (r, mu)
// parameterisation, integrated with the same perigee split and u^2 spacing as the reference.
#ifdef COMPUTE_SHADER
#include "../../renderer/shaders/bindings.glsl"
#include "atmosphere.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba32f, binding = BINDING_IMAGE_OUTPUT) uniform writeonly image2D u_output;

vec3 opticalDepth(float r, float mu, float len, int steps) {
    float t_p = -r * mu;
    bool split = t_p > 0.0 && t_p < len;
    int pieces = split ? 2 : 1;
    int n = max(steps / pieces, 2);
    vec3 od = vec3(0.0);
    for (int piece = 0; piece < pieces; ++piece) {
        float a = piece == 0 ? 0.0 : t_p, b = (split && piece == 0) ? t_p : len;
        bool dense_at_a = !(split && piece == 0);
        float piece_len = b - a;
        // Composite Simpson in u (n even), t = a + L u^2 or b - L (1 - u)^2.
        int m = n + (n & 1);
        vec3 sum = vec3(0.0);
        for (int k = 0; k <= m; ++k) {
            float u = float(k) / float(m);
            float w = (k == 0 || k == m) ? 1.0 : ((k & 1) == 1 ? 4.0 : 2.0);
            float t = dense_at_a ? a + piece_len * u * u : b - piece_len * (1.0 - u) * (1.0 - u);
            float dt_du = 2.0 * piece_len * (dense_at_a ? u : 1.0 - u);
            float r_t = sqrt(max(r * r + t * (2.0 * r * mu + t), 0.0));
            sum += w * dt_du * medium(r_t).extinction;
        }
        od += sum / (3.0 * float(m));
    }
    return od;
}

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (p.x >= a_sizes.x || p.y >= a_sizes.y) return;
    float r, mu;
    transmittanceRMu((vec2(p) + 0.5) / vec2(a_sizes.xy), r, mu);
    vec3 od = opticalDepth(r, mu, distanceToTop(r, mu), a_sizes2.y);
    imageStore(u_output, p, vec4(exp(-od), 1.0));
}
#endif
