// Parallax occlusion mapping (Tatarchuk 2006; the TU Delft renderer's linear-then-binary search):
// the view ray is marched through a relief that lies below the drawn surface, height 1 at the
// surface and height 0 depth_m below it. The includer defines, before including this file,
//     float pomHeight(vec3 p)   relief height (0..1) at the surface point p (any space, as long as
//                               the spans below are in the same one)
// so the same march serves the terrain's blended material layers (terrain.glsl) and the test
// probe's single texture (tests/gl/shaders/pom_probe.glsl, checked against a CPU ray march).

// The steepest view or light ray the march follows: cos(87 deg). Steeper rays would cross the
// whole texture in one step; clamping keeps the span finite (at most 19 depths sideways).
const float kPomMinCos = 0.05;

// Where a ray with unit direction dir (away from the surface, either toward the eye or the sun)
// through the surface point reaches depth_m below the surface: the sideways move along the
// surface (p - p_surface), for a surface of unit normal n.
vec3 pomSpan(vec3 dir, vec3 n, float depth_m) {
    float c = max(dot(dir, n), kPomMinCos);
    return (dir - n * dot(dir, n)) * (depth_m / c);
}

// Linear steps for a view ray whose cosine to the normal is cos_view: max_steps at grazing
// angles, a quarter of them (at least 2) looking straight down, where the ray moves little.
int pomSteps(float cos_view, int max_steps) {
    float low = max(float(max_steps) * 0.25, 2.0);
    return int(mix(float(max_steps), low, clamp(cos_view, 0.0, 1.0)) + 0.5);
}

// The first hit of the view ray with the relief, as the fraction t of depth_m it has descended
// (0..1): the point is p0 - t * span, where span = pomSpan(toward the eye, ...) at p0, the point
// the drawn surface shows. A linear search in `steps` equal steps finds the first step below the
// relief, `refine` bisections narrow it, and a last secant step interpolates between the two
// bracketing heights. The ray always hits by t = 1 (height 0 is the relief's floor).
float pomMarch(vec3 p0, vec3 span, int steps, int refine) {
    float dt = 1.0 / float(max(steps, 1));
    float t_above = 0.0, d_above = pomHeight(p0) - 1.0;  // d = relief height - ray height: < 0 above it
    if (d_above >= 0.0) return 0.0;
    float t_below = 1.0, d_below = pomHeight(p0 - span);
    for (int i = 1; i < steps; ++i) {
        float t = float(i) * dt;
        float d = pomHeight(p0 - span * t) - (1.0 - t);
        if (d >= 0.0) {
            t_below = t;
            d_below = d;
            break;
        }
        t_above = t;
        d_above = d;
    }
    for (int i = 0; i < refine; ++i) {
        float t = 0.5 * (t_above + t_below);
        float d = pomHeight(p0 - span * t) - (1.0 - t);
        if (d >= 0.0) {
            t_below = t;
            d_below = d;
        } else {
            t_above = t;
            d_above = d;
        }
    }
    // Secant between the bracket's ends: where the relief and the ray, both taken as straight
    // between them, cross.
    return mix(t_above, t_below, clamp(d_above / min(d_above - d_below, -1e-6), 0.0, 1.0));
}

// Soft self-shadowing: how much light from the sun reaches the relief at the hit (relief height
// h, point p) along the sun ray rising through it (span_sun = pomSpan(toward the sun, ...)): 1
// unshadowed, toward 0 the deeper the relief rises above the ray (Tatarchuk's penumbra: each
// blocker counts less the farther along the ray it stands).
float pomShadow(vec3 p, float h, vec3 span_sun, int steps) {
    float rise = 1.0 - h;  // the ray leaves the relief by height 1
    if (rise <= 0.0) return 1.0;
    float occlusion = 0.0;
    for (int i = 1; i <= steps; ++i) {
        float f = float(i) / float(steps + 1);
        float ray = h + rise * f;
        // The sun ray rises rise * f above the hit after moving span_sun * rise * f sideways.
        float blocker = pomHeight(p + span_sun * (rise * f)) - ray;
        occlusion = max(occlusion, blocker * (1.0 - f));
    }
    return 1.0 - clamp(occlusion * 4.0, 0.0, 1.0);
}
