// Tessellated displacement of the near terrain (docs/terrain-detail.md; the TU Wien scene's
// hardware tessellation): terrain.glsl's vertex stage (CDLOD morph) and its fragment stage (or
// the depth-only shadow stage), with a control and an evaluation stage between them. Each grid
// triangle is a patch; an edge's factor comes from its two morphed end points only (its length
// and its midpoint's distance from the camera), so the two patches that share an edge, at the
// same or at neighbouring CDLOD levels and whatever their morph, give it the same factor and the
// same vertices. The new vertices sink by the material relief (the detail array's alpha, as
// parallax occlusion mapping uses it), fading to nothing, with factor 1, by u_tess_fade.y.
// A separate file so that terrain.glsl's other programs have no tessellation stages (the shader
// library compiles a stage wherever its name appears).
#define TERRAIN_TESS 1
#include "terrain.glsl"

#if defined(TESS_CONTROL_SHADER) || defined(TESS_EVALUATION_SHADER)
// u_tess, u_tess_relief and u_tess_fade (terrain_block.glsl): u_tess_fade.xy is where the
// displacement starts to fade, and is gone (factors 1 from there on); z the layer whose relief
// displaces (the pixel's layer blend is out of reach per vertex). All from
// terrain/tess_displacement.h tessRelief(), the CPU mirror the GL test compares with.

// Share of the displacement left at distance d: the outermost tessellated patches meet their
// untessellated neighbours flat and with factor 1.
float tessFade(float d) {
    return 1.0 - smoothstep(u_tess_fade.x, u_tess_fade.y, d);
}
#endif

#ifdef TESS_CONTROL_SHADER
layout(vertices = 3) out;
in vec3 tc_rel[];
in vec2 tc_texel[];
in float tc_sample[];
in vec2 tc_grid[];
flat in vec2 tc_lod[];
in float tc_morph[];
out vec3 te_rel[];
out vec2 te_texel[];
out float te_sample[];
out vec2 te_grid[];
out vec2 te_lod[];
out float te_morph[];

// An edge's factor from its end points alone, symmetric in them (a + b and |a - b| do not
// depend on the order), so both patches on an edge agree to the bit.
float edgeFactor(vec3 a, vec3 b) {
    float d = length((a + b) * 0.5);
    if (tessFade(d) <= 0.0) return 1.0;
    float px = length(a - b) * u_tess.y / max(d, 1e-3);
    return clamp(px / u_tess.x, 1.0, u_tess.w);
}

void main() {
    te_rel[gl_InvocationID] = tc_rel[gl_InvocationID];
    te_texel[gl_InvocationID] = tc_texel[gl_InvocationID];
    te_sample[gl_InvocationID] = tc_sample[gl_InvocationID];
    te_grid[gl_InvocationID] = tc_grid[gl_InvocationID];
    te_lod[gl_InvocationID] = tc_lod[gl_InvocationID];
    te_morph[gl_InvocationID] = tc_morph[gl_InvocationID];
    if (gl_InvocationID == 0) {
        // Outer level i is the edge opposite vertex i.
        float e0 = edgeFactor(tc_rel[1], tc_rel[2]);
        float e1 = edgeFactor(tc_rel[2], tc_rel[0]);
        float e2 = edgeFactor(tc_rel[0], tc_rel[1]);
        gl_TessLevelOuter[0] = e0;
        gl_TessLevelOuter[1] = e1;
        gl_TessLevelOuter[2] = e2;
        gl_TessLevelInner[0] = max(max(e0, e1), e2);
    }
}
#endif

#ifdef TESS_EVALUATION_SHADER
layout(triangles, fractional_odd_spacing, ccw) in;
layout(binding = BINDING_TEX_3) uniform sampler2DArray u_relief;  // the detail array: relief in alpha
in vec3 te_rel[];
in vec2 te_texel[];
in float te_sample[];
in vec2 te_grid[];
in vec2 te_lod[];
in float te_morph[];
out vec3 v_rel;
out vec2 v_texel;
out float v_sample;
out vec2 v_grid;
flat out vec2 v_lod;
out float v_morph;

// Sum in a fixed order of the patch's corners, so that a point on a shared edge (one weight 0)
// comes out the same from both patches: the tessellator gives it weights (u, v) on one side and
// (v, u) on the other, and x * 0 adds an exact 0.
#define TESS_LERP(a) (a[0] * gl_TessCoord.x + a[1] * gl_TessCoord.y + a[2] * gl_TessCoord.z)

// The displacement (m, <= 0) at camera-relative point p: the relief below the surface, faded.
float tessDisplacement(vec3 p) {
    float fade = tessFade(length(p));
    if (fade <= 0.0) return 0.0;
    vec2 uv = (p.xz + u_tess_relief.zw) * u_tess_relief.y;
    float h = texelBilinearRepeat(u_relief, uv, int(u_tess_fade.z + 0.5)).a;  // not the anisotropic sampler (material.glsl)
    return (h - 1.0) * u_tess_relief.x * fade;
}

void main() {
    vec3 rel = TESS_LERP(te_rel);
    rel.y += tessDisplacement(rel);
    v_rel = rel;
    v_texel = TESS_LERP(te_texel);
    v_sample = TESS_LERP(te_sample);
    v_grid = TESS_LERP(te_grid);
    v_lod = te_lod[0];
    v_morph = TESS_LERP(te_morph);
#ifdef SHADOW_PASS
    gl_Position = u_shadow_matrix * vec4(rel, 1.0);
#else
    gl_Position = u_view_proj * vec4(rel, 1.0);
#endif
}
#endif
