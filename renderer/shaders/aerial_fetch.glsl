// Reads the aerial-perspective volume (renderer/aerial_volume.h) at a distance along the view ray
// through a screen position: trilinear, bilinear across the screen inside a slice and linear in
// distance between slice ends, from (no in-scattering, transmittance 1) at the camera. Used by
// "sky.aerial" (every pixel at its depth) and by forward surfaces drawn after it (glass).
// volume: the layout, x range (km), y froxels per side, z slices.

// Bilinear inside slice k's tile, never across tiles: the filtered coordinate stays between the
// tile's first and last texel centres.
void aerialFetchSlice(sampler2D inscatter_atlas, sampler2D transmittance_atlas, vec4 volume, int k, vec2 uv,
                      out vec3 inscatter, out vec3 transmittance) {
    float size = volume.y;
    vec2 f = clamp(uv * (size - 1.0), vec2(0.0), vec2(size - 1.0)) + 0.5;
    vec2 atlas_uv = vec2((float(k) * size + f.x) / (size * volume.z), f.y / size);
    inscatter = texture(inscatter_atlas, atlas_uv).rgb;
    transmittance = texture(transmittance_atlas, atlas_uv).rgb;
}

// In-scattering (HDR) and transmittance from the camera to t_km along the ray through screen uv.
void aerialFetch(sampler2D inscatter_atlas, sampler2D transmittance_atlas, vec4 volume, vec2 uv, float t_km,
                 out vec3 inscatter, out vec3 transmittance) {
    int slices = int(volume.z);
    // Slice k ends at range ((k + 1) / slices)^2; "slice -1" is the camera itself.
    float s = clamp(sqrt(max(t_km / volume.x, 0.0)) * float(slices) - 1.0, -1.0, float(slices - 1));
    int k1 = clamp(int(ceil(s)), 0, slices - 1), k0 = k1 - 1;
    float x0 = float(k0 + 1) / float(slices), x1 = float(k1 + 1) / float(slices);
    float t0 = volume.x * x0 * x0, t1 = volume.x * x1 * x1;
    float w = clamp((t_km - t0) / max(t1 - t0, 1e-9), 0.0, 1.0);
    vec3 s0 = vec3(0.0), tr0 = vec3(1.0), s1, tr1;
    if (k0 >= 0) aerialFetchSlice(inscatter_atlas, transmittance_atlas, volume, k0, uv, s0, tr0);
    aerialFetchSlice(inscatter_atlas, transmittance_atlas, volume, k1, uv, s1, tr1);
    inscatter = clamp(mix(s0, s1, w), vec3(0.0), vec3(60000.0));
    transmittance = clamp(mix(tr0, tr1, w), vec3(0.0), vec3(1.0));
}
