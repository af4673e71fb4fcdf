// lighting.sun's uniforms: renderer/lighting/deferred.cpp fills them, sun.glsl reads them.
#include "../../shaders/pass_block.glsl"
PASS_BLOCK(SunBlock)
    vec3 u_sun_irradiance; float u_sun_unused0;  // RGB irradiance of the sun at normal incidence
    vec3 u_sky_up; float u_sun_unused1;          // RGB sky irradiance on an upward-facing surface
    vec3 u_ground_up; float u_sun_unused2;       // RGB irradiance from below (ground bounce) on a downward-facing surface
    vec4 u_cloud_shadow_map;                     // HAS_CLOUD_SHADOW: xy centre minus camera (x/z m), z 1/extent, w max(sun y, 0.05)
PASS_BLOCK_END
