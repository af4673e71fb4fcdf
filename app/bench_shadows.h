// `vista bench shadows`: how stable, clean and accurate the sun's cascaded shadows are, and
// what they cost: shimmer while the cascades' camera moves by sub-texel steps (stabilised and
// not), acne on a flat lit plane for sun elevations 2..90 deg, the shadow term's RMSE against
// an 8192-texel 64-tap reference for each resolution and filter beside its GPU time, and the
// frame's cost in reference copies with shadows on and off; for shadowed spot lights, the atlas
// pass's and the shading's cost per number of shadowed lights, and the lit image's error against
// an 8192-texel 64-tap atlas per filter and atlas size.
#pragma once

#include "app/bench_scene.h"
#include "app/gl_context.h"
#include "config/settings.h"

#include <filesystem>

namespace vista {

struct BenchShadowsOptions {
    int width = 320, height = 180;  // frame size
    Backend backend = Backend::OSMesa;
    bool reference = true;          // the 8192-texel reference (slow on llvmpipe): off skips error_vs_reference
    std::filesystem::path json;     // empty: tables only
    bool force = false;  // --force: replace an existing --json file
};

// Returns the exit code.
// scene: the isolated scene (app/bench_scene.h), stated in the output and the JSON.
int runBenchShadows(const BenchScene& scene, const BenchShadowsOptions& options);

}  // namespace vista
