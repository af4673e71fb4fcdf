// Terrain normal map from the height texture, once at load: central differences in metres
// (one-sided at the edges), so lighting does not change when the LOD does.
#ifdef COMPUTE_SHADER
#include "../../renderer/shaders/bindings.glsl"
layout(local_size_x = 16, local_size_y = 16) in;
layout(binding = BINDING_TEX_0) uniform sampler2D u_height;  // R32F heightmap samples
layout(binding = BINDING_IMAGE_OUTPUT, rgba8_snorm) uniform writeonly image2D u_normals;
layout(location = 0) uniform vec2 u_texel_m;    // metres between samples in x and z
layout(location = 1) uniform float u_scale_m;   // metres per heightmap unit

float h(ivec2 p, ivec2 size) { return texelFetch(u_height, clamp(p, ivec2(0), size - 1), 0).r * u_scale_m; }

void main() {
    ivec2 size = textureSize(u_height, 0);
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, size))) return;
    ivec2 lo = max(p - 1, ivec2(0)), hi = min(p + 1, size - 1);
    float dhdx = (h(ivec2(hi.x, p.y), size) - h(ivec2(lo.x, p.y), size)) / (float(hi.x - lo.x) * u_texel_m.x);
    float dhdz = (h(ivec2(p.x, hi.y), size) - h(ivec2(p.x, lo.y), size)) / (float(hi.y - lo.y) * u_texel_m.y);
    vec3 n = normalize(vec3(-dhdx, 1.0, -dhdz));
    imageStore(u_normals, p, vec4(n, 0.0));
}
#endif
