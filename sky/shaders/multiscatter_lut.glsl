// "sky.multiscatter": Hillaire 2020's psi_ms(r, mu_s) (second and higher scattering orders,
// isotropic), integrated over the sphere with the reference's three polar ranges (up, down to
// the sky, down to the ground) of Gauss-Legendre nodes and a midpoint azimuth rule about the
// sun's plane. Stores log(psi_ms) so bilinear filtering follows its exponential fall at dusk.
#ifdef COMPUTE_SHADER
#include "../../renderer/shaders/bindings.glsl"
#define SKY_TEX_TRANSMITTANCE BINDING_TEX_0
#define SKY_TRANSMITTANCE_LUT
#include "atmosphere.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba32f, binding = BINDING_IMAGE_OUTPUT) uniform writeonly image2D u_output;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    int size = a_sizes.z;
    if (p.x >= size || p.y >= size) return;
    float R = bottomR(), Rt = topR();
    float mu_s = -1.0 + 2.0 * float(p.x) / float(size - 1);
    float x = float(p.y) / float(size - 1);
    float r = R + x * x * (Rt - R);
    float sin_s = safeSqrt(1.0 - mu_s * mu_s);
    float mu_h = horizonMu(r);
    int n_polar = a_gl_count.x, n_az = a_gl_count.y;
    float az_weight = 2.0 * PI / float(n_az);
    vec3 l_2nd = vec3(0.0), f_ms = vec3(0.0);
    for (int range = 0; range < 3; ++range) {
        if (range == 1 && r <= R * 1.0000001) continue;
        for (int i = 0; i < n_polar; ++i) {
            float w = a_gl[i].x, gw = a_gl[i].y, mu, d_mu;
            if (range == 0) {
                mu = w * w;
                d_mu = gw * 2.0 * w;
            } else if (range == 1) {
                float r_p = R + (r - R) * w * w * (3.0 - 2.0 * w);
                float dr_p = (r - R) * 6.0 * w * (1.0 - w);
                float root = safeSqrt((r - r_p) * (r + r_p));
                if (!(root > 0.0)) continue;
                mu = -root / r;
                d_mu = gw * dr_p * r_p / (r * root);
            } else {
                mu = mu_h - (1.0 + mu_h) * w * w;
                d_mu = gw * 2.0 * (1.0 + mu_h) * w;
            }
            float sin_v = safeSqrt(1.0 - mu * mu);
            bool ground = range == 2;
            float len = ground ? distanceToGround(r, mu) : distanceToTop(r, mu);
            for (int j = 0; j < n_az; ++j) {
                float phi = (float(j) + 0.5) * PI / float(n_az);
                float nu = clamp(sin_v * sin_s * cos(phi) + mu * mu_s, -1.0, 1.0);
                RaySums s = integrateRay(r, mu, mu_s, nu, len, a_sizes2.z, 1);
                vec3 l_prime = s.radiance;
                if (ground) {
                    float mu_s_g = clamp((r * mu_s + len * nu) / R, -1.0, 1.0);
                    if (mu_s_g > 0.0)
                        l_prime += s.transmittance * (a_albedo.xyz / PI) * mu_s_g * transmittanceToTop(R, mu_s_g);
                }
                float weight = d_mu * az_weight / (4.0 * PI);
                l_2nd += weight * l_prime;
                f_ms += weight * s.second;
            }
        }
    }
    vec3 psi = l_2nd / (vec3(1.0) - min(f_ms, vec3(0.999)));
    imageStore(u_output, p, vec4(log(max(psi, vec3(1e-30))), 1.0));
}
#endif
