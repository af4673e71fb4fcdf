// G-buffer encoding (layout in renderer/scene_targets.h) and position reconstruction.

// Octahedral normal encoding (Meyer et al. 2010): the unit sphere folded onto the
// octahedron |x| + |y| + |z| = 1 and the lower half unfolded into the square's corners.
vec2 octWrap(vec2 v) {
    return (1.0 - abs(v.yx)) * vec2(v.x >= 0.0 ? 1.0 : -1.0, v.y >= 0.0 ? 1.0 : -1.0);
}
vec2 encodeNormal(vec3 n) {
    n /= abs(n.x) + abs(n.y) + abs(n.z);
    vec2 e = n.y >= 0.0 ? n.xz : octWrap(n.xz);
    return e * 0.5 + 0.5;
}
vec3 decodeNormal(vec2 e) {
    e = e * 2.0 - 1.0;
    vec3 n = vec3(e.x, 1.0 - abs(e.x) - abs(e.y), e.y);
    float t = max(-n.y, 0.0);
    n.x += n.x >= 0.0 ? -t : t;
    n.z += n.z >= 0.0 ? -t : t;
    return normalize(n);
}

struct Surface {
    vec3 albedo;       // linear base colour
    float roughness;   // perceptual, [0, 1]
    vec3 normal;       // world space, unit
    float f0;          // specular reflectance at normal incidence
    bool lit;
};

// Values for the G-buffer's albedo and normal targets.
void encodeSurface(Surface s, out vec4 albedo, out vec4 normal) {
    albedo = vec4(sqrt(max(s.albedo, vec3(0.0))), s.roughness);
    normal = vec4(encodeNormal(s.normal), clamp(s.f0 / 0.16, 0.0, 1.0), s.lit ? 1.0 : 0.0);
}

Surface decodeSurface(vec4 albedo, vec4 normal) {
    Surface s;
    s.albedo = albedo.rgb * albedo.rgb;
    s.roughness = albedo.a;
    s.normal = decodeNormal(normal.xy);
    s.f0 = normal.z * 0.16;
    s.lit = normal.w > 0.5;
    return s;
}

// Camera-relative world position of a pixel (uv in [0, 1]^2) at reversed-Z depth > 0.
vec3 positionFromDepth(vec2 uv, float depth) {
    vec4 p = u_inv_view_proj * vec4(uv * 2.0 - 1.0, depth, 1.0);
    return p.xyz / p.w;
}
