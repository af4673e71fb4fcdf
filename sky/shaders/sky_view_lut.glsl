// "sky.view": in-scattered radiance (single + multiple, per unit solar irradiance) seen from
// the camera's altitude, over Hillaire 2020's (azimuth from the sun, non-linear latitude) map.
#ifdef COMPUTE_SHADER
#include "../../renderer/shaders/bindings.glsl"
#define SKY_TEX_TRANSMITTANCE BINDING_TEX_0
#define SKY_TEX_MULTISCATTER BINDING_TEX_1
#define SKY_TRANSMITTANCE_LUT
#define SKY_MULTISCATTER_LUT
#define SKY_FOG
#include "atmosphere.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba16f, binding = BINDING_IMAGE_OUTPUT) uniform writeonly image2D u_output;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (p.x >= a_sizes.w || p.y >= a_sizes2.x) return;
    float r = a_radii.z;
    float mu, cos_az;
    bool ground;
    skyViewParams(p, mu, cos_az, ground);
    // Local frame: up = +y, the sun in the x-y plane.
    vec3 sun = a_sun.xyz;
    float mu_s = clamp(sun.y, -1.0, 1.0);
    vec3 sun_local = vec3(safeSqrt(1.0 - mu_s * mu_s), mu_s, 0.0);
    float sin_v = safeSqrt(1.0 - mu * mu);
    float sin_az = safeSqrt(1.0 - cos_az * cos_az);
    vec3 dir = vec3(sin_v * cos_az, mu, sin_v * sin_az);
    float nu = clamp(dot(dir, sun_local), -1.0, 1.0);
    float len = ground ? cameraDistanceToGround(mu) : distanceToTop(r, mu);
    RaySums s = integrateRay(r, mu, mu_s, nu, len, a_sizes2.w, 0);
    imageStore(u_output, p, vec4(s.radiance, 1.0));
}
#endif
