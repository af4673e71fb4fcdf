// A moving surface's own motion vector (renderer/velocity.h's layout: uv motion, previous depth,
// valid), from the fragment's previous clip position, for the passes that redraw a surface over
// temporal.velocity with depth EQUAL (water.velocity, grass.velocity). Needs common.glsl.
vec4 surfaceVelocity(vec4 prev_clip, vec2 jitter_ndc) {
    vec2 ndc = gl_FragCoord.xy * u_viewport.zw * 2.0 - 1.0 - jitter_ndc;
    if (!(prev_clip.w > 1e-6)) return vec4(0.0);
    vec2 v = (ndc - prev_clip.xy / prev_clip.w) * 0.5;
    if (any(isnan(v)) || any(isinf(v))) return vec4(0.0);
    return vec4(v, prev_clip.z / prev_clip.w, 1.0);
}
